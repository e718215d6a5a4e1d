#include "solver/velocity_faces.hpp"

#include "src/grid/opening_faces.hpp"

namespace bagnold::solver {

namespace {
using grid::BoundaryType;
using grid::CellKind;

struct Classifier {
  const parallel::Domain& domain;
  bool solids;  // the solids phase: a mass inflow brings the solids' velocity

  const std::array<double, 3>& inflow_velocity(const deck::BoundaryRegion& r) const {
    return solids ? r.solids_velocity : r.gas_velocity;
  }

  CellKind kind_at(grid::Natural n) const { return domain.flags.kind[static_cast<std::size_t>(n)]; }
  const deck::BoundaryRegion& region_at(grid::Natural n) const {
    return domain.regions.regions[static_cast<std::size_t>(domain.flags.region[static_cast<std::size_t>(n)])];
  }
  BoundaryType type_at(grid::Natural n) const {
    return domain.regions.types[static_cast<std::size_t>(domain.flags.region[static_cast<std::size_t>(n)])];
  }
  // The + neighbour along d, or -1 outside the extended box.
  grid::Natural plus(grid::Natural c, int d) const {
    grid::Index3 offset{0, 0, 0}, to;
    offset[static_cast<std::size_t>(d)] = 1;
    return domain.grid.step(domain.grid.index3(c), offset, to) ? domain.grid.natural(to) : -1;
  }

  // Class and fixed value of the face velocity owned by cell c along d.
  std::pair<FaceClass, double> classify(grid::Natural c, int d) const {
    const grid::Natural n = plus(c, d);
    if (n < 0) return {FaceClass::none, 0.0};
    const CellKind kc = kind_at(c), kn = kind_at(n);
    if (kc == CellKind::fluid && kn == CellKind::fluid) return {FaceClass::unknown, 0.0};
    if (kc == CellKind::fluid && kn == CellKind::boundary) return open_or_fixed(n, d);
    if (kc == CellKind::boundary && kn == CellKind::fluid) return open_or_fixed(c, d);
    return {FaceClass::none, 0.0};
  }
  std::pair<FaceClass, double> open_or_fixed(grid::Natural boundary, int d) const {
    const BoundaryType t = type_at(boundary);
    if (grid::is_pressure_opening(t)) return {FaceClass::unknown, 0.0};
    const auto& r = region_at(boundary);
    if (t == BoundaryType::mass_inflow) return {FaceClass::fixed, inflow_velocity(r)[static_cast<std::size_t>(d)]};
    if (t == BoundaryType::moving_wall) return {FaceClass::fixed, r.wall_velocity[static_cast<std::size_t>(d)]};
    return {FaceClass::fixed, 0.0};
  }

  // The tangential condition that a face velocity along d sees across a non-unknown neighbour
  // face owned by cell `other` (c' = other, n' = its + neighbour along d).
  Link side_condition(grid::Natural other, int d) const {
    Link link;
    grid::Natural boundary = -1;
    if (other >= 0 && kind_at(other) == CellKind::boundary) {
      boundary = other;
    } else if (other >= 0) {
      const grid::Natural n = plus(other, d);
      if (n >= 0 && kind_at(n) == CellKind::boundary) boundary = n;
    }
    if (boundary < 0) return link;  // nothing there: zero gradient
    const auto& r = region_at(boundary);
    link.region = domain.flags.region[static_cast<std::size_t>(boundary)];
    switch (type_at(boundary)) {
      case BoundaryType::no_slip_wall: link.kind = LinkKind::wall; break;
      case BoundaryType::moving_wall:
        link.kind = LinkKind::wall;
        link.value = r.wall_velocity[static_cast<std::size_t>(d)];
        break;
      case BoundaryType::mass_inflow:
        link.kind = LinkKind::wall;
        link.value = inflow_velocity(r)[static_cast<std::size_t>(d)];
        break;
      default: break;  // free slip, pressure boundaries: zero gradient
    }
    return link;
  }
};
}  // namespace

VelocityFaces::VelocityFaces(const parallel::Domain& domain, bool solids_phase) {
  const auto& layout = domain.layout;
  const auto local = static_cast<std::size_t>(layout.local_count());
  const Classifier classifier{domain, solids_phase};
  for (int d = 0; d < 3; ++d) {
    auto& k = kind[static_cast<std::size_t>(d)];
    auto& v = fixed_value[static_cast<std::size_t>(d)];
    k.assign(local, FaceClass::none);
    v.assign(local, 0.0);
    for (std::size_t l = 0; l < local; ++l) {
      const auto [c, value] = classifier.classify(layout.natural(static_cast<int>(l)), d);
      k[l] = c;
      v[l] = value;
    }
  }
  for (int d = 0; d < 3; ++d) {
    auto& links_d = links[static_cast<std::size_t>(d)];
    links_d.assign(6 * local, Link{});
    for (std::size_t l = 0; l < local; ++l) {
      if (kind[static_cast<std::size_t>(d)][l] != FaceClass::unknown) continue;
      for (int face = 0; face < 6; ++face) {
        Link& link = links_d[6 * l + static_cast<std::size_t>(face)];
        const int m = layout.neighbour(static_cast<int>(l), face);
        const FaceClass mk = m >= 0 ? kind[static_cast<std::size_t>(d)][static_cast<std::size_t>(m)] : FaceClass::none;
        if (mk == FaceClass::unknown) {
          link = {m, LinkKind::unknown, 0.0};
        } else if (mk == FaceClass::fixed) {
          link = {m, LinkKind::fixed, fixed_value[static_cast<std::size_t>(d)][static_cast<std::size_t>(m)]};
        } else if (parallel::face_direction(face) == d) {
          link = {m, LinkKind::zero_gradient, 0.0};  // open end of an outflow face
        } else {
          // Across a wall: find the cell that would own the neighbour face, globally.
          grid::Index3 offset{0, 0, 0}, to;
          offset[static_cast<std::size_t>(parallel::face_direction(face))] = parallel::face_sign(face);
          const grid::Natural other = domain.grid.step(layout.index3(static_cast<int>(l)), offset, to)
                                          ? domain.grid.natural(to) : -1;
          link = classifier.side_condition(other, d);
          link.local = m;
          if (link.kind != LinkKind::wall) link.region = -1;
        }
      }
    }
  }
  pressure_boundary.assign(local, 0);
  boundary_pressure.assign(local, 0.0);
  for (std::size_t l = 0; l < local; ++l) {
    if (layout.kind(static_cast<int>(l)) != CellKind::boundary) continue;
    const auto t = domain.regions.types[static_cast<std::size_t>(layout.region(static_cast<int>(l)))];
    if (grid::is_pressure_opening(t)) {
      pressure_boundary[l] = 1;
      boundary_pressure[l] = domain.regions.regions[static_cast<std::size_t>(layout.region(static_cast<int>(l)))].pressure;
    }
  }
  for (std::size_t r = 0; r < domain.regions.types.size(); ++r)
    has_pressure_boundary = has_pressure_boundary || (grid::is_pressure_opening(domain.regions.types[r]) &&
                                                      domain.flags.boundary_count > 0);
}

}  // namespace bagnold::solver
