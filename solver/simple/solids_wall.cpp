// The solids' wall laws as implicit coefficients (solids_wall.hpp), and the per-face near-wall
// state the momentum assembly hands them (FlowSolver::solids_wall_coefficient).
#include "solver/simple/solids_wall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/friction_table.hpp"
#include "models/wall/wall_coefficient.hpp"

namespace bagnold::solver {

namespace {
// Carnahan–Starling g0 (App. B Eq. 11) for Johnson–Jackson, at φ capped 0.01 below the packing
// limit so it stays finite in a compressed iterate.
double capped_carnahan_starling(double fraction, double packing_limit) {
  return models::rdf::carnahan_starling(std::clamp(fraction, 0.0, std::max(packing_limit - 0.01, 0.0)));
}
}  // namespace

double solids_packing_limit(const deck::Deck& deck) {
  const auto& c = deck.models.solids_stress.coefficients;
  const auto found = c.find("packed_gas_fraction");
  if (found != c.end() && std::holds_alternative<double>(found->second))
    return 1.0 - std::get<double>(found->second);
  return models::chialvo2012::critical_fraction(deck.solids.material.friction);
}

SolidsWalls::SolidsWalls(const deck::Deck& deck, const grid::BoundaryRegions& regions,
                         bool has_temperature)
    : m_material(deck.solids.material), m_has_temperature(has_temperature) {
  m_laws.resize(regions.regions.size());
  for (std::size_t r = 0; r < regions.regions.size(); ++r) {
    const auto& region = regions.regions[r];
    Law& law = m_laws[r];
    const auto type = regions.types[r];
    if (type != grid::BoundaryType::no_slip_wall && type != grid::BoundaryType::moving_wall) continue;
    if (region.solids_wall == "free-slip") {
      law.kind = Kind::free_slip;
    } else if (region.solids_wall == "johnson-jackson") {
      law.kind = Kind::johnson_jackson;
      law.johnson_jackson = {region.specularity, region.wall_restitution, solids_packing_limit(deck)};
      models::wall::require_valid(law.johnson_jackson);
    } else if (region.solids_wall == "dense-slip") {
      law.kind = Kind::dense_slip;
      law.dense.emplace(m_material, models::wall::DenseSlipWall{.wall_friction = region.wall_friction},
                        models::chialvo2012::yield_stress_ratio(m_material.friction));
    }
  }
}

double SolidsWalls::coefficient(int region, const NearWallSolids& near, double wall_distance) const {
  const Law& law = m_laws[static_cast<std::size_t>(region)];
  const double mu = std::max(near.viscosity, 0.0);
  switch (law.kind) {
    case Kind::no_slip: return mu / wall_distance;
    case Kind::free_slip: return 0.0;
    case Kind::johnson_jackson: {
      const double phi = std::max(near.fraction, 0.0);
      const double g0 = capped_carnahan_starling(phi, law.johnson_jackson.max_packing);
      const double theta =
          m_has_temperature && std::isfinite(near.temperature)
              ? std::max(near.temperature, 0.0)
              : models::wall::johnson_jackson_wall_temperature(law.johnson_jackson, near.slip_speed);
      const double c_slip = models::wall::johnson_jackson_slip_coefficient(
          law.johnson_jackson, m_material, std::min(phi, law.johnson_jackson.max_packing), g0, theta);
      return models::wall::wall_coefficient(c_slip, mu, wall_distance);
    }
    case Kind::dense_slip:
      return law.dense->wall_coefficient({.pressure = near.pressure, .viscosity = mu,
                                          .strain_rate = near.strain_rate},
                                         wall_distance);
  }
  return mu / wall_distance;
}

SolidsWallCoefficients::SolidsWallCoefficients(const deck::Deck& deck,
                                               const Discretization& discretization,
                                               bool has_temperature)
    : m_walls(deck, discretization.domain().regions, has_temperature) {
  if (m_walls.any_partial())
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
  NearWallSolids near;
  int count = 0;
  for (const int c : {l, n}) {
    if (c < 0 || layout.kind(c) != grid::CellKind::fluid) continue;
    const auto i = static_cast<std::size_t>(c);
    near.fraction += state.solids_fraction[i];
    near.pressure += state.solids_pressure[i];
    near.viscosity += closures.viscosity[solids][i];
    near.strain_rate += closures.strain_rate[i];
    near.temperature += state.granular_temperature[i];
    double slip2 = 0.0;  // tangential slip at the cell centre
    for (int a = 0; a < 3; ++a) {
      if (a == e) continue;
      const double slip = centre_velocity(layout, state.solids_velocity[static_cast<std::size_t>(a)], c, a) -
                          region.wall_velocity[static_cast<std::size_t>(a)];
      slip2 += slip * slip;
    }
    near.slip_speed += std::sqrt(slip2);
    ++count;
  }
  if (count == 0) return held = 0.0;
  near.fraction /= count;
  near.pressure /= count;
  near.viscosity /= count;
  near.strain_rate /= count;
  near.temperature /= count;
  near.slip_speed /= count;
  return held = m_walls.coefficient(link.region, near, wall_distance);
}

}  // namespace bagnold::solver
