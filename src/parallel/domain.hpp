#pragma once
// Everything a run builds from the deck before any field exists: the grid, the cell flags, the
// boundary regions, the partition (by fluid cells, by given weights, or by layers across gravity
// under numerics.partition_weights = "layers") and this rank's layout.
// Collective over the communicator.

#include <vector>

#include "src/deck/deck.hpp"
#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"
#include "src/parallel/layout.hpp"
#include "src/parallel/partition.hpp"

namespace bagnold::parallel {

struct Domain {
  Domain(const deck::Deck& deck, const Communicator& comm);
  // Partitioned by these weights of the fluid cells (partition.hpp); by layers, the weights unused.
  Domain(const deck::Deck& deck, const Communicator& comm, const PartitionWeights& weights);
  Domain(const Domain&) = delete;  // the layout points at the grid
  Domain& operator=(const Domain&) = delete;

  grid::StructuredGrid grid;
  grid::BoundaryRegions regions;
  grid::CellFlags flags;
  std::vector<int> owner;  // per natural index of the extended box, -1 when not stored
  Layout layout;
};

}  // namespace bagnold::parallel
