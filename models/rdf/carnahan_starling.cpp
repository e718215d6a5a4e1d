// Carnahan–Starling radial distribution function at contact, App. B Eq. 11.
#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"

namespace bagnold::models::rdf {

template <class Real>
Real carnahan_starling(Real phi) {
  const Real gas = 1.0 - phi;
  return (1.0 - 0.5 * phi) / (gas * gas * gas);
}

template double carnahan_starling(double);
template Dual carnahan_starling(Dual);

}  // namespace bagnold::models::rdf
