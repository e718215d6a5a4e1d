// MFIX's plastic pressure P* = A (ε_g* − ε_g)^n (models/stress/plastic_pressure.hpp): the
// closed form, its derivative, zero below the packing, and that the two closures using it
// (plastic, mfix-default) give exactly its values in the plastic regime.
#include <gtest/gtest.h>

#include <cmath>

#include "models/stress/plastic_pressure.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
using models::PlasticPressure;

TEST(PlasticPressure, ClosedFormWithMfixConstants) {
  const PlasticPressure p;  // ε_g* = 0.4, A = 1e24 Pa, n = 10
  // φ = 0.61: ε_g* − ε_g = 0.01, P* = 1e24 · 1e-20 = 1e4 Pa, dP*/dε_s = 10 · 1e24 · 1e-18.
  EXPECT_NEAR(p.at(0.61).pressure, 1e4, 1e4 * 1e-12);
  EXPECT_NEAR(p.at(0.61).derivative, 1e7, 1e7 * 1e-12);
  EXPECT_EQ(p.at(0.6).pressure, 0.0);  // at ε_s* = 1 − ε_g*
  EXPECT_EQ(p.at(0.3).pressure, 0.0);
  EXPECT_EQ(p.at(0.3).derivative, 0.0);
}

TEST(PlasticPressure, DerivativeMatchesFiniteDifferences) {
  const PlasticPressure p{.packed_gas_fraction = 0.42, .coefficient = 1e24, .exponent = 10.0};
  for (const double phi : {0.5801, 0.585, 0.6, 0.62}) {
    const double h = 1e-8;
    const double fd = (p.at(phi + h).pressure - p.at(phi - h).pressure) / (2 * h);
    EXPECT_NEAR(p.at(phi).derivative, fd, 1e-6 * fd) << phi;  // h² P''' / P' ≈ 1e-10 here
  }
}

TEST(PlasticPressure, BothClosuresUseIt) {
  const models::Coefficients given{{"packed_gas_fraction", 0.42}, {"plastic_exponent", 8.0}};
  const PlasticPressure p{.packed_gas_fraction = 0.42, .coefficient = 1e24, .exponent = 8.0};
  for (const std::string name : {"plastic", "mfix-default"}) {
    const auto model = make_model(name, given);
    for (const double phi : {0.5801, 0.59, 0.61}) {
      const PointStress s = probe(*model, Material{}, phi, 1.0);
      EXPECT_EQ(s.pressure, p.at(phi).pressure) << name << " at φ = " << phi;
      EXPECT_EQ(s.pressure_derivative, p.at(phi).derivative) << name << " at φ = " << phi;
    }
  }
}

}  // namespace bagnold::tests
