// The minimal closure of the two-fluid core (models/stress/plastic.hpp): MFIX's plastic pressure
// above the packed fraction, nothing below it, and a viscosity that fades with the solids.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {

TEST(Plastic, PressureIsMfixPlasticPressureAboveThePackedFraction) {
  const auto model = make_model("plastic");
  Material m;
  // ε_g = 0.38 < ε_g* = 0.4: P* = 10²⁴ (0.02)^10 = 1.024e7 Pa, dP*/dε_s = 10 · 10²⁴ (0.02)^9
  // = 5.12e9 Pa.
  const auto s = probe(*model, m, 0.62, 5.0);
  EXPECT_NEAR(s.pressure, 1.024e7, 1e-12 * 1.024e7);
  EXPECT_NEAR(s.pressure_derivative, 5.12e9, 1e-12 * 5.12e9);
  EXPECT_NEAR(s.pressure_derivative, finite_difference_pressure_derivative(*model, m, 0.62, 5.0, 1e-7),
              1e-5 * s.pressure_derivative);
  for (const double phi : {0.0, 0.3, 0.6}) {
    EXPECT_EQ(probe(*model, m, phi, 5.0).pressure, 0.0) << phi;
    EXPECT_EQ(probe(*model, m, phi, 5.0).pressure_derivative, 0.0) << phi;
  }
}

TEST(Plastic, ViscosityIsConstantInTheBedAndFadesWithTheSolids) {
  const auto model = make_model("plastic", {{"viscosity", 2.0}});
  Material m;
  EXPECT_DOUBLE_EQ(probe(*model, m, 0.62, 1.0).shear_viscosity, 2.0);
  EXPECT_DOUBLE_EQ(probe(*model, m, 0.6, 100.0).shear_viscosity, 2.0);
  EXPECT_DOUBLE_EQ(probe(*model, m, 0.3, 1.0).shear_viscosity, 1.0);
  EXPECT_EQ(probe(*model, m, 0.0, 1.0).shear_viscosity, 0.0);
  EXPECT_EQ(probe(*model, m, 0.3, 1.0).bulk_viscosity, 0.0);
  EXPECT_TRUE(std::isnan(probe(*model, m, 0.3, 1.0).granular_temperature));
}

TEST(Plastic, PackedFractionIsADeckKey) {
  // ε_g* = 0.45: the pressure starts at ε_s = 0.55.
  const auto model = make_model("plastic", {{"packed_gas_fraction", 0.45}});
  Material m;
  EXPECT_GT(probe(*model, m, 0.56, 1.0).pressure, 0.0);
  EXPECT_EQ(probe(*model, m, 0.55, 1.0).pressure, 0.0);
}

}  // namespace bagnold::tests
