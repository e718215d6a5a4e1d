// Steps 2 and 3 and the step's end: the pressure correction (pressure_correction.hpp), the
// solids volume fraction correction (volume_fraction_correction.hpp) with its compression limit
// (compression_limit.hpp), and the conservative solids update and boundary fluxes
// (solids_conservation.hpp). Each on hand-made inputs (predicted velocities, responses d and e),
// on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/simple/closures.hpp"
#include "solver/simple/compression_limit.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/pressure_correction.hpp"
#include "solver/simple/solids_conservation.hpp"
#include "solver/simple/volume_fraction_correction.hpp"
#include "tests/support/petsc_environment.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::CellFace;
using solver::petsc_check;
using solver::gas;
using solver::solids;

const std::string& tight = tight_linear_solves;

// A Case with the inputs the corrections take.
struct Corrections {
  explicit Corrections(const std::string& text, const std::vector<std::string>& overrides = {})
      : c(text, overrides),
        closures(c.deck, c.disc),
        fields(static_cast<std::size_t>(c.local_count())),
        carried(static_cast<std::size_t>(c.local_count())),
        response(static_cast<std::size_t>(c.local_count())) {}

  bool unknown(int l, int d) const {
    return c.disc.faces(gas).kind[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] == solver::FaceClass::unknown;
  }
  // A divergent predicted field: smooth random velocities on the unknown faces of both phases,
  // the given ones elsewhere (walls at rest); d_g, d_s (and e) positive and distinct there.
  void predicted_field(double speed) {
    for (int d = 0; d < 3; ++d)
      for (int l = 0; l < c.local_count(); ++l) {
        const auto i = static_cast<std::size_t>(l);
        const auto ud = static_cast<std::size_t>(d);
        const auto x = c.face_position(l, d);
        const bool free = unknown(l, d);
        c.state.gas_velocity[ud][i] = free ? speed * wiggle(x, d) : c.disc.faces(gas).fixed_value[ud][i];
        c.state.solids_velocity[ud][i] = free ? 0.5 * speed * wiggle(x, 2.0 + d) : c.disc.faces(solids).fixed_value[ud][i];
        response.pressure[gas][ud][i] = free ? 1e-3 * (1.5 + wiggle(x, 4.0)) : 0.0;
        response.pressure[solids][ud][i] = free ? 2e-4 * (1.5 + wiggle(x, 5.0)) : 0.0;
        response.fraction[ud][i] = free ? 1e-3 * (1.5 + wiggle(x, 6.0)) : 0.0;
      }
  }
  // Σ_faces A (ε_g u_g + ε_s u_s)_out of cell l, with the carried fractions.
  double mixture_imbalance(int l) const {
    double sum = 0.0;
    solver::for_each_cell_face(c.disc, l, [&](const CellFace& f) {
      const auto ud = static_cast<std::size_t>(f.direction);
      const auto o = static_cast<std::size_t>(f.owner);
      sum += f.sign * f.area * (carried(gas, f.direction)[o] * c.state.gas_velocity[ud][o] +
                                carried(solids, f.direction)[o] * c.state.solids_velocity[ud][o]);
    });
    return sum;
  }
  double largest_mixture_imbalance() const {
    double largest = 0.0;
    for (int l = 0; l < c.owned_fluid(); ++l) largest = std::max(largest, std::abs(mixture_imbalance(l)));
    return c.max(largest);
  }

  Case c;
  solver::Closures closures;
  solver::ClosureFields fields;
  solver::CarriedFractions carried;
  solver::CorrectionResponse response;
  solver::IterationSums sums;
  solver::WorstCells worst;
  solver::StepResult record;
};

void set_fractions(Case& c, double mean, double spread) {
  for (int l = 0; l < c.local_count(); ++l)
    c.state.solids_fraction[static_cast<std::size_t>(l)] = c.fluid(l) ? mean + spread * wiggle(c.centre(l), 7.0) : 0.0;
  Case::complete_gas_fraction(c.state);
  for (auto& p : c.state.gas_pressure) p = 101325.0;
}

// 4 × 3 × 5 closed box (walls all round), stretched in x and z, both phases.
std::string closed_box(const std::string& more = "") { return unit_deck(4, 3, 5, "", -9.81, two_fluid() + tight + more); }
const std::vector<std::string> stretched = {"grid.x.ratio=0.5", "grid.z.ratio=2.0"};

// ---------------------------------------------------------------------------------------------
// Pressure correction

TEST(PressureCorrection, CorrectedFluxesSatisfyMixtureContinuity) {
  for (const bool with_outlet : {false, true}) {
    Corrections k(closed_box(with_outlet ? "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n" : ""),
                  stretched);
    set_fractions(k.c, 0.3, 0.15);
    k.predicted_field(0.1);
    solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
    const double before = k.largest_mixture_imbalance();
    const auto pressure_before = k.c.state.gas_pressure;
    solver::PressureCorrection correction(k.c.deck, k.c.disc, k.c.settings);
    correction.start_step();
    ASSERT_TRUE(correction.correct(k.response, k.carried, k.c.state, k.sums, k.worst, k.record)) << k.record.failure;
    EXPECT_GT(before, 1e-6);  // the predicted field was divergent
    // CG to a relative 1e-12 of the initial residual: the cells' imbalances fall by at least
    // 1e-10 (the 2-norm over ~60 cells bounds each one).
    EXPECT_LT(k.largest_mixture_imbalance(), 1e-10 * before) << (with_outlet ? "with outlet" : "closed");
    // The residual's sums: the imbalance before the correction, against the throughput.
    auto total = k.sums;
    total.reduce(k.c.layout().comm());
    EXPECT_GE(total.continuity[0][0], before);
    EXPECT_GT(total.continuity[0][1], 0.0);
    EXPECT_GT(k.record.linear_iterations[solver::pressure_system], 0.0);
    if (with_outlet) {
      // p' = 0 in the outlet's cells: their pressure is the given one.
      for (int l = 0; l < k.c.local_count(); ++l)
        if (k.c.disc.faces(gas).pressure_boundary[static_cast<std::size_t>(l)]) {
          EXPECT_EQ(k.c.state.gas_pressure[static_cast<std::size_t>(l)], pressure_before[static_cast<std::size_t>(l)]);
        }
    }
  }
}

TEST(PressureCorrection, VelocitiesFollowTheUnrelaxedCorrectionAndPressureItsRelaxedPart) {
  // u_m += d_m (p'_c − p'_n), P += α_p p': run with α_p = 1 and 0.4 on the same inputs.
  std::array<std::unique_ptr<Corrections>, 2> runs;
  const double alpha[2] = {1.0, 0.4};
  for (int r = 0; r < 2; ++r) {
    runs[r] = std::make_unique<Corrections>(closed_box("relax_pressure = " + std::to_string(alpha[r]) + "\n"), stretched);
    auto& k = *runs[r];
    set_fractions(k.c, 0.3, 0.15);
    k.predicted_field(0.1);
    k.c.old = k.c.state;  // the predicted field, kept
    solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
    solver::PressureCorrection correction(k.c.deck, k.c.disc, k.c.settings);
    correction.start_step();
    ASSERT_TRUE(correction.correct(k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  }
  const auto& full = *runs[0];
  const auto& relaxed = *runs[1];
  const auto& layout = full.c.layout();
  double largest_dp = 0.0;
  for (int l = 0; l < full.c.owned_fluid(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const double dp_full = full.c.state.gas_pressure[i] - full.c.old.gas_pressure[i];
    const double dp_relaxed = relaxed.c.state.gas_pressure[i] - relaxed.c.old.gas_pressure[i];
    largest_dp = std::max(largest_dp, std::abs(dp_full));
    // The same system and solve: p' agrees to the solve's round-off; P moves by α_p p'.
    EXPECT_NEAR(dp_relaxed, 0.4 * dp_full, 1e-9 * std::abs(dp_full) + 1e-9);
  }
  EXPECT_GT(full.c.max(largest_dp), 1.0);  // a real correction [Pa]
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    for (const int l : full.c.disc.velocity_numbering(d).owned_locals) {
      const auto i = static_cast<std::size_t>(l);
      const auto n = static_cast<std::size_t>(layout.neighbour(l, 2 * d + 1));
      const double p_c = full.c.state.gas_pressure[i] - full.c.old.gas_pressure[i];
      const double p_n = full.c.state.gas_pressure[n] - full.c.old.gas_pressure[n];
      for (const solver::Phase phase : {gas, solids}) {
        const auto& u = phase == gas ? full.c.state.gas_velocity : full.c.state.solids_velocity;
        const auto& u0 = phase == gas ? full.c.old.gas_velocity : full.c.old.solids_velocity;
        const double expected = u0[ud][i] + full.response.pressure[phase][ud][i] * (p_c - p_n);
        // p' ~ 10 Pa times d ~ 1e-3: velocities of 0.1 m/s to round-off.
        EXPECT_NEAR(u[ud][i], expected, 1e-13);
        // The relaxed run corrects the velocities by the same, unrelaxed p'.
        const auto& v = phase == gas ? relaxed.c.state.gas_velocity : relaxed.c.state.solids_velocity;
        EXPECT_NEAR(v[ud][i], u[ud][i], 1e-12);
      }
    }
  }
}

TEST(PressureCorrection, DivergenceFreeFieldIsLeftAloneWithZeroResidual) {
  // A uniform flow through a periodic box, ε_s varying: the gas and solids fluxes of each cell
  // cancel face by face only if ε is uniform, so keep ε uniform and the velocities uniform.
  Corrections k(unit_deck(4, 3, 3, "\"x\", \"y\", \"z\"", 0.0, two_fluid() + tight));
  set_fractions(k.c, 0.3, 0.0);
  k.predicted_field(0.1);
  for (int d = 0; d < 3; ++d) {
    std::fill(k.c.state.gas_velocity[static_cast<std::size_t>(d)].begin(), k.c.state.gas_velocity[static_cast<std::size_t>(d)].end(), 0.2 - 0.1 * d);
    std::fill(k.c.state.solids_velocity[static_cast<std::size_t>(d)].begin(), k.c.state.solids_velocity[static_cast<std::size_t>(d)].end(), -0.05 * d);
  }
  const run::FlowState before = k.c.state;
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  solver::PressureCorrection correction(k.c.deck, k.c.disc, k.c.settings);
  correction.start_step();
  ASSERT_TRUE(correction.correct(k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  auto total = k.sums;
  total.reduce(k.c.layout().comm());
  // Uniform fluxes cancel face by face: round-off of 1e-5 m³/s fluxes.
  EXPECT_LT(total.continuity[0][0], 1e-18);
  EXPECT_GT(total.continuity[0][1], 1e-5);
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    EXPECT_NEAR(k.c.state.gas_pressure[i], before.gas_pressure[i], 1e-9);
    for (std::size_t d = 0; d < 3; ++d) {
      EXPECT_NEAR(k.c.state.gas_velocity[d][i], before.gas_velocity[d][i], 1e-15);
      EXPECT_NEAR(k.c.state.solids_velocity[d][i], before.solids_velocity[d][i], 1e-15);
    }
  }
}

TEST(PressureCorrection, AFailedLinearSolveFailsTheCorrection) {
  // One CG iteration cannot reduce the residual by 1e-12 on this system.
  petsc_check(PetscOptionsSetValue(nullptr, "-pressure_ksp_max_it", "1"), "PetscOptionsSetValue");
  Corrections k(closed_box(), stretched);
  set_fractions(k.c, 0.3, 0.15);
  k.predicted_field(0.1);
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  solver::PressureCorrection correction(k.c.deck, k.c.disc, k.c.settings);
  correction.start_step();  // the step's KSP reads the options
  petsc_check(PetscOptionsClearValue(nullptr, "-pressure_ksp_max_it"), "PetscOptionsClearValue");
  EXPECT_FALSE(correction.correct(k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  EXPECT_NE(k.record.failure.find("pressure"), std::string::npos) << k.record.failure;
  EXPECT_NE(k.record.failure.find("DIVERGED_ITS"), std::string::npos) << k.record.failure;
  EXPECT_EQ(k.record.linear_iterations[solver::pressure_system], 1.0);
}

// ---------------------------------------------------------------------------------------------
// Volume fraction correction

// A closed box with solids everywhere (0.3 ± 0.1) at the step's start, an iterate that has
// moved away from it (ε_s* = ε_s^old + 0.02 ± 0.02, a net gain the correction must undo), and
// divergent solids velocities.
void perturbed_iterate(Corrections& k, double dt) {
  set_fractions(k.c, 0.3, 0.1);
  k.c.old = k.c.state;
  for (int l = 0; l < k.c.local_count(); ++l)
    if (k.c.fluid(l)) k.c.state.solids_fraction[static_cast<std::size_t>(l)] += 0.02 + 0.02 * wiggle(k.c.centre(l), 8.0);
  Case::complete_gas_fraction(k.c.state);
  k.predicted_field(0.05);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.old, dt, k.fields);
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
}

TEST(VolumeFractionCorrection, ConservesSolidsAndCorrectsVelocitiesByE) {
  const double dt = 1e-3;
  Corrections k(closed_box(), stretched);
  perturbed_iterate(k, dt);
  const run::FlowState predicted = k.c.state;
  const double before = k.c.solids_volume(k.c.old);
  EXPECT_GT(std::abs(k.c.solids_volume(k.c.state) - before), 1e-3 * before);  // the iterate gained solids
  solver::VolumeFractionCorrection correction(k.c.disc, k.c.settings, k.closures);
  ASSERT_TRUE(correction.correct(k.c.old, dt, k.fields, k.response, k.carried, k.c.state, k.sums, k.worst, k.record))
      << k.record.failure;
  // Closed box: the linearized fluxes cancel between cells, so Σ ε_s V returns to the step's
  // start up to the linear solve's tolerance (relative 1e-8 of a residual ~1e-3 of the inventory).
  EXPECT_NEAR(k.c.solids_volume(k.c.state), before, 1e-9 * before);
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    EXPECT_GE(k.c.state.solids_fraction[i], 0.0);
    EXPECT_EQ(k.c.state.gas_fraction[i], 1.0 - k.c.state.solids_fraction[i]);
  }
  // u_s += e (K_c ε'_c − K_n ε'_n) on unknown faces, each cell's own K = dP_s/dε_s (≥ 0; the
  // fractions differ from cell to cell, so a face mean of K fails this), the gas untouched.
  const auto pressure_change = [&](int l) {
    const auto i = static_cast<std::size_t>(l);
    if (k.c.layout().kind(l) != grid::CellKind::fluid) return 0.0;
    return std::max(k.fields.pressure_derivative[i], 0.0) *
           (k.c.state.solids_fraction[i] - predicted.solids_fraction[i]);
  };
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    for (const int l : k.c.disc.velocity_numbering(d).owned_locals) {
      const auto i = static_cast<std::size_t>(l);
      const int n = k.c.layout().neighbour(l, 2 * d + 1);
      const double jump = pressure_change(l) - pressure_change(n);
      EXPECT_NEAR(k.c.state.solids_velocity[ud][i], predicted.solids_velocity[ud][i] + k.response.fraction[ud][i] * jump, 1e-15);
      EXPECT_EQ(k.c.state.gas_velocity[ud][i], predicted.gas_velocity[ud][i]);
    }
  }
  EXPECT_GT(k.record.linear_iterations[solver::fraction_system], 0.0);
}

// R_P = (ε_P − ε_P^old) V/dt + Σ_faces A ε_up u_out of owned fluid cell l, with the fractions
// carried as they are now.
double solids_residual(const Corrections& k, int l, double dt) {
  const auto i = static_cast<std::size_t>(l);
  double r = (k.c.state.solids_fraction[i] - k.c.old.solids_fraction[i]) * k.c.disc.volume(l) / dt;
  solver::for_each_cell_face(k.c.disc, l, [&](const CellFace& f) {
    const auto o = static_cast<std::size_t>(f.owner);
    r += f.sign * f.area * k.carried(solids, f.direction)[o] * k.c.state.solids_velocity[static_cast<std::size_t>(f.direction)][o];
  });
  return r;
}

// The largest |R_P| over every rank's owned fluid cells.
double largest_solids_residual(Corrections& k, double dt) {
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  double largest = 0.0;
  for (int l = 0; l < k.c.owned_fluid(); ++l) largest = std::max(largest, std::abs(solids_residual(k, l, dt)));
  return k.c.max(largest);
}

TEST(VolumeFractionCorrection, WithoutSolidsPressureOneCorrectionSolvesTheLinearContinuity) {
  // With e = 0 the velocities stay as predicted and the upwind choice with them, so solids
  // continuity is linear in ε_s: one correction (a Newton step) leaves no residual beyond the
  // linear solve's (relative 1e-8).
  const double dt = 1e-3;
  Corrections k(closed_box(), stretched);
  perturbed_iterate(k, dt);
  for (auto& e : k.response.fraction) std::fill(e.begin(), e.end(), 0.0);
  const double before = largest_solids_residual(k, dt);
  solver::VolumeFractionCorrection correction(k.c.disc, k.c.settings, k.closures);
  ASSERT_TRUE(correction.correct(k.c.old, dt, k.fields, k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  EXPECT_GT(before, 1e-6);
  EXPECT_LT(largest_solids_residual(k, dt), 1e-7 * before);
}

TEST(VolumeFractionCorrection, UnderTheForceNormTheResidualIsTheForceOfTheFractionError) {
  // Solids about the plastic closure's ε_s* = 0.6 (K = dP_s/dε_s 0 below it, up to ~10¹¹ Pa
  // above): the residual's sums are Σ δε (K A_max + ρ_s V |g|), δε = |R_P| dt/V, and
  // Σ ρ_s V (ε_s |g| + a_min), computed here from the iterate before the correction.
  const double dt = 1e-3;
  Corrections k(closed_box("residual_normalization = \"force\"\n"), stretched);
  set_fractions(k.c, 0.595, 0.01);
  k.c.old = k.c.state;
  for (int l = 0; l < k.c.local_count(); ++l)
    if (k.c.fluid(l)) k.c.state.solids_fraction[static_cast<std::size_t>(l)] += 0.004 * wiggle(k.c.centre(l), 8.0);
  Case::complete_gas_fraction(k.c.state);
  k.predicted_field(0.05);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.old, dt, k.fields);
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  const auto& settings = k.c.settings;
  const double rho = settings.density[solids], g = settings.gravity_magnitude;
  double stiffness_part = 0.0, weight_part = 0.0, scale = 0.0;
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const double volume = k.c.disc.volume(l);
    const double largest_area = std::max({k.c.disc.face_area(l, 0), k.c.disc.face_area(l, 1), k.c.disc.face_area(l, 2)});
    const double fraction_error = std::abs(solids_residual(k, l, dt)) * dt / volume;
    stiffness_part += fraction_error * std::max(k.fields.pressure_derivative[i], 0.0) * largest_area;
    weight_part += fraction_error * rho * volume * g;
    scale += rho * volume * (k.c.state.solids_fraction[i] * g + settings.least_acceleration);
  }
  stiffness_part = k.c.sum(stiffness_part);
  weight_part = k.c.sum(weight_part);
  scale = k.c.sum(scale);
  EXPECT_GT(stiffness_part, 10.0 * weight_part);  // the packed cells' P_s error dominates
  solver::VolumeFractionCorrection correction(k.c.disc, settings, k.closures);
  ASSERT_TRUE(correction.correct(k.c.old, dt, k.fields, k.response, k.carried, k.c.state, k.sums, k.worst, k.record))
      << k.record.failure;
  auto total = k.sums;
  total.reduce(k.c.layout().comm());
  EXPECT_NEAR(total.continuity[1][0], stiffness_part + weight_part, 1e-12 * (stiffness_part + weight_part));
  EXPECT_NEAR(total.continuity[1][1], scale, 1e-12 * scale);
}

TEST(VolumeFractionCorrection, StationaryStateHasZeroResidualAndStays) {
  const double dt = 1e-3;
  Corrections k(closed_box(), stretched);
  set_fractions(k.c, 0.3, 0.1);
  k.c.old = k.c.state;  // ε_s* = ε_s^old, u_s = 0
  k.predicted_field(0.0);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.old, dt, k.fields);
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  solver::VolumeFractionCorrection correction(k.c.disc, k.c.settings, k.closures);
  ASSERT_TRUE(correction.correct(k.c.old, dt, k.fields, k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  auto total = k.sums;
  total.reduce(k.c.layout().comm());
  EXPECT_EQ(total.continuity[1][0], 0.0);
  for (int l = 0; l < k.c.owned_fluid(); ++l)
    EXPECT_EQ(k.c.state.solids_fraction[static_cast<std::size_t>(l)], k.c.old.solids_fraction[static_cast<std::size_t>(l)]);
  for (const double count : total.interventions) EXPECT_EQ(count, 0.0);
}

TEST(VolumeFractionCorrection, CompressionIntoThePackedBedIsLimited) {
  // Solids at 0.59 everywhere (just below the plastic closure's ε_s* = 0.6, P_s = 0) flowing
  // together into the middle layer at 0.5 m/s over a long step: the linear correction would
  // pack the middle far beyond 0.6 (P_s ~ 1e24 (ε_s − 0.6)^10).
  const double dt = 0.05;
  Corrections k(unit_deck(1, 1, 5, "\"x\", \"y\"", -9.81, two_fluid() + tight));
  set_fractions(k.c, 0.59, 0.0);
  k.c.old = k.c.state;
  for (int l = 0; l < k.c.local_count(); ++l) {
    const int kz = k.c.layout().index3(l)[2];
    // w_s on the top face of layer kz: up below the middle (layer 2), down above it.
    k.c.state.solids_velocity[2][static_cast<std::size_t>(l)] = !k.unknown(l, 2) ? 0.0 : (kz < 2 ? 0.5 : -0.5);
    k.response.fraction[2][static_cast<std::size_t>(l)] = 0.0;  // no solids-pressure response
  }
  k.closures.evaluate(k.c.disc, k.c.state, k.c.old, dt, k.fields);
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  solver::VolumeFractionCorrection correction(k.c.disc, k.c.settings, k.closures);
  ASSERT_TRUE(correction.correct(k.c.old, dt, k.fields, k.response, k.carried, k.c.state, k.sums, k.worst, k.record));
  auto total = k.sums;
  total.reduce(k.c.layout().comm());
  EXPECT_GT(total.interventions[solver::compression_damped], 0.0);
  // Damped until P_s ≤ 2 × its linear prediction (0 here) + the floor ρ_s |g| h 0.6:
  // ε_s ≤ 0.6 + (floor / A)^(1/n).
  const double floor = 2500.0 * 9.81 * 0.01 * solver::CompressionLimit::floor_fraction;
  const double packed = 0.6 + std::pow(floor / 1e24, 0.1);
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    EXPECT_LE(k.c.state.solids_fraction[static_cast<std::size_t>(l)], packed + 1e-12) << "cell " << l;
    EXPECT_GE(k.c.state.solids_fraction[static_cast<std::size_t>(l)], 0.0);
  }
}

// ---------------------------------------------------------------------------------------------
// Compression limit, on hand-made corrections

TEST(CompressionLimit, ClampsACorrectionBelowZeroAndCountsIt) {
  Corrections k(closed_box());
  set_fractions(k.c, 0.01, 0.0);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.state, 1e-3, k.fields);
  solver::CompressionLimit limit(k.c.disc, k.c.settings, k.closures);
  std::vector<double> correction(static_cast<std::size_t>(k.c.local_count()), 0.0);
  int clamped = 0;
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const bool deep = l % 2 == 0;
    correction[static_cast<std::size_t>(l)] = deep ? -0.05 : -0.005;
    clamped += deep;
  }
  limit.apply(k.c.state, k.fields, correction, k.sums);
  for (int l = 0; l < k.c.owned_fluid(); ++l)
    EXPECT_EQ(correction[static_cast<std::size_t>(l)], l % 2 == 0 ? -0.01 : -0.005) << "cell " << l;
  EXPECT_EQ(k.sums.interventions[solver::fraction_clamped_at_zero], clamped);
  EXPECT_EQ(k.sums.interventions[solver::compression_damped], 0.0);
}

TEST(CompressionLimit, HalvesACompressionWhosePressureOvershoots) {
  // At ε_s = 0.6 the plastic P_s and dP_s/dε_s are 0: a correction c is kept as λ c with λ the
  // largest power of ½ for which A (λ c)^n ≤ the floor (147 Pa on 1 cm cells).
  Corrections k(closed_box());
  set_fractions(k.c, 0.6, 0.0);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.state, 1e-3, k.fields);
  solver::CompressionLimit limit(k.c.disc, k.c.settings, k.closures);
  const double floor = 2500.0 * 9.81 * 0.01 * solver::CompressionLimit::floor_fraction;
  std::vector<double> correction(static_cast<std::size_t>(k.c.local_count()), 0.0);
  for (int l = 0; l < k.c.owned_fluid(); ++l) correction[static_cast<std::size_t>(l)] = l % 3 == 0 ? 0.05 : 0.001;
  const auto given = correction;
  limit.apply(k.c.state, k.fields, correction, k.sums);
  int damped = 0;
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const double c = given[static_cast<std::size_t>(l)];
    double lambda = 1.0;
    while (1e24 * std::pow(lambda * c, 10.0) > floor) lambda *= 0.5;
    damped += lambda < 1.0;
    EXPECT_DOUBLE_EQ(correction[static_cast<std::size_t>(l)], lambda * c) << "cell " << l;
  }
  EXPECT_GT(damped, 0);
  // 0.05: P_s(0.65) ≈ 1e11 Pa; λ = 1/8 gives 0.00625 (95 Pa), λ = 1/4 would give 9.5e4 Pa.
  EXPECT_DOUBLE_EQ(correction[0], 0.05 / 8);
  EXPECT_EQ(k.sums.interventions[solver::compression_damped], damped);
  EXPECT_EQ(k.sums.interventions[solver::fraction_clamped_at_zero], 0.0);
}

TEST(CompressionLimit, LeavesAModestCompressionAlone) {
  Corrections k(closed_box());
  set_fractions(k.c, 0.3, 0.1);
  k.closures.evaluate(k.c.disc, k.c.state, k.c.state, 1e-3, k.fields);
  solver::CompressionLimit limit(k.c.disc, k.c.settings, k.closures);
  std::vector<double> correction(static_cast<std::size_t>(k.c.local_count()), 0.0);
  for (int l = 0; l < k.c.owned_fluid(); ++l) correction[static_cast<std::size_t>(l)] = 0.01 * (1.0 + wiggle(k.c.centre(l)));
  const auto given = correction;
  limit.apply(k.c.state, k.fields, correction, k.sums);
  EXPECT_EQ(correction, given);
  for (const double count : k.sums.interventions) EXPECT_EQ(count, 0.0);
}

// ---------------------------------------------------------------------------------------------
// Conservative solids update and boundary fluxes

// 3 × 3 × 6, periodic in x and y; a mass inflow below (ε_s = 0.3, w_g = 0.2, w_s = 0.05 m/s), a
// pressure outflow above. The regions: feed 0, top 1, the default walls 2.
std::string fed_column() {
  return unit_deck(3, 3, 6, "\"x\", \"y\"", -9.81,
                   two_fluid() + tight +
                       "[[boundary]]\nname = \"feed\"\ntype = \"mass_inflow\"\nface = \"z-\"\n"
                       "gas_velocity = [0.0, 0.0, 0.2]\nsolids_velocity = [0.0, 0.0, 0.05]\n"
                       "solids_fraction = 0.3\n"
                       "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n");
}

// Boundary cells as FlowSolver::apply_boundary_values sets them: the feed's ε_s, none elsewhere.
void boundary_cells(Case& c) {
  for (int l = 0; l < c.local_count(); ++l)
    if (!c.fluid(l)) c.state.solids_fraction[static_cast<std::size_t>(l)] = c.layout().index3(l)[2] < 0 ? 0.3 : 0.0;
  Case::complete_gas_fraction(c.state);
}

TEST(SolidsConservation, BoundaryFluxOfAUniformInflowIsRhoEpsUA) {
  Corrections k(fed_column(), {"grid.x.ratio=2.0"});
  set_fractions(k.c, 0.3, 0.0);
  boundary_cells(k.c);
  k.predicted_field(0.0);  // at rest inside, the feed's velocities on its faces
  const auto solids_flux = solver::boundary_mass_flux(k.c.disc, k.c.state, solids, 2500.0);
  const auto gas_flux = solver::boundary_mass_flux(k.c.disc, k.c.state, gas, 1.2);
  ASSERT_EQ(solids_flux.size(), 3u);
  const double area = 0.03 * 0.03;
  // Out of the domain is positive: the feed brings −ρ ε w A. Sums of 9 face fluxes: round-off.
  EXPECT_NEAR(solids_flux[0], -2500.0 * 0.3 * 0.05 * area, 1e-14);
  EXPECT_NEAR(gas_flux[0], -1.2 * 0.7 * 0.2 * area, 1e-15);
  EXPECT_EQ(solids_flux[1], 0.0);
  EXPECT_EQ(solids_flux[2], 0.0);
}

TEST(SolidsConservation, InventoryChangesOnlyThroughTheBoundaries) {
  const double dt = 2e-3;
  Corrections k(fed_column(), {"grid.z.ratio=2.0"});
  set_fractions(k.c, 0.3, 0.1);
  boundary_cells(k.c);
  k.c.old = k.c.state;
  k.predicted_field(0.2);
  // An outflow at the top (the outlet faces are unknowns), all the rest as predicted_field.
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  const auto flux_before = solver::boundary_mass_flux(k.c.disc, k.c.state, solids, 2500.0);
  const double before = k.c.solids_volume(k.c.old);
  const auto stepped = solver::conserve_solids(k.c.disc, k.carried, 2500.0, k.c.old, dt, k.c.state);
  EXPECT_EQ(stepped, flux_before);  // the fluxes it stepped with, before its update
  double net = 0.0;
  for (const double f : stepped) net += f;
  EXPECT_GT(std::abs(net), 1e-4);  // the boundaries carry solids [kg/s]
  // Each face's flux enters its two cells with opposite signs: round-off of ~100 cells'
  // 1e-6 m³ volumes.
  EXPECT_NEAR(k.c.solids_volume(k.c.state), before - dt * net / 2500.0, 1e-16);
  for (int l = 0; l < k.c.owned_fluid(); ++l)
    EXPECT_EQ(k.c.state.gas_fraction[static_cast<std::size_t>(l)], 1.0 - k.c.state.solids_fraction[static_cast<std::size_t>(l)]);
}

TEST(SolidsConservation, UniformVelocityAdvectsTheUpwindFraction) {
  // A periodic column 1 × 1 × 8, w_s = 0.1 m/s up everywhere: ε_P = ε_P^old − dt w/h (ε_P − ε_below)
  // with the iterate's ε (first-order upwind, conservative).
  const double dt = 1e-2, w = 0.1, h = 0.01;
  Corrections k(unit_deck(1, 1, 8, "\"x\", \"y\", \"z\"", 0.0, two_fluid() + tight));
  set_fractions(k.c, 0.3, 0.1);
  k.c.old = k.c.state;
  for (int l = 0; l < k.c.local_count(); ++l) k.c.old.solids_fraction[static_cast<std::size_t>(l)] += 0.01;
  for (auto& u : k.c.state.solids_velocity[2]) u = w;
  solver::carry_all_fractions(k.c.disc, k.c.state, k.carried);
  const run::FlowState iterate = k.c.state;
  solver::conserve_solids(k.c.disc, k.carried, 2500.0, k.c.old, dt, k.c.state);
  for (int l = 0; l < k.c.owned_fluid(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const auto below = static_cast<std::size_t>(k.c.layout().neighbour(l, parallel::bottom));
    const double expected = k.c.old.solids_fraction[i] - dt * w / h * (iterate.solids_fraction[i] - iterate.solids_fraction[below]);
    EXPECT_NEAR(k.c.state.solids_fraction[i], expected, 1e-15) << "cell " << l;
  }
}

}  // namespace
}  // namespace bagnold::tests
