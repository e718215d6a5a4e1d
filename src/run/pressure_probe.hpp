#pragma once
// The deck's [[pressure_probe]]s: the monitor column dp_<name> [Pa] = p_g(lower) − p_g(upper),
// each end the gas pressure of the fluid cell that holds its point (average = cell) or the
// area-weighted mean over the fluid cells of the layer across gravity that holds it
// (average = layer, src/run/layer_average.hpp). A point on a face between two cells belongs to
// the upper cell; one on the domain's upper face to the last cell.

#include <optional>
#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

// The domain cell that holds `point`, or none outside the domain.
std::optional<grid::Index3> cell_holding(const grid::StructuredGrid& grid,
                                         const std::array<double, 3>& point);

struct ProbeProblem {
  std::string key;      // "pressure_probe[0].lower"
  std::string message;  // what is wrong with it
};
// The probes' points outside the domain, in a blocked cell (cell) or in a layer without a fluid
// cell (layer). Not collective: every rank holds the whole cell flags.
std::vector<ProbeProblem> pressure_probe_problems(const deck::Deck& deck,
                                                  const parallel::Domain& domain);

// dp_<name> per probe, in deck order.
std::vector<std::string> pressure_probe_columns(const std::vector<deck::PressureProbe>& probes);

// dp [Pa] per probe, in deck order. Collective: the cells may be on any rank.
std::vector<double> pressure_drops(const deck::Deck& deck, const parallel::Domain& domain,
                                   const FlowState& state);

}  // namespace bagnold::run
