// Phase fractions at staggered faces (solver/simple/face_fractions.hpp): the solids carry their
// upwind ε_s; the momentum equation's face fraction is linear between the centres on a stretched
// grid and, at a boundary face, what flows through it; carry_fractions stores the same values.
// On 1 and 2 ranks.
#include <gtest/gtest.h>

#include "solver/simple/face_fractions.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::gas;
using solver::solids;

// 3 × 3 × 6, periodic in x and y, stretched in z (last/first 3); a mass inflow at the bottom
// (ε_s = 0.3, w_g = 0.2, w_s = 0.05 m/s), a pressure outflow at the top.
std::string fed_column() {
  return unit_deck(3, 3, 6, "\"x\", \"y\"", 0.0,
                   two_fluid() +
                       "[[boundary]]\nname = \"feed\"\ntype = \"mass_inflow\"\nface = \"z-\"\n"
                       "gas_velocity = [0.0, 0.0, 0.2]\nsolids_velocity = [0.0, 0.0, 0.05]\n"
                       "solids_fraction = 0.3\n"
                       "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n");
}
const std::vector<std::string> stretched_z = {"grid.z.ratio=3.0"};

// An owned fluid cell whose + neighbour along z is fluid too.
int cell_below_fluid(const Case& c) {
  for (int l = 0; l < c.owned_fluid(); ++l)
    if (c.fluid(c.layout().neighbour(l, parallel::top))) return l;
  return -1;
}

// ε_s distinct in every cell (0.1 … 0.5), ε_g = 1 − ε_s.
void distinct_fractions(Case& c) {
  for (int l = 0; l < c.local_count(); ++l)
    c.state.solids_fraction[static_cast<std::size_t>(l)] = 0.3 + 0.2 * wiggle(c.centre(l));
  Case::complete_gas_fraction(c.state);
}

// Both signs of u on interior faces (and some exact zeros), the same on every rank.
void mixed_velocities(Case& c) {
  for (int d = 0; d < 3; ++d)
    for (int l = 0; l < c.local_count(); ++l) {
      const double w = wiggle(c.face_position(l, d), 1.0 + d);
      const double u = std::abs(w) < 0.1 ? 0.0 : (w > 0 ? 0.1 : -0.1);
      c.state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = u;
      c.state.gas_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = -u;
    }
}

TEST(FaceFractions, SolidsCarryTheUpwindFractionForBothSigns) {
  Case c(fed_column(), stretched_z);
  distinct_fractions(c);
  mixed_velocities(c);
  int positive = 0, negative = 0;
  for (int l = 0; l < c.owned_fluid(); ++l)
    for (int d = 0; d < 3; ++d) {
      const int n = c.layout().neighbour(l, 2 * d + 1);
      if (!c.fluid(n)) continue;
      const double u = c.state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)];
      const int upwind = u >= 0.0 ? l : n;
      (u > 0 ? positive : negative) += u != 0.0;
      // A copy of a cell's value: exact.
      EXPECT_EQ(solver::carried_fraction(c.disc, c.state, solids, l, d),
                c.state.solids_fraction[static_cast<std::size_t>(upwind)])
          << "cell " << l << " d " << d << " u " << u;
      // The gas carries its momentum face fraction.
      EXPECT_EQ(solver::carried_fraction(c.disc, c.state, gas, l, d),
                solver::face_fraction(c.disc, c.state, gas, l, d));
    }
  EXPECT_GT(positive, 0);
  EXPECT_GT(negative, 0);
}

TEST(FaceFractions, FaceFractionIsLinearBetweenCentresOnAStretchedGrid) {
  Case c(fed_column(), stretched_z);
  // A linear field in z (periodic in x and y): the width-weighted mean of the two centres is
  // the field at the face.
  auto field = [](const std::array<double, 3>& x) { return 0.1 + 5.0 * x[2]; };
  for (int l = 0; l < c.local_count(); ++l) c.state.solids_fraction[static_cast<std::size_t>(l)] = field(c.centre(l));
  Case::complete_gas_fraction(c.state);
  mixed_velocities(c);  // the interior face value must not depend on the flow direction
  int checked = 0;
  for (int l = 0; l < c.owned_fluid(); ++l) {
    const int n = c.layout().neighbour(l, parallel::top);
    if (!c.fluid(n)) continue;
    const double exact = field(c.face_position(l, 2));
    // Round-off of a weighted mean of O(0.3) values.
    EXPECT_NEAR(solver::face_fraction(c.disc, c.state, solids, l, 2), exact, 1e-14) << "cell " << l;
    EXPECT_NEAR(solver::face_fraction(c.disc, c.state, gas, l, 2), 1.0 - exact, 1e-14);
    ++checked;
  }
  EXPECT_GT(checked, 0);
  // The stretched grid makes the mean of the two centres wrong: the test would see it.
  const int l = cell_below_fluid(c), n = c.layout().neighbour(l, parallel::top);
  ASSERT_TRUE(l >= 0 && c.fluid(n));
  const double plain_mean = 0.5 * (c.state.solids_fraction[static_cast<std::size_t>(l)] + c.state.solids_fraction[static_cast<std::size_t>(n)]);
  EXPECT_GT(std::abs(plain_mean - field(c.face_position(l, 2))), 1e-4);
}

TEST(FaceFractions, BoundaryFacesTakeWhatFlowsThroughThem) {
  Case c(fed_column(), stretched_z);
  for (int l = 0; l < c.local_count(); ++l) {
    const auto k = c.layout().index3(l)[2];
    // Inflow cells carry the inflow's ε_s (as FlowSolver::apply_boundary_values sets them),
    // outlet cells a distinct value, fluid cells 0.5.
    c.state.solids_fraction[static_cast<std::size_t>(l)] = k < 0 ? 0.3 : (k >= 6 ? 0.05 : 0.5);
  }
  Case::complete_gas_fraction(c.state);
  int inflow = 0, outflow = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    const auto k = c.layout().index3(l)[2];
    const auto i = static_cast<std::size_t>(l);
    const int n = c.layout().neighbour(l, parallel::top);
    if (k == -1 && c.fluid(n)) {
      // The feed: both phases flow in, each brings the inflow's own fraction.
      c.state.gas_velocity[2][i] = 0.2;
      c.state.solids_velocity[2][i] = 0.05;
      EXPECT_EQ(solver::face_fraction(c.disc, c.state, solids, l, 2), 0.3);
      EXPECT_EQ(solver::face_fraction(c.disc, c.state, gas, l, 2), 0.7);
      EXPECT_EQ(solver::carried_fraction(c.disc, c.state, solids, l, 2), 0.3);
      ++inflow;
    }
    if (k == 5 && c.fluid(l)) {
      // The outlet face, owned by the top fluid cell: going out the cell's, coming back in the
      // outlet cell's, at rest the fluid cell's.
      c.state.solids_velocity[2][i] = 0.1;
      EXPECT_EQ(solver::face_fraction(c.disc, c.state, solids, l, 2), 0.5);
      c.state.solids_velocity[2][i] = -0.1;
      EXPECT_EQ(solver::face_fraction(c.disc, c.state, solids, l, 2), 0.05);
      EXPECT_EQ(solver::carried_fraction(c.disc, c.state, solids, l, 2), 0.05);
      c.state.solids_velocity[2][i] = 0.0;
      EXPECT_EQ(solver::face_fraction(c.disc, c.state, solids, l, 2), 0.5);
      ++outflow;
    }
  }
  EXPECT_GT(c.sum(inflow), 0.0);
  EXPECT_GT(c.sum(outflow), 0.0);
}

TEST(FaceFractions, CarryFractionsStoresCarriedFractionInEveryCell) {
  Case c(fed_column(), stretched_z);
  distinct_fractions(c);
  mixed_velocities(c);
  solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
  auto expect_same = [&](const char* when) {
    for (const solver::Phase phase : {gas, solids})
      for (int d = 0; d < 3; ++d)
        for (int l = 0; l < c.local_count(); ++l)
          ASSERT_EQ(carried(phase, d)[static_cast<std::size_t>(l)],
                    solver::carried_fraction(c.disc, c.state, phase, l, d))
              << when << ": phase " << phase << " d " << d << " cell " << l;
  };
  solver::carry_all_fractions(c.disc, c.state, carried);
  expect_same("carry_all_fractions");
  // Reverse the solids along z: carry_fractions(solids, z) refreshes that direction.
  for (auto& u : c.state.solids_velocity[2]) u = -u;
  solver::carry_fractions(c.disc, c.state, solids, 2, carried);
  expect_same("after reversing w_s");
}

TEST(FaceFractions, SolidsMomentumIsSolvedWhereEitherSideHoldsSolids) {
  Case c(fed_column(), stretched_z);
  const int l = cell_below_fluid(c), n = c.layout().neighbour(l, parallel::top);
  ASSERT_TRUE(l >= 0 && c.fluid(n));
  auto set = [&](double below, double above) {
    c.state.solids_fraction[static_cast<std::size_t>(l)] = below;
    c.state.solids_fraction[static_cast<std::size_t>(n)] = above;
  };
  set(0.0, 0.0);
  EXPECT_FALSE(solver::solids_present(c.disc, c.state, l, 2));
  set(0.5 * solver::solids_threshold, 0.9 * solver::solids_threshold);
  EXPECT_FALSE(solver::solids_present(c.disc, c.state, l, 2));
  set(0.0, 2.0 * solver::solids_threshold);
  EXPECT_TRUE(solver::solids_present(c.disc, c.state, l, 2));
  set(2.0 * solver::solids_threshold, 0.0);
  EXPECT_TRUE(solver::solids_present(c.disc, c.state, l, 2));
}

}  // namespace
}  // namespace bagnold::tests
