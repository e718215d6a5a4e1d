#include "src/parallel/domain.hpp"

#include "src/parallel/partition.hpp"

namespace bagnold::parallel {

Domain::Domain(const deck::Deck& deck, const Communicator& comm) : Domain(deck, comm, {}) {}

Domain::Domain(const deck::Deck& deck, const Communicator& comm, const PartitionWeights& weights)
    : grid(deck.grid),
      regions(grid::make_boundary_regions(deck)),
      flags(grid::classify_cells(grid, deck.geometry, regions)),
      owner(partition_cells(grid, flags, comm.size(), weights)),
      layout(grid, flags, owner, comm) {}

}  // namespace bagnold::parallel
