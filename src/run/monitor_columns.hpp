#pragma once
// The monitor's columns after time: dt, outer iterations, the largest normalized residual, the
// inventory [kg] of each phase in the domain, the mass flux [kg/s] of each phase through each
// boundary region (positive out of the domain), and the pressure drop [Pa] of each
// [[pressure_probe]] (src/run/pressure_probe.hpp).

#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/grid/cell_flags.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

std::vector<std::string> monitor_columns(const grid::BoundaryRegions& regions,
                                         const std::vector<deck::PressureProbe>& probes);

struct Inventory {
  double gas = 0.0;     // Σ ρ_g ε_g V [kg]
  double solids = 0.0;  // Σ ρ_s ε_s V [kg]
};
// Collective: sums over owned fluid cells of all ranks.
Inventory phase_inventory(const deck::Deck& deck, const parallel::Domain& domain,
                          const FlowState& state);

}  // namespace bagnold::run
