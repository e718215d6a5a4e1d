#pragma once
// Which rank owns each stored cell: a METIS k-way partition of the graph of fluid cells (edges
// across faces, periodic wrap included), balancing the number of fluid cells per rank or, given
// vertex weights, each of their sums (src/run/work_weights.hpp); then each boundary cell goes to
// the owner of an adjacent fluid cell so boundary values sit with the cells that use them.
// Every rank computes the same partition from the same (replicated) cell flags.
// Or, by layers across gravity (partition_cells_by_layers), from the geometry alone.

#include <cstdint>
#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"

namespace bagnold::parallel {

// Vertex weights: `constraints` numbers per natural index of the extended box, in
// values[constraints * natural + c] (the fluid cells' entries are used), each ≥ 0 and each
// constraint's sum over the fluid cells > 0. METIS balances every constraint's sum (a
// multi-constraint partition when there are more than one). Empty: every fluid cell weighs 1.
struct PartitionWeights {
  int constraints = 1;
  std::vector<int> values;
  bool empty() const { return values.empty(); }
  int at(std::int64_t natural, int constraint) const {
    return values[static_cast<std::size_t>(constraints * natural + constraint)];
  }
};

// Owner rank per natural index of the extended box; -1 for excluded cells.
std::vector<int> partition_cells(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                 int parts, const PartitionWeights& weights = {});

// Owner rank per natural index, from the geometry alone (numerics.partition_weights = "layers"):
// each layer of cells across `axis` (gravity's) is split over the ranks by recursive coordinate
// bisection across its two other axes, every rank the same number of the layer's fluid cells to
// within rounding (carried from layer to layer), so that a bed stratified along the axis puts the
// same share of the gas-only and of the solids-holding cells on every rank at any fill level.
// Boundary cells as partition_cells. Throws grid::GeometryError when a rank would own no fluid cell.
std::vector<int> partition_cells_by_layers(const grid::StructuredGrid& grid,
                                           const grid::CellFlags& flags, int parts, int axis);

}  // namespace bagnold::parallel
