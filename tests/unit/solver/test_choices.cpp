// The option families that are not models list exactly what is shipped (src/deck/choices.hpp),
// and the solver maps every listed name to its value.
#include <gtest/gtest.h>

#include "solver/convection_limiter.hpp"
#include "solver/simple/momentum_residual.hpp"
#include "src/deck/choices.hpp"

namespace bagnold {
namespace {

TEST(Choices, ConvectionLimitersAreExactlyTheShippedOnes) {
  const std::vector<std::string> shipped = {"upwind", "superbee", "muscl", "van_leer", "minmod"};
  EXPECT_EQ(deck::choice_names(deck::limiter_choices), shipped);
  EXPECT_EQ(solver::limiter_from_name("van_leer"), solver::Limiter::van_leer);
  EXPECT_EQ(solver::limiter_from_name("upwind"), solver::Limiter::upwind);
  EXPECT_THROW(solver::limiter_from_name("quick"), std::invalid_argument);
}

TEST(Choices, ResidualNormalizationsAreExactlyTheShippedOnes) {
  const std::vector<std::string> shipped = {"force", "velocity-scale", "deviation", "mfix"};
  EXPECT_EQ(deck::choice_names(deck::residual_normalization_choices), shipped);
  EXPECT_EQ(solver::residual_normalization_from_name("force"), solver::ResidualNormalization::force);
  EXPECT_EQ(solver::residual_normalization_from_name("deviation"), solver::ResidualNormalization::deviation);
  EXPECT_EQ(solver::residual_normalization_from_name("mfix"), solver::ResidualNormalization::mfix);
  EXPECT_EQ(solver::residual_normalization_from_name("velocity-scale"),
            solver::ResidualNormalization::velocity_scale);
  EXPECT_THROW(solver::residual_normalization_from_name("l2"), std::invalid_argument);
}

TEST(Choices, CouplingsAreExactlyTheShippedOnes) {
  const std::vector<std::string> shipped = {"simplec", "simple"};
  EXPECT_EQ(deck::choice_names(deck::coupling_choices), shipped);
  EXPECT_EQ(deck::choice_value(deck::coupling_choices, "simple", "algorithm"), deck::Coupling::simple);
}

TEST(Choices, ViscosityLinearizationsAreExactlyTheShippedOnes) {
  const std::vector<std::string> shipped = {"picard", "newton"};
  EXPECT_EQ(deck::choice_names(deck::viscosity_linearization_choices), shipped);
  EXPECT_EQ(deck::choice_value(deck::viscosity_linearization_choices, "newton", "viscosity linearization"),
            deck::ViscosityLinearization::newton);
}

TEST(Choices, SolidsMomentumSolvesAreExactlyTheShippedOnes) {
  const std::vector<std::string> shipped = {"segregated", "coupled"};
  EXPECT_EQ(deck::choice_names(deck::solids_momentum_choices), shipped);
  EXPECT_EQ(deck::choice_value(deck::solids_momentum_choices, "coupled", "solids momentum"),
            deck::SolidsMomentum::coupled);
}

// Each limiter ψ(r) is TVD (0 ≤ ψ ≤ min(2r, 2)) and second order (ψ(1) = 1), except upwind.
TEST(Choices, EveryShippedLimiterIsTvdAndSecondOrder) {
  for (const auto& c : deck::limiter_choices) {
    for (double r : {0.1, 0.5, 1.0, 2.0, 5.0}) {
      const double psi = solver::limiter(c.value, r);
      EXPECT_GE(psi, 0.0) << c.name;
      EXPECT_LE(psi, std::min(2.0 * r, 2.0) + 1e-15) << c.name << " r = " << r;
    }
    EXPECT_DOUBLE_EQ(solver::limiter(c.value, 1.0), c.value == solver::Limiter::upwind ? 0.0 : 1.0) << c.name;
    EXPECT_EQ(solver::limiter(c.value, -1.0), 0.0) << c.name;
  }
}

}  // namespace
}  // namespace bagnold
