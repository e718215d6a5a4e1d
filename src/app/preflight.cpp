#include "src/app/preflight.hpp"

#include <fmt/format.h>

#include "src/parallel/domain_summary.hpp"
#include "src/run/flow_state.hpp"
#include "src/run/memory_estimate.hpp"
#include "src/run/pressure_probe.hpp"
#include "src/run/region_census.hpp"
#include "src/run/region_report.hpp"

namespace bagnold::app {

namespace {

// The grid's `cells` key with the most cells (the first of equals): where a grid too large
// for the machine is refused.
std::string largest_axis_key(const deck::Grid& grid) {
  const deck::Axis* axes[] = {&grid.x, &grid.y, &grid.z};
  int largest = 0;
  for (int d = 1; d < 3; ++d)
    if (axes[d]->cells > axes[largest]->cells) largest = d;
  return fmt::format("grid.{}.cells", "xyz"[largest]);
}

}  // namespace

Preflight preflight(const deck::Deck& deck, const parallel::Communicator& comm) {
  Preflight p;
  const auto memory = run::estimate_memory(deck.grid, comm);
  p.text = "# Geometry\nmemory: " + run::memory_text(memory) + "\n";
  if (!memory.fits()) {
    const auto& g = deck.grid;
    const std::string key = largest_axis_key(g);
    p.errors.error(deck.origin_of(key), key,
                   fmt::format("the grid of {} x {} x {} = {:.4g} cells needs {:.3g} GB of memory "
                               "(estimated, docs/reliability.md \"Memory estimate\"), more than "
                               "the {:.3g} GB this machine has: use fewer cells, or more nodes",
                               g.x.cells, g.y.cells, g.z.cells,
                               static_cast<double>(g.x.cells) * g.y.cells * g.z.cells,
                               memory.worst_node_bytes / 1e9, memory.worst_node_physical / 1e9));
    return p;
  }
  if (memory.worst_node_bytes > memory.worst_node_available)
    p.text += "note: the estimate is more than the memory available now; the run may be slow, "
              "or stopped by the system\n";
  p.domain = std::make_unique<parallel::Domain>(deck, comm);
  const auto summary = parallel::summarize(*p.domain);
  p.text += parallel::summary_text(*p.domain, summary,
                                   static_cast<int>(run::FlowState::field_names().size()));
  auto regions = run::report_regions(deck, *p.domain, run::take_region_census(deck, *p.domain));
  p.text += regions.text;
  p.errors = std::move(regions.errors);
  for (const auto& problem : run::pressure_probe_problems(deck, *p.domain))
    p.errors.error(deck.origin_of(problem.key), problem.key, problem.message);
  return p;
}

}  // namespace bagnold::app
