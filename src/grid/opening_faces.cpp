#include "src/grid/opening_faces.hpp"

namespace bagnold::grid {

bool is_opening(BoundaryType type) {
  return type == BoundaryType::pressure_outflow || type == BoundaryType::pressure_inflow ||
         type == BoundaryType::mass_inflow;
}

bool is_pressure_opening(BoundaryType type) {
  return type == BoundaryType::pressure_outflow || type == BoundaryType::pressure_inflow;
}

bool is_opening_cell(const CellFlags& flags, const BoundaryRegions& regions, Natural n) {
  const auto i = static_cast<std::size_t>(n);
  const int r = flags.region[i];
  return flags.kind[i] == CellKind::boundary && r >= 0 && is_opening(regions.types[static_cast<std::size_t>(r)]);
}

namespace {

// The four corners of the face normal to d at coordinate `at`, spanning the fluid cell's extent
// along the two other axes, counter-clockwise seen from +d.
std::array<std::array<double, 3>, 4> face_corners(const StructuredGrid& grid, const Index3& fluid,
                                                  int d, double at) {
  const int a = (d + 1) % 3, b = (d + 2) % 3;
  const auto& axis_a = grid.axis(a);
  const auto& axis_b = grid.axis(b);
  const double a0 = axis_a.lower_face(fluid[static_cast<std::size_t>(a)]);
  const double a1 = axis_a.upper_face(fluid[static_cast<std::size_t>(a)]);
  const double b0 = axis_b.lower_face(fluid[static_cast<std::size_t>(b)]);
  const double b1 = axis_b.upper_face(fluid[static_cast<std::size_t>(b)]);
  std::array<std::array<double, 3>, 4> corners{};
  const double along_a[4] = {a0, a1, a1, a0};
  const double along_b[4] = {b0, b0, b1, b1};
  for (int c = 0; c < 4; ++c) {
    auto& p = corners[static_cast<std::size_t>(c)];
    p[static_cast<std::size_t>(d)] = at;
    p[static_cast<std::size_t>(a)] = along_a[c];
    p[static_cast<std::size_t>(b)] = along_b[c];
  }
  return corners;
}

}  // namespace

std::vector<OpeningFace> opening_faces(const StructuredGrid& grid, const CellFlags& flags,
                                       const BoundaryRegions& regions) {
  std::vector<OpeningFace> out;
  const auto kind = [&](Natural n) { return flags.kind[static_cast<std::size_t>(n)]; };
  const auto opening_region = [&](Natural n) {
    return is_opening_cell(flags, regions, n) ? flags.region[static_cast<std::size_t>(n)] : -1;
  };
  for (Natural c = 0; c < static_cast<Natural>(flags.kind.size()); ++c) {
    if (kind(c) == CellKind::excluded) continue;
    const Index3 from = grid.index3(c);
    for (int d = 0; d < 3; ++d) {
      Index3 offset{0, 0, 0}, to;
      offset[static_cast<std::size_t>(d)] = 1;
      if (!grid.step(from, offset, to)) continue;
      const Natural n = grid.natural(to);
      OpeningFace face;
      face.owner = c;
      face.direction = d;
      if (kind(c) == CellKind::fluid && (face.region = opening_region(n)) >= 0) {
        face.fluid = c;
        face.outward_sign = 1;
      } else if (kind(n) == CellKind::fluid && (face.region = opening_region(c)) >= 0) {
        face.fluid = n;
        face.outward_sign = -1;
      } else {
        continue;
      }
      const Index3 fluid = grid.index3(face.fluid);
      const auto& axis = grid.axis(d);
      // The face is the owner's + face; a periodic wrap puts it at the domain's upper end.
      const double at = face.outward_sign > 0 ? axis.upper_face(fluid[static_cast<std::size_t>(d)])
                                              : axis.lower_face(fluid[static_cast<std::size_t>(d)]);
      face.corners = face_corners(grid, fluid, d, at);
      out.push_back(face);
    }
  }
  return out;
}

}  // namespace bagnold::grid
