// Step 0, the closures (solver/simple/closures.hpp): β is the drag law at ε_g and the centre slip
// speed, zero without solids; ε_g μ_g; P_s, dP_s/dε_s, μ_s, λ_s, Θ are the stress model's at
// the cell's ε_s and strain rate; with τ_P the pressure's rate relaxes by implicit Euler.
// Every local fluid cell (owned and halo), on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "models/drag/drag_law.hpp"
#include "models/stress/solids_stress.hpp"
#include "solver/simple/closures.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::gas;
using solver::solids;

constexpr double shear = 3.0;        // ∂u_s/∂z [1/s]
constexpr double compression = 0.5;  // ∂w_s/∂z [1/s]

// 3 × 3 × 4 (periodic in x, y; walls in z), stretched in z, with the closure `stress`.
// The walls' shear stays out of γ̇ (numerics.wall_shear_in_strain_rate; test_strain_rate has it).
// `numerics`: further lines of the [numerics] table.
std::string column(const std::string& stress, const std::string& numerics = "") {
  return unit_deck(3, 3, 4, "\"x\", \"y\"", -9.81,
                   two_fluid(stress) + "[numerics]\nwall_shear_in_strain_rate = false\n" + numerics);
}

// ε_s per layer: none in the bottom layer, then dilute to dense; u_s = (γ̇ z, 0, c z), u_g =
// (0.2, 0, 0.1 + 4 z) at the face positions (linear, so the strain rate is exact).
void fill(Case& c) {
  const double layer[4] = {0.0, 0.2, 0.45, 0.58};
  for (int l = 0; l < c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const int k = c.layout().index3(l)[2];
    c.state.solids_fraction[i] = c.fluid(l) ? layer[k] : 0.0;
    c.state.solids_velocity[0][i] = shear * c.face_position(l, 0)[2];
    c.state.solids_velocity[2][i] = compression * c.face_position(l, 2)[2];
    c.state.gas_velocity[0][i] = 0.2;
    c.state.gas_velocity[2][i] = 0.1 + 4.0 * c.face_position(l, 2)[2];
  }
  Case::complete_gas_fraction(c.state);
  c.old = c.state;
}

// sqrt(2 D:D) of u = (γ̇ z, 0, c z): D_xz = γ̇/2, D_zz = c.
double expected_rate() { return std::sqrt(2.0 * (2.0 * 0.25 * shear * shear + compression * compression)); }

// The stress model the deck names, evaluated at single cells.
struct Reference {
  explicit Reference(const deck::Deck& deck)
      : material(deck.solids.material),
        model(models::stress_registry().create(deck.models.solids_stress.name,
                                               deck.models.solids_stress.coefficients)) {}
  std::array<double, 5> at(double fraction, double rate, double divergence) const {
    double p, dp, mu, lambda, theta;
    models::SolidsStress out{std::span(&p, 1), std::span(&dp, 1), std::span(&mu, 1),
                             std::span(&lambda, 1), std::span(&theta, 1)};
    model->evaluate(material, {std::span(&fraction, 1), std::span(&rate, 1), std::span(&divergence, 1)}, out);
    return {p, dp, mu, lambda, theta};
  }
  models::Material material;
  std::unique_ptr<models::SolidsStressModel> model;
};

void expect_close(double actual, double expected, const char* what, int l) {
  // The same model at the same inputs; the rate carries round-off ~1e-15 of γ̇ from the
  // staggered differences, which a smooth closure passes on at that relative size.
  EXPECT_NEAR(actual, expected, 1e-9 * std::abs(expected) + 1e-300) << what << " in cell " << l;
}

TEST(Closures, DragIsTheLawAtTheCentreSlipAndZeroWithoutSolids) {
  Case c(column("plastic"), {"grid.z.ratio=2.0"});
  fill(c);
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  const auto law = models::drag_registry().create(c.deck.models.drag.name, c.deck.models.drag.coefficients);
  const models::DragProperties properties{c.deck.gas.density, c.deck.gas.viscosity,
                                          c.deck.solids.material.diameter, c.deck.solids.material.density};
  int empty = 0, laden = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    if (!c.fluid(l)) {
      EXPECT_EQ(fields.drag[i], 0.0) << "boundary cell " << l;
      continue;
    }
    const double z = c.centre(l)[2];
    // Slip at the centre from the linear fields themselves, not from the stencil.
    const double slip = std::hypot(0.2 - shear * z, 0.1 + 4.0 * z - compression * z);
    double beta = 0.0;
    const double eps_g = c.state.gas_fraction[i];
    law->evaluate(properties, {std::span(&eps_g, 1), std::span(&slip, 1)}, std::span(&beta, 1));
    if (c.state.solids_fraction[i] == 0.0) {
      EXPECT_EQ(fields.drag[i], 0.0) << "cell " << l;  // no solids, no drag
      ++empty;
    } else {
      // β(ε_g, |slip|) with |slip| exact to round-off; Gidaspow is smooth in the slip.
      EXPECT_NEAR(fields.drag[i], beta, 1e-10 * beta) << "cell " << l;
      EXPECT_GT(beta, 0.0);
      ++laden;
    }
  }
  EXPECT_GT(empty, 0);
  EXPECT_GT(laden, 0);
}

TEST(Closures, GasViscosityIsFractionTimesViscosity) {
  Case c(column("plastic"), {"grid.z.ratio=2.0"});
  fill(c);
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  for (int l = 0; l < c.local_count(); ++l)
    EXPECT_DOUBLE_EQ(fields.viscosity[gas][static_cast<std::size_t>(l)],
                     c.state.gas_fraction[static_cast<std::size_t>(l)] * 1.8e-5) << "cell " << l;
}

TEST(Closures, NoDragWithoutGas) {
  // Solids in vacuum: the same slip, but β stays zero.
  Case c(unit_deck(3, 3, 4, "\"x\", \"y\"", -9.81, two_fluid("plastic", false)));
  fill(c);
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  for (int l = 0; l < c.local_count(); ++l) EXPECT_EQ(fields.drag[static_cast<std::size_t>(l)], 0.0);
  // The stresses are still evaluated: μ_s of the plastic closure is μ_0 min(ε_s/ε_s*, 1) > 0
  // wherever there are solids.
  for (int l = 0; l < c.owned_fluid(); ++l)
    if (c.state.solids_fraction[static_cast<std::size_t>(l)] > 0.0) {
      EXPECT_GT(fields.viscosity[solids][static_cast<std::size_t>(l)], 0.0);
    }
}

TEST(Closures, SolidsStressIsTheModelAtTheCellsFractionAndStrainRate) {
  // steady-shear: P_s depends on γ̇ as well as ε_s, so a wrong rate would show.
  // Without the walls' shear in γ̇, so that every cell's rate is the linear field's.
  Case c(column("steady-shear"), {"grid.z.ratio=2.0"});
  fill(c);
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  const Reference reference(c.deck);
  int dense = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    if (!c.fluid(l)) continue;
    const auto i = static_cast<std::size_t>(l);
    // Linear fields: the staggered strain rate and divergence are exact (test_strain_rate).
    EXPECT_NEAR(fields.strain_rate[i], expected_rate(), 1e-9);
    EXPECT_NEAR(fields.divergence[solver::solids][i], compression, 1e-9);
    const auto expected = reference.at(c.state.solids_fraction[i], expected_rate(), compression);
    expect_close(c.state.solids_pressure[i], expected[0], "P_s", l);
    expect_close(fields.pressure_derivative[i], expected[1], "dP_s/deps_s", l);
    expect_close(fields.viscosity[solids][i], expected[2], "mu_s", l);
    expect_close(fields.bulk_viscosity[i], expected[3], "lambda_s", l);
    // Without τ_P the pressure's rate is the current one.
    EXPECT_NEAR(c.state.pressure_shear_rate[i], expected_rate(), 1e-9);
    if (expected[0] > 0.0) ++dense;
  }
  EXPECT_GT(dense, 0);
}

TEST(Closures, RelaxedPressureShearRateIsImplicitEuler) {
  const double tau = 0.1, dt = 0.02, before = 1.0;
  Case c(column("steady-shear", "pressure_shear_rate_relaxation_time = 0.1\n"),
         {"grid.z.ratio=2.0"});
  fill(c);
  // The step's start had γ̇_P = 1 /s in the upper half, none (NaN: a fresh start) below.
  for (int l = 0; l < c.local_count(); ++l)
    c.old.pressure_shear_rate[static_cast<std::size_t>(l)] = c.layout().index3(l)[2] >= 2 ? before : std::nan("");
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, dt, fields);
  const Reference reference(c.deck);
  const double relaxed = (before + dt / tau * expected_rate()) / (1.0 + dt / tau);
  int checked = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    if (!c.fluid(l)) continue;
    const auto i = static_cast<std::size_t>(l);
    const bool has_old = c.layout().index3(l)[2] >= 2;
    const double rate_p = has_old ? relaxed : expected_rate();
    EXPECT_NEAR(c.state.pressure_shear_rate[i], rate_p, 1e-9) << "cell " << l;
    // P_s and dP_s/dε_s at γ̇_P, μ_s at the current γ̇.
    const auto at_p = reference.at(c.state.solids_fraction[i], rate_p, compression);
    const auto at_now = reference.at(c.state.solids_fraction[i], expected_rate(), compression);
    expect_close(c.state.solids_pressure[i], at_p[0], "P_s at the relaxed rate", l);
    expect_close(fields.pressure_derivative[i], at_p[1], "dP_s/deps_s at the relaxed rate", l);
    expect_close(fields.viscosity[solids][i], at_now[2], "mu_s at the current rate", l);
    if (has_old && at_p[0] > 0.0) {
      // The relaxation matters here: P_s at the current rate would differ.
      EXPECT_GT(std::abs(at_now[0] - at_p[0]), 1e-3 * at_p[0]);
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

// numerics.solids_bulk_viscosity_ratio r adds r μ_s to λ_s in the steps that start before
// numerics.solids_bulk_viscosity_until, and nothing from that time on.
TEST(Closures, BulkViscosityActsInStepsStartingBeforeItsEnd) {
  Case c(column("steady-shear", "solids_bulk_viscosity_ratio = 2.0\nsolids_bulk_viscosity_until = 0.5\n"),
         {"grid.z.ratio=2.0"});
  fill(c);
  solver::Closures closures(c.deck, c.disc);
  const Reference reference(c.deck);
  for (const auto& [start, ratio] : {std::pair{0.0, 2.0}, std::pair{0.4999, 2.0}, std::pair{0.5, 0.0},
                                     std::pair{3.0, 0.0}}) {
    closures.set_step_start(start);
    solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
    closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
    int dense = 0;
    for (int l = 0; l < c.local_count(); ++l) {
      if (!c.fluid(l)) continue;
      const auto i = static_cast<std::size_t>(l);
      const auto expected = reference.at(c.state.solids_fraction[i], expected_rate(), compression);
      expect_close(fields.bulk_viscosity[i], expected[3] + ratio * expected[2], "lambda_s", l);
      if (expected[2] > 0.0) ++dense;
    }
    EXPECT_GT(dense, 0) << "step start " << start;
  }
}

// The column's top as a pressure outflow (a [[boundary]] table to append).
const std::string top_outflow = "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n";

// Deck c's closures evaluated once at its state (dt = 1 ms).
solver::ClosureFields evaluated(Case& c) {
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  return fields;
}

// An outflow cell of a pressure_outflow region holds its fluid neighbour's P_s with
// solids_pressure = "zero-gradient" (MFIX's set_outflow) and 0 with "zero" (the default).
TEST(Closures, OutflowCellsTakeTheirNeighboursSolidsPressureUnlessZero) {
  for (const std::string treatment : {"zero-gradient", "zero"}) {
    Case c(column("steady-shear", top_outflow + "solids_pressure = \"" + treatment + "\"\n"));
    fill(c);
    evaluated(c);  // the state's P_s
    int outflow_cells = 0;
    for (int l = 0; l < c.local_count(); ++l) {
      if (c.layout().kind(l) != grid::CellKind::boundary || c.layout().index3(l)[2] != 4) continue;
      const int below = c.layout().neighbour(l, parallel::bottom);
      if (!c.fluid(below)) continue;
      const double inside = c.state.solids_pressure[static_cast<std::size_t>(below)];
      ASSERT_GT(inside, 0.0);
      EXPECT_EQ(c.state.solids_pressure[static_cast<std::size_t>(l)], treatment == "zero" ? 0.0 : inside) << treatment;
      ++outflow_cells;
    }
    EXPECT_GT(c.sum(outflow_cells), 0);
  }
}

// numerics.copy_velocity_into_openings reaches the closures' strain rate even with the walls'
// shear left out of it (this column's wall_shear_in_strain_rate = false): under u_s = γ̇ z the
// top layer below a pressure outflow takes the one-sided ∂u/∂z = γ̇ by default, and with the key
// the outflow cell's copy of u_c a width away: γ̇ h/(h + w), h the distance to the layer below,
// w the top layer's height (MFIX's SET_OUTFLOW).
TEST(Closures, OutflowCellsCanHoldTheirNeighboursVelocityInTheStrainRate) {
  for (const bool copy : {false, true}) {
    Case c(column("plastic", std::string("copy_velocity_into_openings = ") + (copy ? "true" : "false") + "\n" +
                                 top_outflow));
    fill(c);
    const auto fields = evaluated(c);
    int top_cells = 0;
    for (int l = 0; l < c.owned_fluid(); ++l) {
      if (c.layout().index3(l)[2] != 3) continue;
      const int below = c.layout().neighbour(l, parallel::bottom);
      const double w = c.disc.width(l, 2), h = 0.5 * (w + c.disc.width(below, 2));
      const double gradient = copy ? shear * h / (h + w) : shear;
      const double expected = std::sqrt(gradient * gradient + 2.0 * compression * compression);
      EXPECT_NEAR(fields.strain_rate[static_cast<std::size_t>(l)], expected, 1e-9 * expected) << "copy " << copy;
      ++top_cells;
    }
    EXPECT_GT(c.sum(top_cells), 0);
  }
}

}  // namespace
}  // namespace bagnold::tests
