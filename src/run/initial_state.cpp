#include "src/run/initial_state.hpp"

#include "src/grid/shapes.hpp"
#include "src/run/initial_gas_pressure.hpp"

namespace bagnold::run {

bool initial_region_selects(const deck::InitialRegion& region, grid::CellKind kind,
                            const std::array<double, 3>& centre) {
  return kind == grid::CellKind::fluid && grid::inside_box(centre, region.min, region.max);
}

void set_initial_state(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state) {
  const auto& layout = domain.layout;
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const auto x = domain.grid.centre(layout.index3(l));
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
  }
  set_initial_gas_pressure(deck, domain, state);
}

}  // namespace bagnold::run
