// The solids' wall coefficients per wall face, from the near-wall state (solids_wall.hpp).
#include "solver/simple/solids_wall.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

double tangential_slip_speed(const parallel::Layout& layout, const run::FlowState& state, int l,
                             int normal, const std::array<double, 3>& wall_velocity) {
  double slip2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    if (a == normal) continue;
    const auto ua = static_cast<std::size_t>(a);
    const double slip = centre_velocity(layout, state.solids_velocity[ua], l, a) - wall_velocity[ua];
    slip2 += slip * slip;
  }
  return std::sqrt(slip2);
}

std::vector<std::unique_ptr<models::wall::WallLaw>> solids_wall_laws(
    const deck::Deck& deck, const grid::BoundaryRegions& regions,
    const models::SolidsStressModel& closure) {
  const auto at_wall = models::wall::closure_at_wall(closure, deck.solids.material);
  std::vector<std::unique_ptr<models::wall::WallLaw>> laws;
  for (std::size_t r = 0; r < regions.regions.size(); ++r) {
    const auto& region = regions.regions[r];
    const bool wall = regions.types[r] == grid::BoundaryType::no_slip_wall ||
                      regions.types[r] == grid::BoundaryType::moving_wall;
    laws.push_back(models::wall::wall_law_registry().create(
        wall ? region.solids_wall : "no-slip",
        {.material = deck.solids.material,
         .wall = {.specularity = region.specularity, .wall_restitution = region.wall_restitution,
                  .wall_friction = region.wall_friction},
         .closure = at_wall}));
  }
  return laws;
}

SolidsWallCoefficients::SolidsWallCoefficients(const deck::Deck& deck,
                                               const Discretization& discretization,
                                               const models::SolidsStressModel& closure)
    : m_laws(solids_wall_laws(deck, discretization.domain().regions, closure)) {
  bool any_partial = false;
  for (const auto& law : m_laws) any_partial = any_partial || law->slips();
  if (any_partial)
    for (auto& held : m_held) held.assign(6 * static_cast<std::size_t>(discretization.layout().local_count()), 0.0);
}

// The wall face across `link` from the tangential velocity (component d) between cells l and
// its + neighbour n: the near-wall solids averaged over the fluid cells of the two.
double SolidsWallCoefficients::coefficient(const Discretization& discretization,
                                           const run::FlowState& state,
                                           const ClosureFields& closures, const Link& link, int l,
                                           int d, int face, bool refresh) {
  double& held = m_held[static_cast<std::size_t>(d)][6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face)];
  if (!refresh) return held;
  const auto& layout = discretization.layout();
  const int e = parallel::face_direction(face);
  const double wall_distance = 0.5 * discretization.width(l, e);
  const int n = layout.neighbour(l, 2 * d + 1);
  const auto& region = discretization.domain().regions.regions[static_cast<std::size_t>(link.region)];
  models::wall::NearWallSolids near;
  int count = 0;
  for (const int c : {l, n}) {
    if (c < 0 || layout.kind(c) != grid::CellKind::fluid) continue;
    const auto i = static_cast<std::size_t>(c);
    near.fraction += state.solids_fraction[i];
    near.pressure += state.solids_pressure[i];
    near.viscosity += closures.viscosity[solids][i];
    near.strain_rate += closures.strain_rate[i];
    near.temperature += state.granular_temperature[i];
    near.slip_speed += tangential_slip_speed(layout, state, c, e, region.wall_velocity);
    ++count;
  }
  if (count == 0) return held = 0.0;
  near.fraction /= count;
  near.pressure /= count;
  near.viscosity /= count;
  near.strain_rate /= count;
  near.temperature /= count;
  near.slip_speed /= count;
  return held = m_laws[static_cast<std::size_t>(link.region)]->coefficient(near, wall_distance);
}

}  // namespace bagnold::solver
