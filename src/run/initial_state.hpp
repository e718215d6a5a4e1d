#pragma once
// The state at t = 0 from the deck's [[initial]] regions (later regions win), with the gas
// pressure of gas.initial_pressure (src/run/initial_gas_pressure.hpp). Collective.

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

// Whether an [[initial]] region sets a cell: a fluid cell whose centre is in [min, max].
bool initial_region_selects(const deck::InitialRegion& region, grid::CellKind kind,
                            const std::array<double, 3>& centre);

void set_initial_state(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state);

}  // namespace bagnold::run
