#include "solver/strain_rate.hpp"

#include "src/grid/opening_faces.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

using grid::CellKind;

void compute_strain_rate(const Discretization& discretization,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& strain_rate, std::vector<double>& divergence,
                         const std::vector<WallGhost>& wall_ghosts, StrainTensor* tensor) {
  const auto& layout = discretization.layout();
  const auto local = static_cast<std::size_t>(layout.local_count());
  strain_rate.assign(local, 0.0);
  divergence.assign(local, 0.0);
  if (tensor)
    for (auto& component : *tensor) component.assign(local, 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    double gradient[3][3] = {};  // gradient[a][b] = ∂u_a/∂x_b
    for (int b = 0; b < 3; ++b) {
      const int minus = layout.neighbour(l, 2 * b), plus = layout.neighbour(l, 2 * b + 1);
      const double width = discretization.width(l, b);
      // What each side contributes: a fluid neighbour its centre value, half the two widths
      // away (periodic wrap: a width away); a boundary cell with a no-slip ghost in wall_ghosts
      // the value −u_c a width away (the wall's zero half a cell away, as MFIX's ghost cells put
      // the wall shear into γ̇), with a mirror ghost +u_c a width away; anything else the
      // cell's own value at no distance (a one-sided difference).
      enum class Side { fluid, wall, mirror, none };
      auto side_of = [&](int neighbour) {
        if (neighbour < 0) return Side::none;
        if (layout.kind(neighbour) == CellKind::fluid) return Side::fluid;
        const WallGhost ghost = wall_ghosts.empty() ? WallGhost::none : wall_ghosts[static_cast<std::size_t>(neighbour)];
        return ghost == WallGhost::no_slip ? Side::wall : ghost == WallGhost::mirror ? Side::mirror : Side::none;
      };
      auto distance = [&](Side side, int neighbour) {
        return side == Side::fluid ? 0.5 * (width + discretization.width(neighbour, b))
               : side == Side::none ? 0.0 : width;
      };
      const Side lower_side = side_of(minus), upper_side = side_of(plus);
      if (lower_side == Side::none && upper_side == Side::none) continue;
      const double span = distance(lower_side, minus) + distance(upper_side, plus);
      for (int a = 0; a < 3; ++a) {
        if (a == b) continue;
        const auto& u = velocity[static_cast<std::size_t>(a)];
        const double own = centre_velocity(layout, u, l, a);
        auto value = [&](Side side, int neighbour) {
          return side == Side::fluid ? centre_velocity(layout, u, neighbour, a) : side == Side::wall ? -own : own;
        };
        gradient[a][b] = (value(upper_side, plus) - value(lower_side, minus)) / span;
      }
    }
    for (int a = 0; a < 3; ++a) {
      const int minus = layout.neighbour(l, 2 * a);
      const auto& u = velocity[static_cast<std::size_t>(a)];
      const double lower = minus >= 0 ? u[static_cast<std::size_t>(minus)] : 0.0;
      gradient[a][a] = (u[static_cast<std::size_t>(l)] - lower) / discretization.width(l, a);
    }
    double d_double_dot_d = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double d_ab = 0.5 * (gradient[a][b] + gradient[b][a]);
        d_double_dot_d += d_ab * d_ab;
        if (tensor && a <= b) (*tensor)[static_cast<std::size_t>(symmetric_component(a, b))][static_cast<std::size_t>(l)] = d_ab;
      }
    strain_rate[static_cast<std::size_t>(l)] = std::sqrt(2.0 * d_double_dot_d);
    divergence[static_cast<std::size_t>(l)] = gradient[0][0] + gradient[1][1] + gradient[2][2];
  }
  parallel::exchange_halo<double>(layout, strain_rate);
  parallel::exchange_halo<double>(layout, divergence);
  if (tensor)
    for (auto& component : *tensor) parallel::exchange_halo<double>(layout, component);
}

std::vector<WallGhost> strain_rate_ghosts(const parallel::Domain& domain,
                                        const std::vector<bool>& wall_shear_regions, bool beside_openings,
                                        bool copy_into_openings) {
  std::vector<WallGhost> flagged;
  if (!copy_into_openings &&
      std::find(wall_shear_regions.begin(), wall_shear_regions.end(), true) == wall_shear_regions.end())
    return flagged;
  const auto& layout = domain.layout;
  const auto& grid = domain.grid;
  auto is_opening = [&](grid::Natural n) { return grid::is_opening_cell(domain.flags, domain.regions, n); };
  flagged.assign(static_cast<std::size_t>(layout.local_count()), WallGhost::none);
  for (int l = 0; l < layout.local_count(); ++l) {
    if (layout.kind(l) != CellKind::boundary) continue;
    const int region = layout.region(l);
    if (region < 0) continue;
    if (copy_into_openings && grid::is_pressure_opening(domain.regions.types[static_cast<std::size_t>(region)])) {
      flagged[static_cast<std::size_t>(l)] = WallGhost::mirror;
      continue;
    }
    if (static_cast<std::size_t>(region) >= wall_shear_regions.size() ||
        !wall_shear_regions[static_cast<std::size_t>(region)])
      continue;
    bool beside_opening = false;
    if (!beside_openings) {
      const grid::Index3 ijk = layout.index3(l);
      for (int face = 0; face < 6 && !beside_opening; ++face) {
        grid::Index3 offset{0, 0, 0}, to{};
        offset[static_cast<std::size_t>(face / 2)] = face % 2 == 0 ? -1 : 1;
        beside_opening = grid.step(ijk, offset, to) && is_opening(grid.natural(to));
      }
    }
    flagged[static_cast<std::size_t>(l)] = beside_opening ? WallGhost::mirror : WallGhost::no_slip;
  }
  return flagged;
}

}  // namespace bagnold::solver
