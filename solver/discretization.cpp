// The per-rank discretization (discretization.hpp): widths, face classes, numberings.
#include "solver/discretization.hpp"

#include "src/grid/opening_faces.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

Discretization::Discretization(const parallel::Domain& domain) : m_domain(domain) {
  const auto& layout = domain.layout;
  const auto local = static_cast<std::size_t>(layout.local_count());
  m_width.resize(3 * local);
  m_opening.resize(local);
  m_pressure_opening_fluid.assign(local, -1);
  for (std::size_t l = 0; l < local; ++l) {
    const auto natural = layout.natural(static_cast<int>(l));
    m_opening[l] = grid::is_opening_cell(domain.flags, domain.regions, natural) ? 1 : 0;
    const int region = domain.flags.region[static_cast<std::size_t>(natural)];
    if (m_opening[l] && grid::is_pressure_opening(domain.regions.types[static_cast<std::size_t>(region)]))
      // The last fluid neighbour in the order −x, +x, −y, +y, −z, +z: MFIX's SET_OUTFLOW copies
      // from each fluid neighbour in that order (W, E, S, N, B, T), so the last one stands.
      for (int face = 0; face < 6; ++face) {
        const int n = layout.neighbour(static_cast<int>(l), face);
        if (n >= 0 && layout.kind(n) == grid::CellKind::fluid) m_pressure_opening_fluid[l] = n;
      }
    const auto ijk = layout.index3(static_cast<int>(l));
    for (int d = 0; d < 3; ++d)
      m_width[3 * l + static_cast<std::size_t>(d)] = domain.grid.axis(d).width(ijk[static_cast<std::size_t>(d)]);
  }
  m_faces[gas] = std::make_unique<VelocityFaces>(domain, false);
  m_faces[solids] = std::make_unique<VelocityFaces>(domain, true);
  for (int d = 0; d < 3; ++d) {
    const auto& kind = faces(gas).kind[static_cast<std::size_t>(d)];
    m_velocity_numbering[static_cast<std::size_t>(d)] = std::make_unique<UnknownNumbering>(
        layout, [&](int l) { return kind[static_cast<std::size_t>(l)] == FaceClass::unknown; });
  }
  m_cell_numbering = std::make_unique<UnknownNumbering>(
      layout, [&](int l) { return layout.kind(l) == grid::CellKind::fluid; });
  double faces_area = 0.0;
  double smallest = INFINITY;
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    for (int d = 0; d < 3; ++d) faces_area += face_area(l, d);  // ½ Σ over the 6 faces
  for (int d = 0; d < 3; ++d)
    for (int l = 0; l < layout.owned_fluid_count(); ++l) smallest = std::min(smallest, width(l, d));
  m_reference_area = layout.comm().sum(faces_area);
  m_smallest_width = smallest;
}

SparsityPattern Discretization::momentum_pattern(int d) const {
  const auto& numbering = velocity_numbering(d);
  const auto& links = faces(gas).links[static_cast<std::size_t>(d)];
  SparsityPattern pattern;
  for (const int l : numbering.owned_locals) {
    std::int64_t columns[7];
    int count = 0;
    for (int face = 0; face < 6; ++face) {
      const Link& link = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face)];
      if (link.kind == LinkKind::unknown) columns[count++] = numbering.global[static_cast<std::size_t>(link.local)];
    }
    columns[count++] = numbering.global[static_cast<std::size_t>(l)];
    pattern.add_row(columns, count);
  }
  return pattern;
}

SparsityPattern Discretization::cell_pattern(Phase phase) const {
  const auto& numbering = cell_numbering();
  const auto& kind = faces(phase).kind;
  SparsityPattern pattern;
  for (const int l : numbering.owned_locals) {
    std::int64_t columns[7];
    int count = 0;
    for_each_cell_face(*this, l, [&](const CellFace& f) {
      if (kind[static_cast<std::size_t>(f.direction)][static_cast<std::size_t>(f.owner)] != FaceClass::unknown) return;
      if (layout().kind(f.neighbour) == grid::CellKind::fluid)
        columns[count++] = numbering.global[static_cast<std::size_t>(f.neighbour)];
    });
    columns[count++] = numbering.global[static_cast<std::size_t>(l)];
    pattern.add_row(columns, count);
  }
  return pattern;
}

void velocity_divergence(const Discretization& discretization,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& divergence) {
  const auto& layout = discretization.layout();
  std::fill(divergence.begin(), divergence.end(), 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    double net = 0.0;
    for_each_cell_face(discretization, l, [&](const CellFace& f) { net += f.sign * f.area * f.of(velocity); });
    divergence[static_cast<std::size_t>(l)] = net / discretization.volume(l);
  }
  parallel::exchange_halo<double>(layout, divergence);
}

}  // namespace bagnold::solver
