#include "src/parallel/domain.hpp"

#include "src/parallel/partition.hpp"

namespace bagnold::parallel {

namespace {
std::vector<int> owners(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                        const deck::Deck& deck, int parts, const PartitionWeights& weights) {
  if (deck.numerics.partition_weights == "layers")
    return partition_cells_by_layers(grid, flags, parts, deck.physics.gravity_axis());
  return partition_cells(grid, flags, parts, weights);
}
}  // namespace

Domain::Domain(const deck::Deck& deck, const Communicator& comm) : Domain(deck, comm, {}) {}

Domain::Domain(const deck::Deck& deck, const Communicator& comm, const PartitionWeights& weights)
    : grid(deck.grid),
      regions(grid::make_boundary_regions(deck)),
      flags(grid::classify_cells(grid, deck.geometry, regions)),
      owner(owners(grid, flags, deck, comm.size(), weights)),
      layout(grid, flags, owner, comm) {}

}  // namespace bagnold::parallel
