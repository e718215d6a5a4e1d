// SKT in transport form (skt_granular_energy.hpp): Garzó–Dufty's conductivity against MFIX's
// GT_PDE_GD written out in its own arrangement with c* = 0 and no gas, and the stresses at a
// transported Θ against the report's Eqs. 1, 2 and the bulk factor.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "models/stress/garzo_dufty.hpp"
#include "models/stress/skt.hpp"
#include "tests/unit/models/gd_reference.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace {

using std::numbers::pi;

// MFIX's GT_PDE_GD conductivity Kth_s = kappa0 * kappa_star, SWITCH off, c_star = 0.
double mfix_gd_conductivity(double ep_s, double chi, double c_e, double ro_s, double d_p, double theta) {
  const double m_p = (pi / 6) * d_p * d_p * d_p * ro_s;
  const double press_star = 1 + 2 * (1 + c_e) * ep_s * chi;
  (void)press_star;  // enters κ_k* only through c*
  const double zeta0_star = (5.0 / 12) * chi * (1 - c_e * c_e);
  const double eta0 = 5 * m_p * std::sqrt(theta / pi) / (16 * d_p * d_p);
  const double kappa0 = (15.0 / 4) * eta0;
  const double nu_kappa_star = (chi / 3) * (1 + c_e) * (1 + (33.0 / 16) * (1 - c_e));
  const double kappa_k_star = (2.0 / 3) * (1 + (3.0 / 5) * ep_s * chi * (1 + c_e) * (1 + c_e) * (2 * c_e - 1)) /
                              (nu_kappa_star - 2 * zeta0_star);
  const double kappa_star = kappa_k_star * (1 + (6.0 / 5) * ep_s * chi * (1 + c_e)) +
                            (256.0 / 25) * (ep_s * ep_s / pi) * chi * (1 + c_e);
  return kappa0 * kappa_star;
}

TEST(SktTransport, ConductivityIsGarzoDuftysAsMfixWritesIt) {
  for (const double e : {0.5, 0.8, 0.95})
    for (const double phi : {0.01, 0.2, 0.45})
      for (const double g0 : {1.0, 3.0, 20.0}) {
        const double rho = 2500, d = 1e-3, theta = 0.04;
        const double ours = rho * d * models::garzo_dufty::conductivity_factor(phi, g0, e) * std::sqrt(theta);
        const double mfix = mfix_gd_conductivity(phi, g0, e, rho, d, theta);
        EXPECT_NEAR(ours, mfix, 1e-13 * mfix) << "e " << e << " φ " << phi << " g0 " << g0;
      }
}

TEST(SktTransport, StressesAtTheTransportedTemperature) {
  const auto model = make_model("skt", {{"granular_energy", std::string("transport")}});
  ASSERT_NE(model->granular_energy(), nullptr);
  Material m;
  const std::vector<double> phi = {0.1, 0.4}, rate = {5.0, 5.0}, divergence = {0.0, 0.0},
                            theta = {0.01, 0.003}, beta = {0.0, 0.0};
  std::vector<double> p(2), dp(2), mu(2), lambda(2), t(2);
  models::SolidsStress out{p, dp, mu, lambda, t};
  model->evaluate(m, {phi, rate, divergence, theta, beta}, out);
  for (std::size_t i = 0; i < 2; ++i) {
    const double g0 = gd_reference::carnahan_starling(phi[i]);  // below the jamming cap
    const double e = m.restitution;
    EXPECT_NEAR(p[i], m.density * phi[i] * (1 + 2 * (1 + e) * phi[i] * g0) * theta[i], 1e-12 * p[i]);  // Eq. 1, 4
    EXPECT_NEAR(mu[i], m.density * m.diameter * models::garzo_dufty::shear_factor(phi[i], g0, e) * std::sqrt(theta[i]),
                1e-12 * mu[i]);  // Eq. 2
    EXPECT_NEAR(lambda[i], m.density * m.diameter * models::garzo_dufty::bulk_factor(phi[i], g0, e) * std::sqrt(theta[i]),
                1e-12 * lambda[i]);
    EXPECT_EQ(t[i], theta[i]);
  }
}

}  // namespace
}  // namespace bagnold::tests
