// The sheared-system radial distribution function at contact of MKT, App. B Eq. 31.
#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"

namespace bagnold::models::rdf {

template <class Real>
Real chialvo_sundaresan(Real phi, double critical_fraction, double alpha_2) {
  // The (φ_c − φ)^{−3/2} divergence is the DEM scaling of App. B Fig. 6a (p/ρ_s φ T ~ g0).
  return carnahan_starling(phi) + alpha_2 * phi * phi / three_halves_power(critical_fraction - phi);
}

template double chialvo_sundaresan(double, double, double);
template Dual chialvo_sundaresan(Dual, double, double);

}  // namespace bagnold::models::rdf
