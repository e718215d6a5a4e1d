// Standard kinetic theory (App. B Eqs. 1–18): Garzó–Dufty steady shear, radial-distribution
// choices, derivatives and the dense limit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "models/stress/friction_table.hpp"
#include "models/stress/rheometer.hpp"
#include "models/stress/skt.hpp"
#include "tests/unit/models/gd_reference.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {

namespace {
// The formulas as printed: no viscosity regularization, no dilute (ideal-gas) treatment.
const models::Coefficients unregularized{
    {"min_strain_rate", 0.0}, {"max_viscosity", 1e12}, {"dilute_stress", std::string("kinetic")}};
}

TEST(Skt, SteadyShearIsGarzoDuftyEquations15To18) {
  // Eqs. 15–18 with Carnahan–Starling g0 (μ = 0: no effect of friction below the cap); to
  // rounding, 1e-12 relative.
  Material m;
  m.restitution = 0.7;
  m.friction = 0.0;
  const auto model = make_model("skt", unregularized);
  for (const double phi : {1e-3, 0.1, 0.3, 0.49}) {
    const double rate = 3.0, rate_d2 = std::pow(rate * m.diameter, 2);
    const auto gd = gd_reference::steady_shear(phi, m.restitution);
    const auto row = models::shear_rheometer(*model, m, phi, rate);
    EXPECT_NEAR(row.granular_temperature, gd.temperature_factor * rate_d2,
                1e-12 * row.granular_temperature);
    EXPECT_NEAR(row.pressure, gd.pressure_factor * m.density * rate_d2, 1e-12 * row.pressure);
    EXPECT_NEAR(row.shear_stress, gd.shear_factor * m.density * rate_d2, 1e-12 * row.shear_stress);
    EXPECT_NEAR(row.stress_ratio, gd.stress_ratio, 1e-12);
  }
}

TEST(Skt, MktRadialDistributionSharesMktJammingPoint) {
  // With radial_distribution = mkt, SKT's pressure diverges at φ_c(μ) like MKT's g0
  // (p/ρ_s(γ̇d)² = JH/K ~ g0 in the dense limit: exponent −3/2 from Eq. 31).
  const auto model =
      make_model("skt", {{"radial_distribution", std::string("mkt")}, {"jamming_margin", 1e-9}});
  Material m;
  m.friction = 0.5;
  const double phi_c = models::chialvo2012::critical_fraction(0.5);
  const double slope = log_log_slope(1e-5, probe(*model, m, phi_c - 1e-5, 1.0).pressure, 1e-4,
                                     probe(*model, m, phi_c - 1e-4, 1.0).pressure);
  EXPECT_NEAR(slope, -1.5, 2e-3);  // J/K tends to a constant, H ~ g0; subleading terms < 2e-3
}

TEST(Skt, FrictionalYieldIsOffByDefaultAndAddsTheQuasiStaticYieldStressWhenOn) {
  // Above the quasi-static onset, at rest: the report's SKT (default) has no shear stress there
  // (√T = 0), with frictional_yield = on the regularized yield stress η_s P_qs gives the capped
  // viscosity; in a sheared dilute state (no P_qs) the two agree.
  Material m;
  m.friction = 0.3;
  const auto report = make_model("skt");
  const auto frictional = make_model("skt", {{"frictional_yield", std::string("on")}});
  const double packed = models::chialvo2012::critical_fraction(0.3) + 0.01;
  EXPECT_EQ(probe(*report, m, packed, 0.0).shear_viscosity, 0.0);
  EXPECT_DOUBLE_EQ(probe(*frictional, m, packed, 0.0).shear_viscosity, 1e9);  // at rest: the cap
  EXPECT_EQ(probe(*report, m, packed, 0.0).pressure, probe(*frictional, m, packed, 0.0).pressure);
  EXPECT_GT(probe(*report, m, packed, 0.0).pressure, 0.0);
  EXPECT_EQ(probe(*report, m, 0.3, 10.0).shear_viscosity,
            probe(*frictional, m, 0.3, 10.0).shear_viscosity);
}

TEST(Skt, PressureDerivativeMatchesFiniteDifferences) {
  Material m;
  for (const std::string radial : {"carnahan-starling", "torquato", "mkt"}) {
    const auto model = make_model("skt", {{"radial_distribution", radial}});
    for (const double phi : {0.01, 0.2, 0.45, 0.55, 0.6, 0.68}) {
      const double exact = probe(*model, m, phi, 2.0).pressure_derivative;
      const double fd = finite_difference_pressure_derivative(*model, m, phi, 2.0, 1e-7);
      // h = 1e-7: truncation and rounding below 1e-5 relative away from kinks.
      EXPECT_NEAR(exact, fd, 1e-5 * std::abs(fd)) << radial << ", φ = " << phi;
    }
  }
}

TEST(Skt, TemperatureFollowsTheDeviatoricShearRate) {
  // In a 3-D strain field T = (J/K)(γ̇_s d)² with γ̇_s² = γ̇² − ⅔ (tr D)² (models/pointwise.hpp).
  const auto model = make_model("skt");
  Material m;
  const double strain_rate = 5.0, divergence = 3.0;
  const double deviatoric =
      std::sqrt(strain_rate * strain_rate - 2.0 / 3.0 * divergence * divergence);
  const auto compressed = probe(*model, m, 0.3, strain_rate, divergence);
  const auto sheared = probe(*model, m, 0.3, deviatoric, 0.0);
  EXPECT_NEAR(compressed.granular_temperature, sheared.granular_temperature,
              1e-14 * sheared.granular_temperature);
  EXPECT_GT(compressed.bulk_viscosity, 0.0);
}

}  // namespace bagnold::tests
