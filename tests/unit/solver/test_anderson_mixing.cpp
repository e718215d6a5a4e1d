// Anderson mixing of the outer iteration (anderson_mixing.hpp) on maps whose fixed point is
// known: a linear contraction converges in a few mixed iterations where Picard needs dozens, the
// mixture keeps every value the images share (fixed boundary values, ε_g + ε_s = 1), and where
// a mixture would take ε_s above every image's, ε_s is clipped to the images' largest. On 1 and
// 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/simple/anderson_mixing.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

// G(x): velocities contract towards 1 + 0.1 l by 0.5 per iteration, the pressure towards 100 + l
// by 0.9; ε_s and ε_g are left as they are; a "boundary" value (the last owned cell's u_g,z) is
// held at 7.
void apply_map(const Case& c, run::FlowState& s) {
  const int owned = c.layout().owned_count();
  for (int l = 0; l < owned; ++l) {
    const auto i = static_cast<std::size_t>(l);
    const double natural = static_cast<double>(c.layout().natural(l) % 97);
    for (auto* v : {&s.gas_velocity, &s.solids_velocity})
      for (auto& component : *v) component[i] = 0.5 * component[i] + 0.5 * (1.0 + 0.1 * natural);
    s.gas_pressure[i] = 0.9 * s.gas_pressure[i] + 0.1 * (100.0 + natural);
  }
  s.gas_velocity[2][static_cast<std::size_t>(owned - 1)] = 7.0;
}

double error(const Case& c, const run::FlowState& s) {
  double worst = 0.0;
  for (int l = 0; l < c.layout().owned_count() - 1; ++l) {
    const auto i = static_cast<std::size_t>(l);
    const double natural = static_cast<double>(c.layout().natural(l) % 97);
    worst = std::max({worst, std::abs(s.solids_velocity[0][i] - (1.0 + 0.1 * natural)),
                      std::abs(s.gas_pressure[i] - (100.0 + natural)) / 100.0});
  }
  return c.max(worst);
}

run::FlowState start(const Case& c) {
  run::FlowState s(c.local_count());
  for (std::size_t i = 0; i < s.solids_fraction.size(); ++i) {
    s.solids_fraction[i] = 0.3;
    s.gas_fraction[i] = 0.7;
  }
  return s;
}

TEST(AndersonMixing, ALinearContractionConvergesInAFewMixedIterations) {
  const Case c(unit_deck(4, 2, 6, "", 0.0, gas_only()));
  run::FlowState picard = start(c), mixed = start(c);
  solver::AndersonMixing anderson(c.layout(), 3);
  anderson.start_step(mixed);
  for (int k = 0; k < 6; ++k) {
    apply_map(c, picard);
    anderson.remember_input(mixed);
    apply_map(c, mixed);
    EXPECT_EQ(anderson.mix(mixed, 1.0), 0);
  }
  // Two distinct contraction rates: exact after depth 2 (round-off), Picard at 0.9^6 = 0.53.
  EXPECT_LT(error(c, mixed), 1e-9);
  EXPECT_GT(error(c, picard), 0.3);
  // What every image shares stays: the held value, the fractions and their sum.
  const int owned = c.layout().owned_count();
  EXPECT_EQ(mixed.gas_velocity[2][static_cast<std::size_t>(owned - 1)], 7.0);
  for (int l = 0; l < owned; ++l) {
    const auto i = static_cast<std::size_t>(l);
    EXPECT_NEAR(mixed.solids_fraction[i], 0.3, 1e-15);
    EXPECT_NEAR(mixed.solids_fraction[i] + mixed.gas_fraction[i], 1.0, 1e-15);
  }
}

TEST(AndersonMixing, AMixtureAboveEveryImagesSolidsFractionIsClipped) {
  // ε_s rises uniformly towards 0.64 by half the gap per iteration: the mixture would reach 0.64
  // at once, above what any image holds; it is clipped to the images' largest in every cell.
  const Case c(unit_deck(2, 2, 4, "", 0.0, gas_only()));
  run::FlowState s = start(c);
  solver::AndersonMixing anderson(c.layout(), 3);
  anderson.start_step(s);
  auto rise = [&] {
    for (int l = 0; l < c.layout().owned_count(); ++l) {
      const auto i = static_cast<std::size_t>(l);
      s.solids_fraction[i] = 0.5 * s.solids_fraction[i] + 0.32;
      s.gas_fraction[i] = 1.0 - s.solids_fraction[i];
    }
  };
  anderson.remember_input(s);
  rise();
  EXPECT_EQ(anderson.mix(s, 1.0), 0);  // no history yet: Picard's image
  EXPECT_NEAR(s.solids_fraction[0], 0.47, 1e-15);
  anderson.remember_input(s);
  rise();
  EXPECT_EQ(anderson.mix(s, 1.0), c.layout().owned_count());
  for (int l = 0; l < c.layout().owned_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    EXPECT_NEAR(s.solids_fraction[i], 0.555, 1e-15);
    EXPECT_NEAR(s.gas_fraction[i], 0.445, 1e-15);
  }
}

}  // namespace
}  // namespace bagnold::tests
