// Friction-dependent constants: tabulated values, the piecewise-linear rule between them, and
// clamping outside the table (models/stress/friction_table.hpp).
#include <gtest/gtest.h>

#include "models/stress/friction_table.hpp"

namespace bagnold::tests {
namespace chialvo2012 = models::chialvo2012;

TEST(FrictionTable, ReproducesAppendixATablesAtTabulatedFriction) {
  // App. A Table I (φ_c) and Table II (η_s, α_QS), exact: the table stores these numbers.
  const double mu[] = {0.0, 0.1, 0.3, 0.5, 1.0};
  const double phi_c[] = {0.636, 0.613, 0.596, 0.587, 0.581};
  const double eta_s[] = {0.105, 0.268, 0.357, 0.382, 0.405};
  const double alpha_qs[] = {0.095, 0.083, 0.14, 0.20, 0.25};
  for (int i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(chialvo2012::critical_fraction(mu[i]), phi_c[i]);
    EXPECT_DOUBLE_EQ(chialvo2012::yield_stress_ratio(mu[i]), eta_s[i]);
    EXPECT_DOUBLE_EQ(chialvo2012::quasi_static_coefficient(mu[i]), alpha_qs[i]);
  }
}

TEST(FrictionTable, InterpolatesLinearlyBetweenTabulatedFriction) {
  // Midway between μ = 0.1 and 0.3, and a quarter of the way from 0.5 to 1.0.
  EXPECT_DOUBLE_EQ(chialvo2012::critical_fraction(0.2), 0.5 * (0.613 + 0.596));
  EXPECT_NEAR(chialvo2012::yield_stress_ratio(0.625), 0.382 + 0.25 * (0.405 - 0.382), 1e-15);
}

TEST(FrictionTable, ClampsOutsideTheTable) {
  EXPECT_DOUBLE_EQ(chialvo2012::critical_fraction(-0.2), 0.636);
  EXPECT_DOUBLE_EQ(chialvo2012::critical_fraction(3.0), 0.581);
  const models::FrictionTable cohesive{{0.1, 0.3, 0.5}, {0.614, 0.596, 0.587}};
  EXPECT_DOUBLE_EQ(cohesive(0.0), 0.614);  // App. D Table I starts at μ = 0.1
  EXPECT_DOUBLE_EQ(cohesive(1.0), 0.587);
}

TEST(FrictionTable, RejectsMismatchedOrUnsortedTables) {
  EXPECT_THROW((models::FrictionTable{{0.0, 0.1}, {1.0}}), std::invalid_argument);
  EXPECT_THROW((models::FrictionTable{{0.3, 0.1}, {1.0, 2.0}}), std::invalid_argument);
}

}  // namespace bagnold::tests
