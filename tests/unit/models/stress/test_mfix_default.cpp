// MFIX default (Lun et al. + Schaeffer + plastic pressure): the algebraic energy balance, the
// plastic branch, derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/stress/mfix_default.hpp"
#include "tests/unit/models/gd_reference.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {

namespace {
// Lun et al. dissipation Γ = 12(1 − e²) ρ_s φ² g0 T^{3/2}/(√π d), Carnahan–Starling g0.
double lun_dissipation(const Material& m, double phi, double temperature) {
  return 12 * (1 - m.restitution * m.restitution) * m.density * phi * phi *
         gd_reference::carnahan_starling(phi) * std::pow(temperature, 1.5) /
         (std::sqrt(std::numbers::pi) * m.diameter);
}
}  // namespace

TEST(MfixDefault, AlgebraicTemperatureBalancesProductionAndDissipation) {
  // 0 = −P tr D + μ γ̇_s² + λ (tr D)² − Γ (MFIX's algebraic granular energy); to rounding.
  const auto model = make_model(
      "mfix-default", {{"max_viscosity", 1e12}, {"dilute_stress", std::string("kinetic")}});
  Material m;
  for (const double phi : {0.05, 0.3, 0.55}) {
    for (const double divergence : {0.0, 2.0, -2.0}) {
      const double strain_rate = 10.0;
      const auto s = probe(*model, m, phi, strain_rate, divergence);
      const double shear2 = strain_rate * strain_rate - 2.0 / 3.0 * divergence * divergence;
      const double balance = -s.pressure * divergence + s.shear_viscosity * shear2 +
                             s.bulk_viscosity * divergence * divergence -
                             lun_dissipation(m, phi, s.granular_temperature);
      EXPECT_NEAR(balance, 0.0, 1e-10 * lun_dissipation(m, phi, s.granular_temperature));
      // Lun's pressure: P = ρ_s φ T (1 + 2(1 + e) φ g0).
      EXPECT_NEAR(s.pressure,
                  m.density * phi * s.granular_temperature *
                      (1 + 2 * (1 + m.restitution) * phi * gd_reference::carnahan_starling(phi)),
                  1e-12 * s.pressure);
    }
  }
}

TEST(MfixDefault, PlasticRegimeHasPlasticPressureAndSchaefferViscosity) {
  // ε_g < ε_g* = 0.4: P* = 10²⁴ (φ − 0.6)^10 Pa; τ = P* sin 30° (Schaeffer); T = 0.
  const auto uncapped = make_model("mfix-default", {{"max_viscosity", 1e12}});
  Material m;
  const double rate = 1e4;
  const auto s = probe(*uncapped, m, 0.62, rate);
  const double plastic = 1e24 * std::pow(0.02, 10);
  EXPECT_NEAR(s.pressure, plastic, 1e-12 * plastic);
  EXPECT_NEAR(s.pressure_derivative, 10 * 1e24 * std::pow(0.02, 9), 1e-12 * s.pressure_derivative);
  // γ̇_min = 1e-3 changes τ by (γ̇_min/γ̇)²/2 = 5e-15.
  EXPECT_NEAR(s.shear_viscosity * rate, 0.5 * plastic, 1e-12 * plastic);
  EXPECT_EQ(s.granular_temperature, 0.0);
  // MFIX caps the Schaeffer viscosity at 1000 poise = 100 Pa s by default.
  EXPECT_DOUBLE_EQ(probe(*make_model("mfix-default"), m, 0.65, 1.0).shear_viscosity, 100.0);
}

TEST(MfixDefault, PressureDerivativeMatchesFiniteDifferences) {
  const auto model = make_model("mfix-default");
  Material m;
  for (const double phi : {0.01, 0.2, 0.5, 0.59, 0.61, 0.68}) {
    const double exact = probe(*model, m, phi, 3.0).pressure_derivative;
    const double fd = finite_difference_pressure_derivative(*model, m, phi, 3.0, 1e-7);
    EXPECT_NEAR(exact, fd, 1e-5 * std::abs(fd)) << "φ = " << phi;
  }
}

}  // namespace bagnold::tests
