#include "models/stress/solids_stress.hpp"

namespace bagnold::models {

Registry<SolidsStressModel>& stress_registry() {
  static Registry<SolidsStressModel> registry;
  return registry;
}

}  // namespace bagnold::models
