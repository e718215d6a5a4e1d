#pragma once
// What `bagnold run` says about a run before it starts, after the geometry: the build (version,
// git hash), the ranks and the start time, then every model the run resolved to, with the
// coefficients in effect: the solids-stress closure, the drag law, the solids wall law of each
// wall region, and the discretization's choices.

#include <string>

#include "src/deck/deck.hpp"
#include "src/grid/cell_flags.hpp"
#include "src/run/provenance.hpp"

namespace bagnold::app {

std::string run_banner(const deck::Deck& deck, const grid::BoundaryRegions& regions,
                       const run::Provenance& provenance);

}  // namespace bagnold::app
