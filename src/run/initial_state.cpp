#include "src/run/initial_state.hpp"

#include "src/grid/shapes.hpp"

namespace bagnold::run {

bool initial_region_selects(const deck::InitialRegion& region, grid::CellKind kind,
                            const std::array<double, 3>& centre) {
  return kind == grid::CellKind::fluid && grid::inside_box(centre, region.min, region.max);
}

void set_initial_state(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state) {
  const auto& layout = domain.layout;
  const auto& g = domain.grid;
  // Hydrostatic gas pressure: the reference pressure at the domain's highest point along gravity.
  std::array<double, 3> reference{};
  for (int d = 0; d < 3; ++d) {
    const auto& faces = g.axis(d).faces();
    reference[static_cast<std::size_t>(d)] =
        deck.physics.gravity[static_cast<std::size_t>(d)] < 0 ? faces.back() : faces.front();
  }
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const auto x = g.centre(layout.index3(l));
    for (const auto& region : deck.initial) {
      if (!initial_region_selects(region, layout.kind(l), x)) continue;
      state.solids_fraction[i] = region.solids_fraction;
      state.granular_temperature[i] = region.granular_temperature;
      for (std::size_t d = 0; d < 3; ++d) {
        state.gas_velocity[d][i] = region.gas_velocity[d];
        state.solids_velocity[d][i] = region.solids_velocity[d];
      }
    }
    state.gas_fraction[i] = 1.0 - state.solids_fraction[i];
    double head = 0.0;  // g · (x − x_ref) [m²/s²], >= 0 below the reference point
    for (std::size_t d = 0; d < 3; ++d) head += deck.physics.gravity[d] * (x[d] - reference[d]);
    state.gas_pressure[i] = deck.gas.reference_pressure + deck.gas.density * head;
  }
}

}  // namespace bagnold::run
