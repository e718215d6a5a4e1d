// Torquato's radial distribution function at contact, App. B Eq. 12 (product form).
#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"

namespace bagnold::models::rdf {

template <class Real>
Real torquato(Real phi, double critical_fraction) {
  if (value_of(phi) <= freezing_fraction) return carnahan_starling(phi);
  // Eq. 12 prints g0_CS(φ_f)^((φ_c−φ_f)/(φ_c−φ)); the text (divergence with exponent −1 at φ_c)
  // and Torquato's paper have the product, which is what we evaluate.
  return carnahan_starling(freezing_fraction) * (critical_fraction - freezing_fraction) /
         (critical_fraction - phi);
}

template double torquato(double, double);
template Dual torquato(Dual, double);

}  // namespace bagnold::models::rdf
