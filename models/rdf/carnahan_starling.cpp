// Carnahan–Starling radial distribution function at contact, App. B Eq. 11.
#include <stdexcept>

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

Kind kind_from_name(const std::string& name) {
  if (name == "carnahan-starling") return Kind::carnahan_starling;
  if (name == "torquato") return Kind::torquato;
  if (name == "mkt") return Kind::chialvo_sundaresan;
  throw std::invalid_argument("unknown radial distribution '" + name +
                              "' (known: carnahan-starling, torquato, mkt)");
}

const std::vector<std::string>& kind_names() {
  static const std::vector<std::string> names{"carnahan-starling", "torquato", "mkt"};
  return names;
}

}  // namespace bagnold::models::rdf
