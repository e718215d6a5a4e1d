#pragma once
// Which rank owns each stored cell: a METIS k-way partition of the graph of fluid cells (edges
// across faces, periodic wrap included), then each boundary cell goes to the owner of an
// adjacent fluid cell so boundary values sit with the cells that use them.
// Every rank computes the same partition from the same (replicated) cell flags.

#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"

namespace bagnold::parallel {

// Owner rank per natural index of the extended box; -1 for excluded cells.
std::vector<int> partition_cells(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                 int parts);

}  // namespace bagnold::parallel
