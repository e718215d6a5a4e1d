// Cohesive steady-shear rheology (App. D Eqs. 7–19): the cohesive regime, App. D's own
// non-cohesive limit, the μ interpolation of its Table I.
#include <gtest/gtest.h>

#include <cmath>

#include "models/stress/rheometer.hpp"
#include "models/stress/steady_shear_cohesive.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace blended = models::blended;

namespace {
Material powder(double bond_number, double friction = 0.1) {
  Material m;
  m.diameter = 1e-3;
  m.density = 2500.0;
  m.stiffness = 1e5;
  m.friction = friction;
  m.bond_number = bond_number;
  return m;
}
}  // namespace

TEST(SteadyShearCohesive, CohesionAddsARateIndependentRegimeBelowCriticalFraction) {
  // App. D Sec. III: below φ_c the inertial regime bifurcates — rate independent at low γ̂
  // (cohesive regime), Bagnold (slope 2) at higher γ̂. μ = 0.1, φ = 0.55 < φ_c = 0.614.
  const auto model = make_model("steady-shear-cohesive");
  const Material cohesive = powder(5e-6), dry = powder(0.0);
  const double low_cohesive = scaled_pressure_slope(*model, cohesive, 0.55, 1e-8, 1e-7);
  const double low_dry = scaled_pressure_slope(*model, dry, 0.55, 1e-8, 1e-7);
  const double higher_cohesive = scaled_pressure_slope(*model, cohesive, 0.55, 3e-3, 6e-3);
  EXPECT_NEAR(low_cohesive, 0.0, 1e-3);  // p_inert/p_coh,1 < 1e-5 at γ̂ ≤ 1e-7
  EXPECT_NEAR(low_dry, 2.0, 1e-3);       // without cohesion: inertial
  EXPECT_GT(higher_cohesive, 1.8);       // past γ̂ ~ √Bo*: inertial again (p_inert ≫ p_coh,1)
  RecordProperty("slope_cohesive_low_rate", std::to_string(low_cohesive));
  RecordProperty("slope_dry_low_rate", std::to_string(low_dry));
  RecordProperty("slope_cohesive_higher_rate", std::to_string(higher_cohesive));
  // In the cohesive regime p is the harmonic blend of Eqs. 11 and 12 (γ̂ → 0), written out:
  const double eps = 1.0, chi = 2.08;
  const double coh_1 = 0.15 * 5e-6 * std::abs(0.55 - 0.45) / (0.614 - 0.55);
  const double coh_2 = 0.008 * std::pow(5e-6, eps / (eps + chi));
  EXPECT_NEAR(scaled_pressure(*model, cohesive, 0.55, 0.0), coh_1 * coh_2 / (coh_1 + coh_2),
              1e-12 * coh_1);
}

TEST(SteadyShearCohesive, CohesionRaisesTheStressRatioOnlyAtLowShearRate) {
  // App. D Sec. V, Eq. 19: η − η* = α₃ φ Bo* (k/d)/p · 1/(γ̂/(α₄√Bo*) + 1) > 0, fading for
  // γ̂ ≫ α₄√Bo*.
  const auto model =
      make_model("steady-shear-cohesive", {{"min_strain_rate", 0.0}, {"max_viscosity", 1e12}});
  const Material cohesive = powder(5e-5);
  const double slow = rate_for(1e-7, cohesive), fast = rate_for(1e-1, cohesive);
  const auto slow_row = models::shear_rheometer(*model, cohesive, 0.58, slow);
  const double expected_excess = 0.23 * 0.58 * 5e-5 /
                                 (slow_row.pressure * cohesive.diameter / cohesive.stiffness) /
                                 (1e-7 / (0.1 * std::sqrt(5e-5)) + 1.0);
  const double eta_star = slow_row.stress_ratio - expected_excess;
  EXPECT_GT(expected_excess, 0.1);
  EXPECT_NEAR(eta_star, 0.268, 1e-3);  // η* → η_s(0.1) at I, γ̂ → 0
  const auto fast_row = models::shear_rheometer(*model, cohesive, 0.58, fast);
  const auto fast_dry = models::shear_rheometer(*model, powder(0.0), 0.58, fast);
  // At γ̂ = 0.1 the cohesive term is α₄√Bo*/γ̂ ≈ 7e-3 of its low-rate value.
  EXPECT_NEAR(fast_row.stress_ratio, fast_dry.stress_ratio, 0.02 * fast_dry.stress_ratio);
}

TEST(SteadyShearCohesive, NonCohesiveLimitUsesAppendixDTableI) {
  // Bo* = 0 is App. D's own refit: at φ_c(0.1) = 0.614, p d/k = α_int γ̂^{2ε/(ε+χ)} with
  // α_int = 0.15, ε = 1.00, χ = 2.08 (not App. A's 0.099 γ̂^{1/2}).
  const auto model = make_model("steady-shear-cohesive");
  const Material dry = powder(0.0);
  for (const double g : {1e-6, 1e-3})
    EXPECT_NEAR(scaled_pressure(*model, dry, 0.614, g), 0.15 * std::pow(g, 2.0 / 3.08),
                1e-12 * std::pow(g, 2.0 / 3.08));
}

TEST(SteadyShearCohesive, TableIIsInterpolatedInFrictionAndClampedToItsRange) {
  const auto mid = models::steady_shear_cohesive::constants_at(0.2, {});
  EXPECT_DOUBLE_EQ(mid.critical_fraction, 0.5 * (0.614 + 0.596));
  EXPECT_DOUBLE_EQ(mid.quasi_static_exponent, 0.5 * (1.00 + 0.92));
  const auto frictionless = models::steady_shear_cohesive::constants_at(0.0, {});
  EXPECT_DOUBLE_EQ(frictionless.critical_fraction, 0.614);  // clamped to μ = 0.1
}

TEST(SteadyShearCohesive, PressureDerivativeMatchesFiniteDifferences) {
  const auto model = make_model("steady-shear-cohesive");
  for (const double mu : {0.1, 0.5}) {
    const Material m = powder(5e-5, mu);
    for (const double phi : {0.4, 0.5, 0.57, 0.6, 0.63, 0.68}) {
      const double rate = rate_for(1e-4, m);
      const double exact = probe(*model, m, phi, rate).pressure_derivative;
      const double fd = finite_difference_pressure_derivative(*model, m, phi, rate, 1e-7);
      EXPECT_NEAR(exact, fd, 1e-5 * std::abs(fd) + 1e-9) << "μ = " << mu << ", φ = " << phi;
    }
  }
}

}  // namespace bagnold::tests
