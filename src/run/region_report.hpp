#pragma once
// What `bagnold check` and `bagnold run` say about the deck's regions before anything runs,
// from their census (region_census.hpp):
//   refused, each at its table's line:  a [[geometry.block]] that blocks no cell; a [[boundary]]
//     that selects no cell, or whose cells an earlier region holds every one of; an [[initial]]
//     region that selects no cell;
//   noted:  every pair of boundary regions, and every pair of initial regions, that select the
//     same cells, with the count and the rule that decides them (boundary: first wins; initial:
//     later wins);
//   printed:  each region's cells, and each initial region's solids mass and their total.

#include <string>
#include <vector>

#include "src/deck/diagnostics.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/region_census.hpp"

namespace bagnold::run {

struct RegionReport {
  deck::Diagnostics errors;        // empty when every region selects cells
  std::vector<std::string> notes;  // "note: ..." lines
  std::string text;                // one line per region, then the notes
};

RegionReport report_regions(const deck::Deck& deck, const parallel::Domain& domain,
                            const RegionCensus& census);

// "file:line" of a deck origin, or the --set argument (for messages that name a region).
std::string origin_text(const deck::Origin& origin);

}  // namespace bagnold::run
