#pragma once
// What `bagnold check` and `bagnold run` both do once the deck has loaded, before anything runs:
//   1. estimate the memory the grid needs and refuse a grid the machine cannot hold, at the
//      line of the grid's largest `cells` key (src/run/memory_estimate.hpp);
//   2. build the domain: grid, cell flags, boundary regions, partition (grid::GeometryError
//      when nothing can flow);
//   3. count the cells of every region and refuse a region that selects none, each at its
//      table's line, noting the overlaps (src/run/region_report.hpp).
// Collective. `text` is for rank 0: the memory estimate, the geometry summary and the regions.

#include <memory>
#include <string>

#include "src/deck/diagnostics.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::app {

struct Preflight {
  std::unique_ptr<parallel::Domain> domain;  // null when refused before it was built
  std::string text;
  deck::Diagnostics errors;  // what is refused; the deck can run when ok()
};

Preflight preflight(const deck::Deck& deck, const parallel::Communicator& comm);

}  // namespace bagnold::app
