#include "src/grid/structured_grid.hpp"

#include <cmath>

namespace bagnold::grid {

AxisCoordinates::AxisCoordinates(const deck::Axis& axis) {
  const int n = axis.cells;
  const double length = axis.max - axis.min;
  // Geometric widths w_i = w_0 q^i with q^(n-1) = ratio, scaled to the length.
  const double q = n > 1 ? std::pow(axis.ratio, 1.0 / (n - 1)) : 1.0;
  std::vector<double> widths(static_cast<std::size_t>(n));
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += widths[static_cast<std::size_t>(i)] = std::pow(q, i);
  m_faces.resize(static_cast<std::size_t>(n) + 1);
  m_faces[0] = axis.min;
  for (int i = 0; i < n; ++i)
    m_faces[static_cast<std::size_t>(i) + 1] =
        m_faces[static_cast<std::size_t>(i)] + length * widths[static_cast<std::size_t>(i)] / sum;
  m_faces.back() = axis.max;  // exact end despite round-off
}

double AxisCoordinates::width(int i) const {
  const int n = cells();
  if (i < 0) i = 0;
  if (i >= n) i = n - 1;
  return m_faces[static_cast<std::size_t>(i) + 1] - m_faces[static_cast<std::size_t>(i)];
}

double AxisCoordinates::lower_face(int i) const {
  if (i < 0) return m_faces.front() - width(-1);
  return m_faces[static_cast<std::size_t>(i)];
}

double AxisCoordinates::centre(int i) const { return lower_face(i) + 0.5 * width(i); }

StructuredGrid::StructuredGrid(const deck::Grid& grid)
    : m_axes{AxisCoordinates(grid.x), AxisCoordinates(grid.y), AxisCoordinates(grid.z)} {
  for (int d = 0; d < 3; ++d) {
    m_periodic[d] = grid.is_periodic(d);
    m_extent[d] = m_axes[d].cells() + 2;
  }
}

std::int64_t StructuredGrid::domain_cell_count() const {
  return std::int64_t{cells(0)} * cells(1) * cells(2);
}

std::int64_t StructuredGrid::extended_cell_count() const {
  return m_extent[0] * m_extent[1] * m_extent[2];
}

Natural StructuredGrid::natural(const Index3& ijk) const {
  return (ijk[0] + 1) + m_extent[0] * ((ijk[1] + 1) + m_extent[1] * (ijk[2] + 1));
}

Index3 StructuredGrid::index3(Natural n) const {
  const int i = static_cast<int>(n % m_extent[0]);
  n /= m_extent[0];
  const int j = static_cast<int>(n % m_extent[1]);
  const int k = static_cast<int>(n / m_extent[1]);
  return {i - 1, j - 1, k - 1};
}

bool StructuredGrid::in_domain(const Index3& ijk) const {
  for (int d = 0; d < 3; ++d)
    if (ijk[d] < 0 || ijk[d] >= cells(d)) return false;
  return true;
}

bool StructuredGrid::in_extended_box(const Index3& ijk) const {
  for (int d = 0; d < 3; ++d)
    if (ijk[d] < -1 || ijk[d] > cells(d)) return false;
  return true;
}

bool StructuredGrid::step(const Index3& from, const Index3& offset, Index3& to) const {
  for (int d = 0; d < 3; ++d) {
    int c = from[d] + offset[d];
    const int n = cells(d);
    if (m_periodic[d]) {
      c = ((c % n) + n) % n;
    } else if (c < -1 || c > n) {
      return false;
    }
    to[d] = c;
  }
  return true;
}

std::array<double, 3> StructuredGrid::centre(const Index3& ijk) const {
  return {m_axes[0].centre(ijk[0]), m_axes[1].centre(ijk[1]), m_axes[2].centre(ijk[2])};
}

double StructuredGrid::volume(const Index3& ijk) const {
  return m_axes[0].width(ijk[0]) * m_axes[1].width(ijk[1]) * m_axes[2].width(ijk[2]);
}

}  // namespace bagnold::grid
