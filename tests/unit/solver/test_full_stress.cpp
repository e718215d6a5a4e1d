// The full stress tensor in the momentum rows (solver/simple/momentum_assembly.cpp):
//   σ = −P I + μ (∇u + ∇uᵀ) + (λ − ⅔ μ)(∇·u) I.
// The stress force on a row is measured from the rows themselves: the row residual
// b + Σ a_nb u_nb − a_P u_P with the viscosities set, minus the same with them zero (convection,
// the transient, gravity and the pressures do not depend on μ or λ, so they cancel).
//   - uniaxial extension u = (a x, −a y, 0) beside a stress-free region: the tractions are
//     σ_xx = 2 μ a and σ_yy = −2 μ a (their difference 4 μ a: the transpose doubles it);
//   - the steady-shear closure under a homogeneous, dilatant velocity gradient: the normal
//     tractions equal σ = p(I − η S/|D|) of App. A Eq. 15 with p and η from the published
//     equations at γ̇ = 2|D| (Eq. 14);
//   - a two-layer Couette flow (μ = 1 and 10⁴ Pa s): the exact piecewise-linear profile leaves
//     every row in balance with harmonic face viscosities, and not with arithmetic ones.
// On 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "models/stress/blended_rheology.hpp"
#include "models/stress/steady_shear.hpp"
#include "solver/simple/closures.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::gas;
using solver::solids;

constexpr double dt = 1e-3;  // [s]

// The rows' stress force along d per owned unknown face, with the closure fields as given.
struct StressRows {
  explicit StressRows(const std::string& text)
      : c(text), fields(static_cast<std::size_t>(c.local_count())),
        carried(static_cast<std::size_t>(c.local_count())) {}

  std::vector<solver::MomentumRow> rows(solver::Phase phase, int d, const solver::ClosureFields& f) {
    const std::array<std::vector<double>, 3> no_source;
    solver::carry_all_fractions(c.disc, c.state, carried);
    const solver::MomentumAssemblyInputs in{c.disc, c.settings, c.old, dt, f, carried, no_source};
    std::vector<solver::MomentumRow> out;
    solver::MomentumAssemblyScratch scratch;
    solver::assemble_momentum_rows(in, phase, d, c.state, nullptr, true, out, scratch);
    return out;
  }
  double residual(const solver::MomentumRow& row, int l, int d, solver::Phase phase) const {
    const auto& u = (phase == gas ? c.state.gas_velocity : c.state.solids_velocity)[static_cast<std::size_t>(d)];
    return row.b + row.neighbours_u - row.a * u[static_cast<std::size_t>(l)];
  }
  // Σ of the stress force on each owned unknown face along d (indexed like the numbering).
  std::vector<double> stress_force(solver::Phase phase, int d) {
    solver::ClosureFields inviscid = fields;
    for (auto& v : inviscid.viscosity) std::fill(v.begin(), v.end(), 0.0);
    std::fill(inviscid.bulk_viscosity.begin(), inviscid.bulk_viscosity.end(), 0.0);
    const auto with = rows(phase, d, fields);
    const auto without = rows(phase, d, inviscid);
    const auto& numbering = c.disc.velocity_numbering(d);
    std::vector<double> force(numbering.owned_locals.size());
    for (std::size_t r = 0; r < force.size(); ++r) {
      const int l = numbering.owned_locals[r];
      force[r] = residual(with[r], l, d, phase) - residual(without[r], l, d, phase);
    }
    return force;
  }

  Case c;
  solver::ClosureFields fields;
  solver::CarriedFractions carried;
};

// A closed 8 × 8 × 8 box of 1 cm cells, solids only, with the closure `stress`. Harmonic edge
// viscosities: an edge that touches a stress-free cell (μ = 0) then carries no shear, so the
// stress force on a row beside a stress-free region is the normal traction alone.
std::string solids_box(const std::string& stress = "plastic") {
  return unit_deck(8, 8, 8, "", 0.0,
                   two_fluid(stress, false) + "[numerics]\nviscosity_average = \"harmonic\"\n");
}

// The traction on the + side of the plane x_d = x0 (a cell face) with the region below it free
// of stress: the stress force on the row of the face at x0, over its area, averaged over the
// rows of that plane away from the box's walls.
double traction(StressRows& s, int d, double x0, const std::vector<double>& force) {
  const auto& numbering = s.c.disc.velocity_numbering(d);
  double sum = 0.0, count = 0.0;
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    const int l = numbering.owned_locals[r];
    const auto x = s.c.face_position(l, d);
    if (std::abs(x[static_cast<std::size_t>(d)] - x0) > 1e-9) continue;
    bool interior = true;
    for (int e = 0; e < 3; ++e)
      if (e != d && (x[static_cast<std::size_t>(e)] < 0.02 || x[static_cast<std::size_t>(e)] > 0.06)) interior = false;
    if (!interior) continue;
    sum += force[r] / s.c.disc.face_area(l, d);
    count += 1.0;
  }
  sum = s.c.sum(sum);
  count = s.c.sum(count);
  EXPECT_GT(count, 0.0);
  return sum / count;
}

// Zero the closure fields (and P_s) of the cells whose centre lies below x0 along d.
void free_below(StressRows& s, int d, double x0) {
  for (int l = 0; l < s.c.local_count(); ++l) {
    if (s.c.centre(l)[static_cast<std::size_t>(d)] > x0) continue;
    const auto i = static_cast<std::size_t>(l);
    s.fields.viscosity[solids][i] = 0.0;
    s.fields.bulk_viscosity[i] = 0.0;
    s.c.state.solids_pressure[i] = 0.0;
  }
}

TEST(FullStress, UniaxialExtensionHasNormalStressDifferenceFourMuA) {
  const double a = 3.0, mu = 7.0, x0 = 0.04;  // [1/s], [Pa s], the plane [m]
  const double G[3][3] = {{a, 0, 0}, {0, -a, 0}, {0, 0, 0}};
  std::array<double, 2> normal{};
  for (int d = 0; d < 2; ++d) {
    StressRows s(solids_box());
    set_linear_solids(s.c, 0.5, G);
    std::fill(s.fields.viscosity[solids].begin(), s.fields.viscosity[solids].end(), mu);
    solver::velocity_divergence(s.c.disc, s.c.state.solids_velocity, s.fields.divergence[solids]);
    free_below(s, d, x0);
    normal[static_cast<std::size_t>(d)] = traction(s, d, x0, s.stress_force(solids, d));
  }
  EXPECT_NEAR(normal[0], 2.0 * mu * a, 1e-9 * mu * a);
  EXPECT_NEAR(normal[1], -2.0 * mu * a, 1e-9 * mu * a);
  EXPECT_NEAR(normal[0] - normal[1], 4.0 * mu * a, 1e-9 * mu * a);  // ∇·(μ ∇u) alone: 2 μ a
}

TEST(FullStress, SteadyShearNormalStressesAreAppendixAEquation15UnderADilatantGradient) {
  // A homogeneous gradient with shear, extension and a net dilation (tr G ≠ 0).
  const double G[3][3] = {{4.0, 10.0, 0.0}, {0.0, -1.0, 6.0}, {3.0, 0.0, 2.5}};
  const double phi = 0.57, x0 = 0.04;
  // App. A Eqs. 14-15 by hand: D, S = D − ⅓ tr D I, |D| = sqrt(½ D:D), γ̇ = 2|D|.
  double D[3][3], trace = 0.0, dd = 0.0;
  for (int i = 0; i < 3; ++i) {
    trace += G[i][i];
    for (int j = 0; j < 3; ++j) D[i][j] = 0.5 * (G[i][j] + G[j][i]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dd += D[i][j] * D[i][j];
  const double modulus = std::sqrt(0.5 * dd), rate = 2.0 * modulus;

  for (int d = 0; d < 3; ++d) {
    StressRows s(solids_box("steady-shear"));
    // p and η of App. A Eqs. 7-13 at φ and γ̇ = 2|D|, from the published forms.
    const models::Material& m = s.c.deck.solids.material;
    const auto c = models::steady_shear::constants_at(m.friction, models::steady_shear::Constants{});
    const double stress_scale = m.stiffness / m.diameter;
    const double scaled_rate = models::blended::scaled_shear_rate(rate, m);
    const double p = models::blended::scaled_pressure(phi, scaled_rate, 0.0, c) * stress_scale;
    const double eta = models::blended::hard_stress_ratio(scaled_rate / std::sqrt(p / stress_scale), c) -
                       models::blended::soft_stress_ratio(scaled_rate, c);
    ASSERT_GT(p, 0.0);
    ASSERT_GT(eta, 0.0);
    ASSERT_LT(eta * p / rate, 1e4) << "the viscosity cap would act";

    set_linear_solids(s.c, phi, G);
    solver::Closures closures(s.c.deck, s.c.disc);
    closures.evaluate(s.c.disc, s.c.state, s.c.old, dt, s.fields);
    // An interior cell carries p, μ_s = η p/γ̇ and no bulk viscosity.
    for (int l = 0; l < s.c.layout().owned_fluid_count(); ++l) {
      const auto x = s.c.centre(l);
      if (std::abs(x[0] - 0.045) > 1e-9 || std::abs(x[1] - 0.045) > 1e-9 || std::abs(x[2] - 0.045) > 1e-9) continue;
      const auto i = static_cast<std::size_t>(l);
      EXPECT_NEAR(s.c.state.solids_pressure[i], p, 1e-12 * p);
      // μ_s = η p/sqrt(γ̇² + γ̇_min²) (regularization.hpp), η p/γ̇ with the default γ̇_min = 0.
      EXPECT_NEAR(s.fields.viscosity[solids][i], eta * p / rate, 1e-8 * eta * p / rate);
      EXPECT_EQ(s.fields.bulk_viscosity[i], 0.0);
    }
    free_below(s, d, x0);
    // The viscous traction; P_s enters the row as a pressure gradient, the same with and
    // without the viscosities, so Eq. 15's isotropic part is −p.
    const double measured = -p + traction(s, d, x0, s.stress_force(solids, d));
    // Tension-positive Cauchy stress of Eq. 15 (which is compression positive): −p + η p S_dd/|D|.
    const double expected = -p + eta * p * (D[d][d] - trace / 3.0) / modulus;
    EXPECT_NEAR(measured, expected, 1e-8 * p) << "direction " << d;
  }
}

// A Couette flow along x across y: μ = 1 below y = H/2, 10⁴ above, walls at y = 0 and H; the
// exact profile u(y) is linear in each layer with the same shear stress τ in both.
double couette_imbalance(const std::string& average, bool plastic_rates = false) {
  StressRows s(unit_deck(4, 8, 4, "\"x\", \"z\"", 0.0, two_fluid("plastic", false) +
                                                           "[numerics]\nviscosity_average = \"" + average + "\"\n"));
  const double H = 0.08, mu_low = 1.0, mu_high = 1e4, tau = 5.0;
  for (int l = 0; l < s.c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    s.c.state.solids_fraction[i] = 0.5;
    const double y = s.c.face_position(l, 0)[1];
    const double u = y <= 0.5 * H ? tau * y / mu_low : tau * (0.5 * H) / mu_low + tau * (y - 0.5 * H) / mu_high;
    s.c.state.solids_velocity[0][i] = u;
    s.fields.viscosity[solids][i] = s.c.centre(l)[1] < 0.5 * H ? mu_low : mu_high;
    // Each layer's own strain rate τ/μ, as a plastic closure (μ = τ/γ̇) would give it.
    if (plastic_rates) s.fields.strain_rate[i] = tau / s.fields.viscosity[solids][i];
  }
  s.c.old = s.c.state;
  const auto force = s.stress_force(solids, 0);
  // Every row but the top layer's (whose wall is at rest while the profile is not).
  double worst = 0.0;
  const auto& numbering = s.c.disc.velocity_numbering(0);
  for (std::size_t r = 0; r < force.size(); ++r) {
    const int l = numbering.owned_locals[r];
    if (s.c.centre(l)[1] > H - 0.01) continue;
    worst = std::max(worst, std::abs(force[r]) / (tau * s.c.disc.face_area(l, 1)));
  }
  return s.c.max(worst);
}

TEST(FullStress, TwoLayerCouetteProfileIsExactWithHarmonicViscosities) {
  EXPECT_LT(couette_imbalance("harmonic"), 1e-9);
  EXPECT_GT(couette_imbalance("arithmetic"), 0.1);  // the interface's edge viscosity is wrong
}

// The same two layers as a plastic material: both carry the yield stress τ, the upper one
// nearly rigid (γ̇ = τ/μ = 5·10⁻⁴ 1/s against 5 1/s). With arithmetic means the interface's edge
// takes half the rigid layer's viscosity on the mean of the two shear rates and carries about
// 2,500 τ; with yield-bounded means the rigid cells there count with their stress over the
// edge's rate, and the edge carries (1 + γ̇_e/γ̇_low)/2 τ ≈ 0.75 τ: within the cells' stresses,
// so no row is out of balance by more than a quarter of τ A.
TEST(FullStress, YieldBoundedEdgesKeepARigidLayerToItsYieldStress) {
  const double bounded = couette_imbalance("yield-bounded", true);
  EXPECT_LT(bounded, 0.26);
  EXPECT_GT(bounded, 0.24);  // (1 − γ̇_e/γ̇_low)/2 with γ̇_e the two layers' mean rate
  EXPECT_GT(couette_imbalance("arithmetic", true), 1000.0);
}

// numerics.shear_on_opening_faces: a plug over a 1 cm hole in the floor of a 3 × 3 × 3 box
// (μ_s = 1 Pa s in every fluid cell, 0 in the outflow cell, as the closures leave it), the
// walls' faces at rest. Moving down (w = W), the hole's face row, half in the outflow cell, is
// held back by the floor's and the other faces' shear by default (its edges take the mean of the
// two cells' viscosities) and feels none with the key false (MFIX); every other z-row is the
// same either way. Sliding along x (u = U), the x-row of the face x = 1 cm over the hole's
// edge (c over the floor, n over the hole) loses the shear of its floor edge, half over the
// outflow cell, and only it: the row at x = 2 cm, whose own cell c is over the hole, takes the
// outflow cell's open condition across that edge either way (velocity_faces.cpp,
// side_condition looks at the cell under c first).
std::string box_with_a_hole(bool shear_on_opening_faces) {
  return tests::box_with_a_hole(std::string("shear_on_opening_faces = ") + (shear_on_opening_faces ? "true" : "false"));
}

std::vector<double> plug_over_a_hole(StressRows& s, int d, double speed) {
  for (int l = 0; l < s.c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    s.c.state.solids_fraction[i] = 0.5;
    const bool unknown = s.c.disc.faces(solids).kind[static_cast<std::size_t>(d)][i] == solver::FaceClass::unknown;
    s.c.state.solids_velocity[static_cast<std::size_t>(d)][i] = unknown ? speed : 0.0;
    s.fields.viscosity[solids][i] = s.c.fluid(l) ? 1.0 : 0.0;
  }
  s.c.old = s.c.state;
  return s.stress_force(solids, d);
}

TEST(FullStress, AnOpeningsFaceIsShearedUnlessMfixsRuleIsChosen) {
  const double speed = -0.4, mu = 1.0, width = 0.01;
  StressRows sheared_rows(box_with_a_hole(true)), free_rows(box_with_a_hole(false));
  const auto sheared = plug_over_a_hole(sheared_rows, 2, speed);
  const auto free = plug_over_a_hole(free_rows, 2, speed);
  ASSERT_EQ(sheared.size(), free.size());
  const auto& numbering = sheared_rows.c.disc.velocity_numbering(2);
  int hole_rows = 0;
  for (std::size_t r = 0; r < sheared.size(); ++r) {
    const int l = numbering.owned_locals[r];
    const auto x = sheared_rows.c.face_position(l, 2);
    if (std::abs(x[2]) < 1e-12) {
      ++hole_rows;
      // Each of the four walls beside it: (μ/2) |W| A/(w/2), A = w²/2 (the half inside).
      EXPECT_NEAR(sheared[r], 4.0 * 0.5 * mu * -speed * 0.5 * width * width / (0.5 * width), 1e-12);
      EXPECT_NEAR(free[r], 0.0, 1e-12);
    } else {
      EXPECT_NEAR(free[r], sheared[r], 1e-12) << "row at z = " << x[2];
    }
  }
  EXPECT_EQ(sheared_rows.c.sum(static_cast<double>(hole_rows)), 1.0);

  // Sliding along x: the rows of the faces x = 1 and 2 cm at the hole's y, in the bottom layer.
  StressRows sheared_x(box_with_a_hole(true)), free_x(box_with_a_hole(false));
  const auto sheared_u = plug_over_a_hole(sheared_x, 0, speed);
  const auto free_u = plug_over_a_hole(free_x, 0, speed);
  const auto& numbering_x = sheared_x.c.disc.velocity_numbering(0);
  int over_the_hole = 0;
  for (std::size_t r = 0; r < sheared_u.size(); ++r) {
    const auto x = sheared_x.c.face_position(numbering_x.owned_locals[r], 0);
    const bool over = std::abs(x[1] - 0.015) < 1e-12 && std::abs(x[2] - 0.005) < 1e-12 &&
                      x[0] > 0.005 && x[0] < 0.025;
    if (over) {
      ++over_the_hole;
      // The floor edge's shear by default: μ |U| A/(w/2), A = w² (both cells fluid, μ = 1).
      const double edge = x[0] < 0.015 ? mu * -speed * width * width / (0.5 * width) : 0.0;
      EXPECT_NEAR(sheared_u[r] - free_u[r], edge, 1e-12) << "x-row at x = " << x[0];
    } else {
      EXPECT_NEAR(free_u[r], sheared_u[r], 1e-12) << "x-row at " << x[0] << ", " << x[1] << ", " << x[2];
    }
  }
  EXPECT_EQ(sheared_x.c.sum(static_cast<double>(over_the_hole)), 2.0);
}

}  // namespace
}  // namespace bagnold::tests
