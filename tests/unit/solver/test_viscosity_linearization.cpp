// numerics.viscosity_linearization = "newton" (closures.cpp, momentum_assembly.cpp): the solids
// rows take the tangent of τ = 2 μ_s(γ̇) D along the current strain direction implicitly and the
// rest of μ_s on the iterate.
//   - In simple shear u_x = G z the tangent factor of the xz faces is the flow index
//     n = dln τ/dln γ̇: 2 for MKT below jamming (Bagnold scaling, τ ∝ γ̇²), about 0 in the
//     jammed, rate-independent frictional state; the faces of the components D does not have
//     keep the secant viscosity (factor 1).
//   - At the iterate the Newton rows have the Picard rows' residual (the converged step is the
//     same), and a different diagonal.
// On 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/simple/closures.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "solver/strain_rate.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::solids;

constexpr double dt = 1e-3;  // [s]

std::string newton_box() {
  return unit_deck(6, 6, 6, "", 0.0,
                   two_fluid("mkt", false) + "[numerics]\nviscosity_linearization = \"newton\"\n");
}

// The tangent factors of the box's central cell under simple shear u_x = rate · z at ε_s.
std::array<double, 6> simple_shear_factors(double eps_s, double rate) {
  Case c(newton_box());
  const double G[3][3] = {{0, 0, rate}, {0, 0, 0}, {0, 0, 0}};
  set_linear_solids(c, eps_s, G);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  solver::Closures closures(c.deck, c.disc);
  closures.evaluate(c.disc, c.state, c.old, dt, fields);
  std::array<double, 6> factors{};
  double found = 0.0;
  for (int l = 0; l < c.owned_fluid(); ++l) {
    const auto x = c.centre(l);
    if (std::abs(x[0] - 0.025) > 1e-9 || std::abs(x[1] - 0.025) > 1e-9 || std::abs(x[2] - 0.025) > 1e-9) continue;
    for (std::size_t k = 0; k < 6; ++k) factors[k] = fields.tangent_factor[k][static_cast<std::size_t>(l)];
    found = 1.0;
  }
  // Gather the owning rank's values.
  const double owner = c.sum(found);
  EXPECT_EQ(owner, 1.0);
  for (auto& f : factors) f = c.sum(found * f);
  return factors;
}

TEST(ViscosityLinearization, SimpleShearTangentIsTheFlowIndex) {
  const int xz = solver::symmetric_component(0, 2);
  // Below jamming MKT is kinetic, τ ∝ γ̇²: n = 2.
  const auto kinetic = simple_shear_factors(0.55, 10.0);
  EXPECT_NEAR(kinetic[static_cast<std::size_t>(xz)], 2.0, 1e-3);
  // Jammed (φ = 0.6 > φ_c), the frictional stress barely depends on the rate: n ≈ 0.
  const auto jammed = simple_shear_factors(0.60, 10.0);
  EXPECT_LT(jammed[static_cast<std::size_t>(xz)], 0.02);
  EXPECT_GE(jammed[static_cast<std::size_t>(xz)], 0.0);
  // D has no xx, yy, zz, xy, yz part: those faces keep μ_s.
  for (const int k : {0, 1, 2, 3, 5}) {
    EXPECT_DOUBLE_EQ(kinetic[static_cast<std::size_t>(k)], 1.0) << k;
    EXPECT_DOUBLE_EQ(jammed[static_cast<std::size_t>(k)], 1.0) << k;
  }
}

TEST(ViscosityLinearization, NewtonRowsHaveThePicardResidualAtTheIterate) {
  Case c(newton_box());
  const double G[3][3] = {{4.0, 10.0, 0.0}, {0.0, -1.0, 6.0}, {3.0, 0.0, 2.5}};
  set_linear_solids(c, 0.6, G);
  solver::ClosureFields newton(static_cast<std::size_t>(c.local_count()));
  solver::Closures closures(c.deck, c.disc);
  closures.evaluate(c.disc, c.state, c.old, dt, newton);
  solver::ClosureFields picard = newton;
  for (auto& f : picard.tangent_factor) f.clear();
  solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
  solver::carry_all_fractions(c.disc, c.state, carried);
  const std::array<std::vector<double>, 3> no_source;
  double worst = 0.0, scale = 0.0, changed = 0.0;
  for (int d = 0; d < 3; ++d) {
    auto rows = [&](const solver::ClosureFields& f) {
      const solver::MomentumAssemblyInputs in{c.disc, c.settings, c.old, dt, f, carried, no_source};
      std::vector<solver::MomentumRow> out;
      solver::MomentumAssemblyScratch scratch;
      solver::assemble_momentum_rows(in, solids, d, c.state, nullptr, true, out, scratch);
      return out;
    };
    const auto with_newton = rows(newton), with_picard = rows(picard);
    const auto& numbering = c.disc.velocity_numbering(d);
    const auto& u = c.state.solids_velocity[static_cast<std::size_t>(d)];
    for (std::size_t r = 0; r < with_newton.size(); ++r) {
      const double u_p = u[static_cast<std::size_t>(numbering.owned_locals[r])];
      auto residual = [u_p](const solver::MomentumRow& row) { return row.b + row.neighbours_u - row.a * u_p; };
      worst = std::max(worst, std::abs(residual(with_newton[r]) - residual(with_picard[r])));
      scale = std::max(scale, with_picard[r].force);
      if (std::abs(with_newton[r].a - with_picard[r].a) > 0.01 * with_picard[r].a) changed += 1.0;
    }
  }
  EXPECT_LT(c.max(worst), 1e-10 * c.max(scale));
  EXPECT_GT(c.sum(changed), 0.0);
}

}  // namespace
}  // namespace bagnold::tests
