// The stress registry, and the default wall g0 of the interface (solids_stress.hpp).
#include <algorithm>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models {

Registry<SolidsStressModel>& stress_registry() {
  static Registry<SolidsStressModel> registry;
  return registry;
}

double SolidsStressModel::wall_radial_distribution(const Material& material,
                                                   double solids_fraction) const {
  const double cap = std::max(packing_limit(material) - wall_jamming_margin, 0.0);
  return rdf::carnahan_starling(std::clamp(solids_fraction, 0.0, cap));
}

}  // namespace bagnold::models
