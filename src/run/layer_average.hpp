#pragma once
// Means over the layers of cells across one axis (the layers normal to gravity in a column): for
// each layer k of the domain, the mean of a cell field over its fluid cells weighted by their
// area across the axis. Collective: each rank sums its owned fluid cells and the sums are added
// over the ranks, so every rank gets every layer's mean whichever ranks hold its cells.

#include <vector>

#include "src/parallel/domain.hpp"

namespace bagnold::run {

struct LayerMeans {
  std::vector<double> mean;  // per layer k = 0 .. cells(axis) − 1; 0 where area is 0
  std::vector<double> area;  // [m²] of the layer's fluid cells across the axis
};

// `values` holds one value per local cell (layout order); only owned fluid cells are read.
LayerMeans layer_means(const parallel::Domain& domain, int axis, const std::vector<double>& values);

// The area [m²] of cell ijk across `axis`: the product of its widths along the other two.
double area_across(const grid::StructuredGrid& grid, const grid::Index3& ijk, int axis);

}  // namespace bagnold::run
