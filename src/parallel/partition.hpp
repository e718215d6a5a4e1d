#pragma once
// Which rank owns each stored cell: a METIS k-way partition of the graph of fluid cells (edges
// across faces, periodic wrap included), balancing the number of fluid cells per rank or, given
// vertex weights, their summed weight (src/run/work_weights.hpp); then each boundary cell goes to the owner of an
// adjacent fluid cell so boundary values sit with the cells that use them.
// Every rank computes the same partition from the same (replicated) cell flags.

#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"

namespace bagnold::parallel {

// Owner rank per natural index of the extended box; -1 for excluded cells. `weights`: per
// natural index of the extended box, each fluid cell's weight (≥ 1; other entries unused); empty:
// every fluid cell weighs the same.
std::vector<int> partition_cells(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                 int parts, const std::vector<int>& weights = {});

}  // namespace bagnold::parallel
