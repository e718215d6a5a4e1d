#pragma once
// Garzó–Dufty steady simple shear written out independently of models/ (App. B Eqs. 4–18 with
// Carnahan–Starling g0), the reference for the SKT and MKT dilute-limit tests.

#include <cmath>
#include <numbers>

namespace bagnold::tests::gd_reference {

struct SteadyShear {
  double temperature_factor;  // T/(γ̇d)² = J/K, Eq. 15
  double pressure_factor;     // p/(ρ_s(γ̇d)²) = JH/K, Eq. 16
  double shear_factor;        // τ/(ρ_s(γ̇d)²) = sqrt(J³/K), Eq. 17
  double stress_ratio;        // η = sqrt(JK)/H, Eq. 18
};

inline double carnahan_starling(double phi) { return (1 - phi / 2) / std::pow(1 - phi, 3); }

inline SteadyShear steady_shear(double phi, double e, double g0) {
  const double pi = std::numbers::pi;
  const double h = phi * (1 + 2 * (1 + e) * phi * g0);
  const double eta_k = (1 - 0.4 * (1 + e) * (1 - 3 * e) * phi * g0) /
                       ((1 - (1 - e) * (1 - e) / 4 - 5 * (1 - e * e) / 24) * g0);
  const double eta_c = 0.8 * (1 + e) * phi * g0 * eta_k;
  const double eta_b = 384 / (25 * pi) * (1 + e) * phi * phi * g0;
  const double j = 5 * std::sqrt(pi) / 96 * (eta_k + eta_c + eta_b);
  const double k = 12 / std::sqrt(pi) * phi * phi * g0 * (1 - e * e);
  return {j / k, j * h / k, std::sqrt(j * j * j / k), std::sqrt(j * k) / h};
}

inline SteadyShear steady_shear(double phi, double e) {
  return steady_shear(phi, e, carnahan_starling(phi));
}

}  // namespace bagnold::tests::gd_reference
