#include "src/parallel/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace bagnold::parallel {

namespace {
using grid::CellKind;
using grid::Index3;

const Index3 face_offsets[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};

// METIS k-way on the fluid-cell graph; returns the part of each fluid cell in natural order.
std::vector<idx_t> metis_parts(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                               const std::vector<std::int64_t>& fluid_cells, int parts,
                               const PartitionWeights& weights) {
  std::vector<idx_t> vertex_of(static_cast<std::size_t>(grid.extended_cell_count()), -1);
  for (std::size_t v = 0; v < fluid_cells.size(); ++v)
    vertex_of[static_cast<std::size_t>(fluid_cells[v])] = static_cast<idx_t>(v);
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

// The fluid cells' natural indices, in order; throws when there are none or fewer than `parts`.
std::vector<std::int64_t> fluid_cells_of(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                         int parts) {
  std::vector<std::int64_t> fluid;
  for (std::size_t c = 0; c < static_cast<std::size_t>(grid.extended_cell_count()); ++c)
    if (flags.kind[c] == CellKind::fluid) fluid.push_back(static_cast<std::int64_t>(c));
  if (fluid.empty())
    throw grid::GeometryError("the geometry blocks every cell of the domain: nothing can flow");
  if (parts > static_cast<int>(fluid.size()))
    throw grid::GeometryError("more ranks (" + std::to_string(parts) + ") than fluid cells (" +
                             std::to_string(fluid.size()) + ")");
  return fluid;
}

// Boundary cells: the owner of a face-adjacent fluid cell (the cell that uses the boundary
// value), else of the first fluid cell across an edge or corner.
void give_boundary_cells_owners(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                std::vector<int>& owner) {
  std::vector<Index3> offsets(std::begin(face_offsets), std::end(face_offsets));
  for (int dk = -1; dk <= 1; ++dk)
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) offsets.push_back({di, dj, dk});
  for (std::size_t c = 0; c < owner.size(); ++c) {
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
}

// Recursive coordinate bisection of one layer's fluid cells [begin, end) over the parts
// [first, first + count): cut across the axis along which they span more cells (on a tie the
// first of the two, unless it is periodic and the other not: across a periodic axis the parts
// meet at both ends), the cells on each side in proportion to its parts. m_carry holds, per node
// of the bisection (its first part and count), how far the cuts of the layers before fell short
// of the ideal, so that the rounding of many small layers does not add up on one side.
class LayerBisection {
 public:
  LayerBisection(const grid::StructuredGrid& grid, int axis, std::vector<int>& owner)
      : m_grid(grid), m_across{axis == 0 ? 1 : 0, axis == 2 ? 1 : 2}, m_owner(owner) {}

  void split(std::vector<std::int64_t>::iterator begin, std::vector<std::int64_t>::iterator end,
             int first, int count) {
    if (begin == end) return;
    if (count == 1) {
      for (auto c = begin; c != end; ++c) m_owner[static_cast<std::size_t>(*c)] = first;
      return;
    }
    int low[2] = {std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
    int high[2] = {std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
    for (auto c = begin; c != end; ++c) {
      const Index3 ijk = m_grid.index3(*c);
      for (int a = 0; a < 2; ++a) {
        low[a] = std::min(low[a], ijk[static_cast<std::size_t>(m_across[a])]);
        high[a] = std::max(high[a], ijk[static_cast<std::size_t>(m_across[a])]);
      }
    }
    // On a tie, not across a periodic axis, where the parts would meet at both ends.
    const int span0 = high[0] - low[0], span1 = high[1] - low[1];
    const bool periodic0 = m_grid.periodic(m_across[0]), periodic1 = m_grid.periodic(m_across[1]);
    const int along = span1 > span0 || (span1 == span0 && periodic0 && !periodic1) ? 1 : 0;
    const auto cut_axis = static_cast<std::size_t>(m_across[along]);
    const auto other_axis = static_cast<std::size_t>(m_across[1 - along]);
    std::sort(begin, end, [&](std::int64_t a, std::int64_t b) {
      const Index3 p = m_grid.index3(a), q = m_grid.index3(b);
      return std::tie(p[cut_axis], p[other_axis]) < std::tie(q[cut_axis], q[other_axis]);
    });
    const int left = count / 2;
    const auto cells = static_cast<double>(end - begin);
    double& carry = m_carry[{first, count}];
    const double ideal = cells * left / count + carry;
    const auto taken = static_cast<std::ptrdiff_t>(std::clamp(std::round(ideal), 0.0, cells));
    carry = ideal - static_cast<double>(taken);
    split(begin, begin + taken, first, left);
    split(begin + taken, end, first + left, count - left);
  }

 private:
  const grid::StructuredGrid& m_grid;
  int m_across[2];
  std::vector<int>& m_owner;
  std::map<std::pair<int, int>, double> m_carry;
};
}  // namespace

std::vector<int> partition_cells(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
                                 int parts, const PartitionWeights& weights) {
  const auto fluid = fluid_cells_of(grid, flags, parts);
  std::vector<int> owner(static_cast<std::size_t>(grid.extended_cell_count()), -1);
  if (parts > 1) {
    const auto part = metis_parts(grid, flags, fluid, parts, weights);
    for (std::size_t v = 0; v < fluid.size(); ++v)
      owner[static_cast<std::size_t>(fluid[v])] = static_cast<int>(part[v]);
  } else {
    for (const auto c : fluid) owner[static_cast<std::size_t>(c)] = 0;
  }
  give_boundary_cells_owners(grid, flags, owner);
  return owner;
}

std::vector<int> partition_cells_by_layers(const grid::StructuredGrid& grid,
                                           const grid::CellFlags& flags, int parts, int axis) {
  const auto fluid = fluid_cells_of(grid, flags, parts);
  std::vector<int> owner(static_cast<std::size_t>(grid.extended_cell_count()), -1);
  std::map<int, std::vector<std::int64_t>> layers;  // by index along the axis
  for (const auto c : fluid) layers[grid.index3(c)[static_cast<std::size_t>(axis)]].push_back(c);
  LayerBisection bisection(grid, axis, owner);
  for (auto& [index, cells] : layers) bisection.split(cells.begin(), cells.end(), 0, parts);
  std::vector<std::int64_t> owned(static_cast<std::size_t>(parts), 0);
  for (const auto c : fluid) ++owned[static_cast<std::size_t>(owner[static_cast<std::size_t>(c)])];
  for (int r = 0; r < parts; ++r)
    if (owned[static_cast<std::size_t>(r)] == 0)
      throw grid::GeometryError("numerics.partition_weights = \"layers\" leaves rank " + std::to_string(r) +
                                " of " + std::to_string(parts) + " without a fluid cell: the domain has too few fluid cells "
                                "per layer across " + std::string(1, "xyz"[axis]) + " for that many ranks");
  give_boundary_cells_owners(grid, flags, owner);
  return owner;
}

}  // namespace bagnold::parallel
