#include "src/app/preflight.hpp"

#include "src/parallel/domain_summary.hpp"
#include "src/run/flow_state.hpp"
#include "src/run/region_census.hpp"
#include "src/run/region_report.hpp"

namespace bagnold::app {

Preflight preflight(const deck::Deck& deck, const parallel::Communicator& comm) {
  Preflight p;
  p.domain = std::make_unique<parallel::Domain>(deck, comm);
  const auto summary = parallel::summarize(*p.domain);
  p.text = "# Geometry\n" + parallel::summary_text(*p.domain, summary,
                                                  static_cast<int>(run::FlowState::field_names().size()));
  auto regions = run::report_regions(deck, *p.domain, run::take_region_census(deck, *p.domain));
  p.text += regions.text;
  p.errors = std::move(regions.errors);
  return p;
}

}  // namespace bagnold::app
