// Free slip for the solids: c_slip = 0, no tangential wall stress, c_w = 0 (MFIX's free-slip
// wall, a ghost velocity +u_P). The gas keeps its own condition (the region's type).
#include <memory>

#include "models/wall/wall_law.hpp"

namespace bagnold::models::wall {

namespace {
class FreeSlip final : public WallLaw {
 public:
  std::string name() const override { return "free-slip"; }
  double coefficient(const NearWallSolids& /*near*/, double /*wall_distance*/) const override {
    return 0.0;
  }
  bool slips() const override { return true; }
};

[[maybe_unused]] const bool registered = wall_law_registry().add(
    {.name = "free-slip",
     .summary = "free slip: no tangential wall stress on the solids, c_w = 0",
     .coefficients = {},
     .make = [](const WallLawInput&) -> std::unique_ptr<WallLaw> {
       return std::make_unique<FreeSlip>();
     }});
}  // namespace

}  // namespace bagnold::models::wall
