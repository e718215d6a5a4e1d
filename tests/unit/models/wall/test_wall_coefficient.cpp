// The series (Robin) form of a wall slip law with the half cell next to the wall.
#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

#include "models/wall/wall_coefficient.hpp"

namespace bagnold::tests {
using models::wall::wall_coefficient;

TEST(WallCoefficient, NoSlipAndFreeSlipLimits) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(wall_coefficient(inf, 3.0, 0.01), 300.0);  // μ_s/δ, the no-slip term
  EXPECT_EQ(wall_coefficient(0.0, 3.0, 0.01), 0.0);           // free slip
  EXPECT_EQ(wall_coefficient(5.0, 0.0, 0.01), 0.0);           // no viscosity, no stress
}

TEST(WallCoefficient, ResistancesAddInSeries) {
  // μ_s/δ = 300, c_slip = 100: 1/c_w = 1/300 + 1/100 → c_w = 75.
  EXPECT_DOUBLE_EQ(wall_coefficient(100.0, 3.0, 0.01), 75.0);
  // Never above the no-slip value, and increasing in c_slip (continuity toward no slip).
  double previous = 0.0;
  for (const double c : {1.0, 10.0, 1e3, 1e6, 1e12}) {
    const double w = wall_coefficient(c, 3.0, 0.01);
    EXPECT_GT(w, previous);
    EXPECT_LE(w, 300.0);
    previous = w;
  }
  EXPECT_NEAR(previous, 300.0, 1e-6);
}

TEST(WallCoefficient, RejectsNonsense) {
  EXPECT_THROW(wall_coefficient(1.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(wall_coefficient(1.0, -1.0, 0.1), std::invalid_argument);
  EXPECT_THROW(wall_coefficient(-1.0, 1.0, 0.1), std::invalid_argument);
}

}  // namespace bagnold::tests
