// Lun et al. (1984) in MFIX's LUN_1984 transport form (lun_granular_energy.hpp), and
// mfix-default's stresses at a transported Θ: each coefficient against MFIX's GT_PDE_LUN and
// SOURCE_GRANULAR_ENERGY written out here in their own arrangement, with and without drag.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "models/stress/lun_granular_energy.hpp"
#include "models/stress/mfix_default.hpp"
#include "tests/unit/models/gd_reference.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace {

using std::numbers::pi;

// MFIX's GT_PDE_LUN for one solids phase (SUM_EpsGo = ε_s g0, ALPHA = 1.6, SWITCH = 1).
struct MfixLun {
  double p_s, mu_s, lambda_mfix, kth_s, dissipation_lhs, slip_rhs;
};
MfixLun mfix_gt_pde_lun(const Material& m, double ep_s, double theta, double f_gs, double mu_g,
                        double vslip) {
  const double eta = (1 + m.restitution) / 2, ro_s = m.density, d_p = m.diameter;
  const double g_0 = gd_reference::carnahan_starling(ep_s);
  const double sum_eps_go = ep_s * g_0, rop_s = ro_s * ep_s;
  MfixLun r{};
  r.p_s = rop_s * (1 + 4 * eta * sum_eps_go) * theta;
  double mu_s_v = 5 * std::sqrt(pi * theta) * d_p * ro_s / 96;
  const double mu_b_v = 256 * mu_s_v * ep_s * sum_eps_go / (5 * pi);
  const double mu_star = ro_s * ep_s * g_0 * theta * mu_s_v /
                         (ro_s * sum_eps_go * theta + 2 * f_gs * mu_s_v / (ro_s * ep_s));
  mu_s_v = ((2 + 1.6) / 3) * ((mu_star / (eta * (2 - eta) * g_0)) * (1 + 1.6 * eta * sum_eps_go) *
                                  (1 + 1.6 * eta * (3 * eta - 2) * sum_eps_go) +
                              0.6 * mu_b_v * eta);
  r.mu_s = mu_s_v;
  r.lambda_mfix = eta * mu_b_v - 2 * mu_s_v / 3;
  const double kth = 75 * ro_s * d_p * std::sqrt(pi * theta) / (48 * eta * (41 - 33 * eta));
  const double kth_star = ro_s * ep_s * g_0 * theta * kth /
                          (ro_s * sum_eps_go * theta + 1.2 * f_gs * kth / (ro_s * ep_s));
  r.kth_s = kth_star / g_0 *
            ((1 + (12.0 / 5) * eta * sum_eps_go) * (1 + (12.0 / 5) * eta * eta * (4 * eta - 3) * sum_eps_go) +
             (64 / (25 * pi)) * (41 - 33 * eta) * std::pow(eta * sum_eps_go, 2));
  // SOURCE_GRANULAR_ENERGY: S4_lhs (per Θ) and S7_rhs.
  r.dissipation_lhs = (48 / std::sqrt(pi)) * eta * (1 - eta) * rop_s * sum_eps_go * std::sqrt(theta) / d_p;
  r.slip_rhs = 81 * ep_s * std::pow(mu_g * vslip, 2) /
               (g_0 * std::pow(d_p, 3) * ro_s * std::sqrt(pi) * std::sqrt(theta + 1e-15));
  return r;
}

TEST(Lun1984Transport, EveryTermIsMfixsGtPdeLun) {
  Material m;
  m.restitution = 0.9;
  m.diameter = 2.5e-4;
  m.density = 2000;
  int states = 0;
  for (const double phi : {0.01, 0.1, 0.3, 0.5, 0.57})
    for (const double theta : {1e-6, 1e-3, 0.1})
      for (const double beta : {0.0, 1e3, 1e5}) {
        const double mu_g = 1.8e-5, slip = 0.3;
        const auto t = models::lun1984::point_terms(phi, theta, beta, slip, mu_g, m);
        const auto r = mfix_gt_pde_lun(m, phi, theta, beta, mu_g, slip);
        const double tol = 1e-12;
        EXPECT_NEAR(t.pressure_per_temperature.value * theta, r.p_s, tol * r.p_s);
        EXPECT_NEAR(t.shear_viscosity, r.mu_s, tol * r.mu_s);
        EXPECT_NEAR(t.bulk_viscosity, r.lambda_mfix + 2 * r.mu_s / 3, tol * r.mu_s);
        EXPECT_NEAR(t.conductivity, r.kth_s, tol * r.kth_s);
        EXPECT_NEAR(t.dissipation_coefficient * std::sqrt(theta), r.dissipation_lhs, tol * r.dissipation_lhs);
        EXPECT_NEAR(t.slip_production, r.slip_rhs, tol * r.slip_rhs);
        ++states;
      }
  EXPECT_EQ(states, 45);
}

TEST(Lun1984Transport, NoTemperatureNoViscosityNoConductivity) {
  Material m;
  const auto t = models::lun1984::point_terms(0.3, 0.0, 1e3, 0.0, 0.0, m);
  EXPECT_EQ(t.shear_viscosity, 0.0);
  EXPECT_EQ(t.conductivity, 0.0);
  EXPECT_GT(t.pressure_per_temperature.value, 0.0);
  EXPECT_GT(t.dissipation_coefficient, 0.0);
}

TEST(MfixDefaultTransport, StressesAtTheTransportedTemperature) {
  const auto model = make_model("mfix-default", {{"kinetic_theory", std::string("lun")},
                                                 {"granular_energy", std::string("transport")},
                                                 {"packed_gas_fraction", 0.42}});
  ASSERT_NE(model->granular_energy(), nullptr);
  Material m;
  const std::vector<double> phi = {0.2, 0.55, 0.6}, rate = {10.0, 10.0, 10.0}, divergence = {0.0, 1.0, 0.0},
                            theta = {0.01, 0.02, 0.03}, beta = {1e3, 1e3, 1e3};
  std::vector<double> p(3), dp(3), mu(3), lambda(3), t(3);
  models::SolidsStress out{p, dp, mu, lambda, t};
  models::SolidsState in{phi, rate, divergence, theta, beta};
  model->evaluate(m, in, out);
  for (std::size_t i = 0; i < 2; ++i) {  // viscous regime: the kinetic stresses at Θ
    const auto k = models::lun1984::point_terms(phi[i], theta[i], beta[i], 0.0, 0.0, m);
    EXPECT_DOUBLE_EQ(p[i], k.pressure_per_temperature.value * theta[i]);
    EXPECT_DOUBLE_EQ(dp[i], k.pressure_per_temperature.slope * theta[i]);
    EXPECT_DOUBLE_EQ(mu[i], k.shear_viscosity);
    EXPECT_DOUBLE_EQ(lambda[i], k.bulk_viscosity);
    EXPECT_DOUBLE_EQ(t[i], theta[i]);
  }
  // Plastic regime (φ > 1 − ε_g* = 0.58): Θ held at 0, P* = 10²⁴ (φ − 0.58)¹⁰ and Schaeffer's
  // P* sin 30°/γ̇, capped at 100 Pa s, with MFIX's zero second viscosity (a bulk ⅔ μ).
  EXPECT_EQ(t[2], 0.0);
  EXPECT_NEAR(p[2], 1e24 * std::pow(0.02, 10), 1e-9 * p[2]);
  EXPECT_DOUBLE_EQ(mu[2], 100.0);
  EXPECT_DOUBLE_EQ(lambda[2], 2.0 / 3.0 * 100.0);
}

TEST(MfixDefaultTransport, OnlyLunsTheoryIsTransported) {
  EXPECT_THROW(make_model("mfix-default", {{"granular_energy", std::string("transport")},
                                           {"packed_gas_fraction", 0.42}}),
               std::invalid_argument);
}

// slip_temperature_floor is the Θ_floor of √(Θ + Θ_floor) in the slip production: at Θ = 0 the
// production scales as Θ_floor^(-1/2), and at a Θ far above it the floor does not show.
TEST(MfixDefaultTransport, SlipTemperatureFloorActsOnlyNearZeroTemperature) {
  Material m;
  auto slip_production = [&](double floor, double theta) {
    const auto model = make_model("mfix-default", {{"kinetic_theory", std::string("lun")},
                                                   {"granular_energy", std::string("transport")},
                                                   {"packed_gas_fraction", 0.42},
                                                   {"slip_temperature_floor", floor}});
    const std::vector<double> phi = {0.3}, temperature = {theta}, beta = {2e4}, slip = {0.2};
    std::vector<double> p(1), mu(1), lambda(1), kappa(1), c(1), s(1), held(1);
    models::KineticTerms out{p, mu, lambda, kappa, c, s, held};
    model->granular_energy()->evaluate(m, {phi, temperature, beta, slip, 1.8e-5}, out);
    return s[0];
  };
  EXPECT_NEAR(slip_production(1e-16, 0.0) / slip_production(1e-15, 0.0), std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(slip_production(1e-16, 1e-3) / slip_production(1e-15, 1e-3), 1.0, 1e-11);
  EXPECT_DOUBLE_EQ(slip_production(1e-15, 1e-3),
                   models::lun1984::point_terms(0.3, 1e-3, 2e4, 0.2, 1.8e-5, m).slip_production);
}

}  // namespace
}  // namespace bagnold::tests
