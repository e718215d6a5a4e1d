// The wall-law registry, and what a wall law takes from the solids-stress closure. See
// wall_law.hpp.
#include "models/wall/wall_law.hpp"

#include "models/stress/solids_stress.hpp"

namespace bagnold::models::wall {

Registry<WallLaw, WallLawInput>& wall_law_registry() {
  static Registry<WallLaw, WallLawInput> registry;
  return registry;
}

ClosureAtWall closure_at_wall(const SolidsStressModel& model, const Material& material) {
  return {.defines_temperature = model.defines_temperature(),
          .packing_limit = model.packing_limit(material),
          .radial_distribution = [&model, material](double solids_fraction) {
            return model.wall_radial_distribution(material, solids_fraction);
          }};
}

}  // namespace bagnold::models::wall
