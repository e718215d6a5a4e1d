#include "solver/strain_rate.hpp"

#include <cmath>

namespace bagnold::solver {

namespace {
using grid::CellKind;

// Component d of the velocity at the centre of local cell l (needs its − neighbour along d).
double centred(const parallel::Layout& layout, const std::vector<double>& face_velocity, int l,
               int d) {
  const int minus = layout.neighbour(l, 2 * d);
  const double lower = minus >= 0 ? face_velocity[static_cast<std::size_t>(minus)] : 0.0;
  return 0.5 * (face_velocity[static_cast<std::size_t>(l)] + lower);
}
}  // namespace

void compute_strain_rate(const parallel::Domain& domain,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& strain_rate, std::vector<double>& divergence,
                         const std::vector<bool>& no_slip_regions) {
  const auto& layout = domain.layout;
  const auto& g = domain.grid;
  const auto local = static_cast<std::size_t>(layout.local_count());
  strain_rate.assign(local, 0.0);
  divergence.assign(local, 0.0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const auto ijk = layout.index3(l);
    double gradient[3][3] = {};  // gradient[a][b] = ∂u_a/∂x_b
    for (int b = 0; b < 3; ++b) {
      const int minus = layout.neighbour(l, 2 * b), plus = layout.neighbour(l, 2 * b + 1);
      const bool has_minus = minus >= 0 && layout.kind(minus) == CellKind::fluid;
      const bool has_plus = plus >= 0 && layout.kind(plus) == CellKind::fluid;
      // A stationary no-slip wall beside the cell: its ghost value −u_c (the wall's zero half a
      // cell away), so the wall shear enters γ̇ as MFIX's ghost cells put it there.
      auto at_wall = [&](int neighbour) {
        return !no_slip_regions.empty() && neighbour >= 0 && layout.kind(neighbour) == CellKind::boundary &&
               layout.region(neighbour) >= 0 &&
               no_slip_regions[static_cast<std::size_t>(layout.region(neighbour))];
      };
      const bool wall_minus = !has_minus && at_wall(minus), wall_plus = !has_plus && at_wall(plus);
      if (wall_minus || wall_plus) {
        const auto& axis = g.axis(b);
        const double width = axis.width(ijk[static_cast<std::size_t>(b)]);
        // Distance from the centre to the value used on one side: a ghost a width away, a fluid
        // neighbour's centre, or the cell's own value.
        auto side = [&](bool fluid, bool wall, int neighbour) {
          return wall ? width
                 : fluid ? 0.5 * (width + axis.width(layout.index3(neighbour)[static_cast<std::size_t>(b)]))
                         : 0.0;
        };
        for (int a = 0; a < 3; ++a) {
          if (a == b) continue;
          const auto& u = velocity[static_cast<std::size_t>(a)];
          const double own = centred(layout, u, l, a);
          const double lower = wall_minus ? -own : has_minus ? centred(layout, u, minus, a) : own;
          const double upper = wall_plus ? -own : has_plus ? centred(layout, u, plus, a) : own;
          gradient[a][b] = (upper - lower) / (side(has_minus, wall_minus, minus) + side(has_plus, wall_plus, plus));
        }
        continue;
      }
      if (!has_minus && !has_plus) continue;
      const int lo = has_minus ? minus : l, hi = has_plus ? plus : l;
      // Distance between the centres used (periodic wrap: neighbours are a width away).
      const auto& axis = g.axis(b);
      const double distance =
          (has_minus ? 0.5 * (axis.width(ijk[static_cast<std::size_t>(b)]) +
                              axis.width(layout.index3(lo)[static_cast<std::size_t>(b)]))
                     : 0.0) +
          (has_plus ? 0.5 * (axis.width(ijk[static_cast<std::size_t>(b)]) +
                             axis.width(layout.index3(hi)[static_cast<std::size_t>(b)]))
                    : 0.0);
      for (int a = 0; a < 3; ++a) {
        if (a == b) continue;
        const auto& u = velocity[static_cast<std::size_t>(a)];
        gradient[a][b] = (centred(layout, u, hi, a) - centred(layout, u, lo, a)) / distance;
      }
    }
    for (int a = 0; a < 3; ++a) {
      const int minus = layout.neighbour(l, 2 * a);
      const auto& u = velocity[static_cast<std::size_t>(a)];
      const double lower = minus >= 0 ? u[static_cast<std::size_t>(minus)] : 0.0;
      gradient[a][a] = (u[static_cast<std::size_t>(l)] - lower) / g.axis(a).width(ijk[static_cast<std::size_t>(a)]);
    }
    double d_double_dot_d = 0.0;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const double d_ab = 0.5 * (gradient[a][b] + gradient[b][a]);
        d_double_dot_d += d_ab * d_ab;
      }
    strain_rate[static_cast<std::size_t>(l)] = std::sqrt(2.0 * d_double_dot_d);
    divergence[static_cast<std::size_t>(l)] = gradient[0][0] + gradient[1][1] + gradient[2][2];
  }
  parallel::exchange_halo<double>(layout, strain_rate);
  parallel::exchange_halo<double>(layout, divergence);
}

}  // namespace bagnold::solver
