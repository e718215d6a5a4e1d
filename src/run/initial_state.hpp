#pragma once
// The state at t = 0 from the deck's [[initial]] regions (later regions win), with the gas
// pressure hydrostatic from gas.reference_pressure at the top of the domain.

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

void set_initial_state(const deck::Deck& deck, const parallel::Domain& domain, FlowState& state);

}  // namespace bagnold::run
