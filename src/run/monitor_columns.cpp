#include "src/run/monitor_columns.hpp"

#include "src/run/pressure_probe.hpp"

namespace bagnold::run {

std::vector<std::string> monitor_columns(const grid::BoundaryRegions& regions,
                                         const std::vector<deck::PressureProbe>& probes) {
  std::vector<std::string> columns = {"dt", "iterations", "residual", "inventory_gas_kg",
                                      "inventory_solids_kg"};
  for (const auto& r : regions.regions) {
    columns.push_back("flux_" + r.name + "_gas_kg_per_s");
    columns.push_back("flux_" + r.name + "_solids_kg_per_s");
  }
  for (const auto& c : pressure_probe_columns(probes)) columns.push_back(c);
  return columns;
}

Inventory phase_inventory(const deck::Deck& deck, const parallel::Domain& domain,
                          const FlowState& state) {
  const auto& layout = domain.layout;
  double gas = 0.0, solids = 0.0;
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const double volume = domain.grid.volume(layout.index3(l));
    gas += state.gas_fraction[static_cast<std::size_t>(l)] * volume;
    solids += state.solids_fraction[static_cast<std::size_t>(l)] * volume;
  }
  const auto& comm = layout.comm();
  return {deck.gas.enabled ? deck.gas.density * comm.sum(gas) : 0.0,
          deck.solids.material.density * comm.sum(solids)};
}

}  // namespace bagnold::run
