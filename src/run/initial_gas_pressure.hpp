#pragma once
// The gas pressure at t = 0, from gas.reference_pressure at the top of the domain (its highest
// point along gravity), by gas.initial_pressure:
//   gas-weight  p = p_ref + ρ_g g·(x − x_top): the gas at rest, the solids carried by the floor;
//   bed-weight  p = p_ref + the weight per area of the gas and solids above the cell's centre,
//               layer by layer across gravity, each layer's mixture density ε_g ρ_g + ε_s ρ_s
//               averaged over its fluid cells (weighted by area): the gas carries the bed, as in
//               a fluidized bed at minimum fluidization. MFIX's set_fluidbed_p does the same when
//               no initial pressure is given (it adds a whole layer's weight at each centre;
//               here the layers above and half the cell's own layer).
// Every local cell (owned, boundary ring and halo) gets its value. bed-weight is collective.

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

// Needs the state's volume fractions set on the owned fluid cells.
void set_initial_gas_pressure(const deck::Deck& deck, const parallel::Domain& domain,
                              FlowState& state);

}  // namespace bagnold::run
