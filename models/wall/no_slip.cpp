// No slip for the solids: c_slip = ∞, so the wall coefficient is the bulk one, c_w = μ_s/δ
// (wall_coefficient.hpp with c_slip = ∞; MFIX's no-slip wall, a ghost velocity −u_P).
#include <algorithm>
#include <memory>

#include "models/wall/wall_law.hpp"

namespace bagnold::models::wall {

namespace {
class NoSlip final : public WallLaw {
 public:
  std::string name() const override { return "no-slip"; }
  double coefficient(const NearWallSolids& near, double wall_distance) const override {
    return std::max(near.viscosity, 0.0) / wall_distance;
  }
  bool slips() const override { return false; }
};

[[maybe_unused]] const bool registered =
    wall_law_registry().add({.name = "no-slip",
                             .summary = "no slip: the solids stick to the wall, c_w = μ_s/δ",
                             .coefficients = {},
                             .make = [](const WallLawInput&) -> std::unique_ptr<WallLaw> {
                               return std::make_unique<NoSlip>();
                             }});
}  // namespace

}  // namespace bagnold::models::wall
