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
  const auto model = make_model("mfix-default", {{"max_viscosity", 1e12},
                                                 {"dilute_stress", std::string("kinetic")},
                                                 {"kinetic_theory", std::string("lun")}});
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

TEST(MfixDefault, SyamlalAlgebraicTemperatureIsMfixsGtAlgebraic) {
  // MFIX's GT_ALGEBRAIC (calc_mu_s.f) written out as MFIX does: K_1..K_4, the quadratic
  // aq x² + bq x + cq = 0 in x = ε_s √Θ with aq = K_4 ε_s, bq = K_1 ε_s tr D,
  // cq = −(K_2 (tr D)² + 2 K_3 D:D), x = (−bq + √(bq² − 4 aq cq))/(2 K_4); P = K_1 x²,
  // μ = K_3 x, MFIX's second viscosity K_2 x (our bulk viscosity is K_2 x + ⅔ μ), Θ = x²/ε_s².
  const auto model = make_model("mfix-default", {{"max_viscosity", 1e12},
                                                 {"dilute_stress", std::string("kinetic")}});
  Material m;
  m.restitution = 0.8;
  const double e = m.restitution, d = m.diameter, rho = m.density;
  const double sqrt_pi = std::sqrt(std::numbers::pi);
  int cases = 0;
  for (const double phi : {0.01, 0.2, 0.45, 0.579}) {
    for (const double divergence : {0.0, 1.5, -1.5}) {
      for (const double strain_rate : {3.0, 20.0}) {  // γ̇² ≥ ⅔ (tr D)²: a real D
        const double g0 = gd_reference::carnahan_starling(phi);
        const double k1 = 2 * (1 + e) * rho * g0;
        const double k3 = 0.5 * d * rho *
                          ((sqrt_pi / (3 * (3 - e))) *
                               (0.5 * (3 * e + 1) + 0.4 * (1 + e) * (3 * e - 1) * phi * g0) +
                           8 * phi * g0 * (1 + e) / (5 * sqrt_pi));
        const double k2 = 4 * d * rho * (1 + e) * phi * g0 / (3 * sqrt_pi) - 2.0 / 3.0 * k3;
        const double k4 = 12 * (1 - e * e) * rho * g0 / (d * sqrt_pi);
        const double d_double_dot_d = 0.5 * strain_rate * strain_rate;  // γ̇ = √(2 D:D)
        const double aq = k4 * phi, bq = k1 * phi * divergence,
                     cq = -(k2 * divergence * divergence + 2 * k3 * d_double_dot_d);
        const double x = (-bq + std::sqrt(bq * bq - 4 * aq * cq)) / (2 * k4);
        const auto s = probe(*model, m, phi, strain_rate, divergence);
        const double tolerance = 1e-11;
        EXPECT_NEAR(s.granular_temperature, x * x / (phi * phi),
                    tolerance * x * x / (phi * phi)) << phi << " " << divergence;
        EXPECT_NEAR(s.pressure, k1 * x * x, tolerance * k1 * x * x);
        EXPECT_NEAR(s.shear_viscosity, k3 * x, tolerance * k3 * x);
        EXPECT_NEAR(s.bulk_viscosity, k2 * x + 2.0 / 3.0 * k3 * x, tolerance * k3 * x);
        ++cases;
      }
    }
  }
  EXPECT_EQ(cases, 24);
  // The streaming pressure is what separates the two theories' P/Θ: ρ_s φ, at any state.
  const auto lun = make_model("mfix-default", {{"kinetic_theory", std::string("lun")}});
  const auto a = probe(*model, m, 0.3, 5.0), b = probe(*lun, m, 0.3, 5.0);
  EXPECT_NEAR(b.pressure / b.granular_temperature - a.pressure / a.granular_temperature,
              rho * 0.3, 1e-9 * rho);
}

TEST(MfixDefault, PlasticRegimeHasPlasticPressureAndSchaefferViscosity) {
  // ε_g < ε_g* = 0.4: P* = 10²⁴ (φ − 0.6)^10 Pa; τ = P* sin 30° (Schaeffer); T = 0; no second
  // viscosity.
  const auto uncapped = make_model("mfix-default", {{"max_viscosity", 1e12}});
  Material m;
  const double rate = 1e4;
  const auto s = probe(*uncapped, m, 0.62, rate);
  const double plastic = 1e24 * std::pow(0.02, 10);
  EXPECT_NEAR(s.pressure, plastic, 1e-12 * plastic);
  EXPECT_NEAR(s.pressure_derivative, 10 * 1e24 * std::pow(0.02, 9), 1e-12 * s.pressure_derivative);
  // γ̇_min is 0 by default: τ = μ γ̇ exactly.
  EXPECT_NEAR(s.shear_viscosity * rate, 0.5 * plastic, 1e-12 * plastic);
  EXPECT_EQ(s.granular_temperature, 0.0);
  // MFIX's Schaeffer stress is 2 μ D (LAMBDA_s_p = 0): a bulk viscosity of ⅔ μ.
  EXPECT_NEAR(s.bulk_viscosity, 2.0 / 3.0 * s.shear_viscosity, 1e-15 * s.shear_viscosity);
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
