#pragma once
// How many cells each region of the deck selects, and which regions select the same cells, for
// `bagnold check` and the start of a run (src/app/preflight.cpp judges the counts):
//   [[geometry.block]]  the domain cells whose centre it blocks;
//   [[boundary]]        the boundary cells it selects (grid::region_selects), and the ones it
//                       holds: a cell belongs to the first region listed that selects it;
//   [[initial]]         the fluid cells it selects (run::initial_region_selects), the ones it
//                       sets (the last region listed that selects a cell sets it) and the solids
//                       mass ρ_s ε_s V it puts in them.
// Collective: boundary and initial regions are counted over each rank's owned cells and summed
// over the ranks; the blocks' counts come from the cell flags, which every rank holds whole.

#include <cstdint>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::run {

struct RegionCount {
  std::int64_t selected = 0;
  std::int64_t kept = 0;  // held (boundary) or set (initial): selected less those another takes
};

// Two regions of one kind that select `shared` cells in common; first < second in deck order.
struct RegionOverlap {
  int first = 0;
  int second = 0;
  std::int64_t shared = 0;
};

struct RegionCensus {
  std::vector<std::int64_t> block_cells;      // per [[geometry.block]]
  std::vector<RegionCount> boundaries;        // per [[boundary]] (not the implicit "walls")
  std::vector<RegionOverlap> boundary_overlaps;
  std::int64_t walls = 0;                     // boundary cells no [[boundary]] holds
  std::vector<RegionCount> initial;           // per [[initial]]
  std::vector<double> initial_solids_mass;    // [kg] in the cells each region sets
  std::vector<RegionOverlap> initial_overlaps;
};

RegionCensus take_region_census(const deck::Deck& deck, const parallel::Domain& domain);

}  // namespace bagnold::run
