#include "src/parallel/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace bagnold::parallel {

namespace {
using grid::CellKind;
using grid::Index3;

const Index3 face_offsets[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

// METIS k-way on the fluid-cell graph; returns the part of each fluid cell in natural order.
std::vector<idx_t> metis_parts(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                               const std::vector<std::int64_t>& fluid_cells,
                               const std::vector<idx_t>& vertex_of, int parts,
                               const PartitionWeights& weights) {
  std::vector<idx_t> xadj{0}, adjncy;
  xadj.reserve(fluid_cells.size() + 1);
  adjncy.reserve(6 * fluid_cells.size());
  for (const auto c : fluid_cells) {
    const Index3 ijk = grid.index3(c);
    const auto row_begin = adjncy.size();
    for (const auto& offset : face_offsets) {
      Index3 other;
      if (!grid.step(ijk, offset, other)) continue;
      const auto n = grid.natural(other);
      if (n == c || flags.kind[static_cast<std::size_t>(n)] != CellKind::fluid) continue;
      const idx_t v = vertex_of[static_cast<std::size_t>(n)];
      // A periodic direction two cells long reaches the same neighbour twice.
      if (std::find(adjncy.begin() + static_cast<std::ptrdiff_t>(row_begin), adjncy.end(), v) ==
          adjncy.end())
        adjncy.push_back(v);
    }
    xadj.push_back(static_cast<idx_t>(adjncy.size()));
  }
  idx_t vertices = static_cast<idx_t>(fluid_cells.size());
  idx_t constraints = weights.constraints;
  idx_t nparts = parts;
  idx_t cut = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same partition on every rank and every run
  std::vector<idx_t> part(fluid_cells.size(), 0);
  std::vector<idx_t> vertex_weights;
  if (!weights.empty())
    for (const auto c : fluid_cells)
      for (int k = 0; k < weights.constraints; ++k) vertex_weights.push_back(static_cast<idx_t>(weights.at(c, k)));
  // Several constraints (numerics.partition_weights = "phases"): each within 1 % of its share
  // rather than METIS's 3 % (k-way's default), since the pressure solve, about half an outer
  // iteration's work on the bins, goes by the first (fluid cells): at 3 % the 2.5 mm bin's
  // fluid cells split 5.5 % unevenly (docs/benchmarks.md, "The 2.5 mm bin on 2 ranks: where the
  // waits are").
  std::vector<real_t> tolerance(static_cast<std::size_t>(constraints), 1.01f);
  const int status = METIS_PartGraphKway(&vertices, &constraints, xadj.data(), adjncy.data(),
                                         vertex_weights.empty() ? nullptr : vertex_weights.data(),
                                         nullptr, nullptr, &nparts, nullptr,
                                         constraints > 1 ? tolerance.data() : nullptr,
                                         options, &cut, part.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS_PartGraphKway failed with status " + std::to_string(status));
  return part;
}
}  // namespace

std::vector<int> partition_cells(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                 int parts, const PartitionWeights& weights) {
  const auto n = static_cast<std::size_t>(grid.extended_cell_count());
  std::vector<int> owner(n, -1);
  std::vector<std::int64_t> fluid_cells;
  std::vector<idx_t> vertex_of(n, -1);
  for (std::size_t c = 0; c < n; ++c)
    if (flags.kind[c] == CellKind::fluid) {
      vertex_of[c] = static_cast<idx_t>(fluid_cells.size());
      fluid_cells.push_back(static_cast<std::int64_t>(c));
    }
  if (fluid_cells.empty())
    throw grid::GeometryError("the geometry blocks every cell of the domain: nothing can flow");
  if (parts > static_cast<int>(fluid_cells.size()))
    throw grid::GeometryError("more ranks (" + std::to_string(parts) + ") than fluid cells (" +
                             std::to_string(fluid_cells.size()) + ")");
  if (parts > 1) {
    const auto part = metis_parts(grid, flags, fluid_cells, vertex_of, parts, weights);
    for (std::size_t v = 0; v < fluid_cells.size(); ++v)
      owner[static_cast<std::size_t>(fluid_cells[v])] = static_cast<int>(part[v]);
  } else {
    for (const auto c : fluid_cells) owner[static_cast<std::size_t>(c)] = 0;
  }
  // Boundary cells: the owner of a face-adjacent fluid cell (the cell that uses the boundary
  // value), else of the first fluid cell across an edge or corner.
  std::vector<Index3> offsets(std::begin(face_offsets), std::end(face_offsets));
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) offsets.push_back({di, dj, dk});
  for (std::size_t c = 0; c < n; ++c) {
    if (flags.kind[c] != CellKind::boundary) continue;
    const Index3 ijk = grid.index3(static_cast<std::int64_t>(c));
    for (const auto& offset : offsets) {
      Index3 other;
      if (!grid.step(ijk, offset, other)) continue;
      const auto o = static_cast<std::size_t>(grid.natural(other));
      if (flags.kind[o] == CellKind::fluid) {
        owner[c] = owner[o];
        break;
      }
    }
  }
  return owner;
}

}  // namespace bagnold::parallel
