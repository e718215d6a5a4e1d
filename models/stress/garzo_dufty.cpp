#include "models/stress/garzo_dufty.hpp"

#include <numbers>

#include "models/dual.hpp"

namespace bagnold::models::garzo_dufty {

using std::numbers::pi;

template <class Real>
Real pressure_factor(Real phi, Real g0, double restitution) {
  return phi * (1.0 + 2.0 * (1.0 + restitution) * phi * g0);
}

template <class Real>
Real scaled_viscosity(Real phi, Real g0, double restitution) {
  const double e = restitution;
  // Eq. 8: kinetic part.
  const double denominator = 1.0 - 0.25 * (1.0 - e) * (1.0 - e) - (5.0 / 24.0) * (1.0 - e * e);
  const Real kinetic = (1.0 - 0.4 * (1.0 + e) * (1.0 - 3.0 * e) * phi * g0) / (denominator * g0);
  // Eq. 9: collisional transfer.
  const Real collisional = 0.8 * (1.0 + e) * phi * g0 * kinetic;
  // Eq. 10: bulk-viscosity contribution.
  const Real bulk = (384.0 / (25.0 * pi)) * (1.0 + e) * phi * phi * g0;
  return kinetic + collisional + bulk;
}

template <class Real>
Real shear_factor(Real phi, Real g0, double restitution) {
  return (5.0 * std::sqrt(pi) / 96.0) * scaled_viscosity(phi, g0, restitution);
}

template <class Real>
Real dissipation_factor(Real phi, Real g0, double restitution) {
  return (12.0 / std::sqrt(pi)) * phi * phi * g0 * (1.0 - restitution * restitution);
}

template <class Real>
Real bulk_factor(Real phi, Real g0, double restitution) {
  return (4.0 / (3.0 * std::sqrt(pi))) * (1.0 + restitution) * phi * phi * g0;
}

template <class Real>
Real conductivity_factor(Real phi, Real g0, double restitution) {
  const double e = restitution;
  const Real cooling = (5.0 / 12.0) * g0 * (1.0 - e * e);                               // ζ0*
  const Real collision_frequency = (g0 / 3.0) * (1.0 + e) * (1.0 + (33.0 / 16.0) * (1.0 - e));  // ν_κ*
  const Real kinetic = (2.0 / 3.0) * (1.0 + 0.6 * phi * g0 * (1.0 + e) * (1.0 + e) * (2.0 * e - 1.0)) /
                       (collision_frequency - 2.0 * cooling);                          // κ_k*
  const Real scaled = kinetic * (1.0 + 1.2 * phi * g0 * (1.0 + e)) +
                      (256.0 / 25.0) * (phi * phi / pi) * g0 * (1.0 + e);              // κ*
  return (15.0 / 4.0) * (5.0 * std::sqrt(pi) / 96.0) * scaled;
}

#define BAGNOLD_INSTANTIATE(Real)                       \
  template Real pressure_factor(Real, Real, double);    \
  template Real scaled_viscosity(Real, Real, double);   \
  template Real shear_factor(Real, Real, double);       \
  template Real dissipation_factor(Real, Real, double); \
  template Real bulk_factor(Real, Real, double);        \
  template Real conductivity_factor(Real, Real, double);
BAGNOLD_INSTANTIATE(double)
BAGNOLD_INSTANTIATE(Dual)
#undef BAGNOLD_INSTANTIATE

}  // namespace bagnold::models::garzo_dufty
