#pragma once
// The Cartesian grid, uniform or geometrically stretched per direction.
//
// Cells are addressed by (i, j, k) with 0 <= i < nx in the domain, and one ring of boundary
// cells around it (i = -1 and i = nx) in every non-periodic direction: the "extended box".
// Every field, scalar or staggered, is indexed by its owning cell: scalars live at the centre,
// U on the east face (x = face(0, i + 1)), V on the north face, W on the top face.
// A cell's natural index numbers the extended box with x fastest.

#include <array>
#include <cstdint>
#include <vector>

#include "src/deck/deck.hpp"

namespace bagnold::grid {

using Natural = std::int64_t;
using Index3 = std::array<int, 3>;

// Face coordinates of one direction; cell i spans [faces[i], faces[i+1]].
class AxisCoordinates {
 public:
  explicit AxisCoordinates(const deck::Axis& axis);
  int cells() const { return static_cast<int>(m_faces.size()) - 1; }
  // Valid for -1 <= i <= cells(): the ring cells mirror the width of the first/last cell.
  double width(int i) const;
  double centre(int i) const;
  double lower_face(int i) const;
  double upper_face(int i) const { return lower_face(i) + width(i); }
  const std::vector<double>& faces() const { return m_faces; }

 private:
  std::vector<double> m_faces;
};

class StructuredGrid {
 public:
  explicit StructuredGrid(const deck::Grid& grid);

  const AxisCoordinates& axis(int direction) const { return m_axes[direction]; }
  int cells(int direction) const { return m_axes[direction].cells(); }
  bool periodic(int direction) const { return m_periodic[direction]; }
  std::int64_t domain_cell_count() const;   // nx * ny * nz
  std::int64_t extended_cell_count() const;  // (nx + 2)(ny + 2)(nz + 2)

  Natural natural(const Index3& ijk) const;
  Index3 index3(Natural n) const;
  bool in_domain(const Index3& ijk) const;
  bool in_extended_box(const Index3& ijk) const;
  // Steps `offset` cells, wrapping periodic directions; false when it leaves the extended box
  // (or lands in the ring of a periodic direction, which is never used).
  bool step(const Index3& from, const Index3& offset, Index3& to) const;
  std::array<double, 3> centre(const Index3& ijk) const;
  double volume(const Index3& ijk) const;

 private:
  std::array<AxisCoordinates, 3> m_axes;
  std::array<bool, 3> m_periodic;
  std::array<std::int64_t, 3> m_extent;  // n + 2 per direction
};

}  // namespace bagnold::grid
