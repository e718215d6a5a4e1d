#include "src/run/layer_average.hpp"

namespace bagnold::run {

double area_across(const grid::StructuredGrid& grid, const grid::Index3& ijk, int axis) {
  double area = 1.0;
  for (int d = 0; d < 3; ++d)
    if (d != axis) area *= grid.axis(d).width(ijk[static_cast<std::size_t>(d)]);
  return area;
}

LayerMeans layer_means(const parallel::Domain& domain, int axis, const std::vector<double>& values) {
  const auto& layout = domain.layout;
  const auto layers = static_cast<std::size_t>(domain.grid.cells(axis));
  // One reduction for both sums: [0, layers) the weighted values, [layers, 2 layers) the areas.
  std::vector<double> sums(2 * layers, 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const auto ijk = layout.index3(l);
    const auto k = static_cast<std::size_t>(ijk[static_cast<std::size_t>(axis)]);
    const double area = area_across(domain.grid, ijk, axis);
    sums[k] += area * values[static_cast<std::size_t>(l)];
    sums[layers + k] += area;
  }
  layout.comm().sum_in_place(sums);
  LayerMeans out;
  out.mean.assign(layers, 0.0);
  out.area.assign(sums.begin() + static_cast<std::ptrdiff_t>(layers), sums.end());
  for (std::size_t k = 0; k < layers; ++k)
    if (out.area[k] > 0.0) out.mean[k] = sums[k] / out.area[k];
  return out;
}

}  // namespace bagnold::run
