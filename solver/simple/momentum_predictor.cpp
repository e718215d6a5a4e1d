// Step 1 of the outer iteration: the momentum predictor for one velocity component d.
//
//   1. For each unknown face velocity u_P (control volume between the centres of its owning
//      cell c and c's + neighbour n), and each of its six faces:
//        F  outward mass flux through the face, from the current iterate;
//        D  μ A / δ, with δ the distance to the neighbour (half a cell to a wall);
//        a_nb = D + max(−F, 0),  a_P += D + max(F, 0)         (first-order upwind, implicit);
//        b −= F (φ_f^TVD − φ_upwind)                           (TVD by deferred correction).
//   2. Sources: ε_g (P_c − P_n) A, ε_g ρ g_d V, drag β V (u_s − u_P) (implicit in u_P), and the
//      implicit-Euler term ε_g ρ V / dt (u_P − u_P^old). Fluxes and diffusion carry ε_g too.
//   3. Under-relaxation (Patankar): a_P ← a_P / α_u, b ← b + (1 − α_u) a_P u_P*.
//   4. d = ε_g A / a_P for the pressure correction; solve; exchange the halo.
//   (SIMPLEC, the default: d = A / (a_P − Σ a_nb), with no pressure under-relaxation needed.)
// Returns Σ|b + Σ a_nb u_nb − a_P u_P| / Σ a_P U before the solve (U: the step's residual velocity scale).
#include <algorithm>
#include <cmath>

#include "solver/simple/gas_solver.hpp"

namespace bagnold::solver {

double GasSolver::predict_momentum(int d, run::FlowState& state, const run::FlowState& old,
                                   double dt) {
  const auto& layout = m_domain.layout;
  const auto ud = static_cast<std::size_t>(d);
  const double rho = m_deck.gas.density;
  const double mu = m_deck.gas.viscosity;
  const double alpha = m_deck.numerics.relax_velocity;
  auto& u = state.gas_velocity[ud];
  const auto& u_old = old.gas_velocity[ud];
  const auto& pressure = state.gas_pressure;
  const auto& links = m_faces.links[ud];
  const auto& kind = m_faces.kind[ud];
  const auto& numbering = *m_velocity_numbering[ud];
  auto& d_coefficient = m_d[ud];
  auto at = [&](int local) { return u[static_cast<std::size_t>(local)]; };
  if (numbering.total_rows == 0) return 0.0;  // e.g. no fluid faces along d
  const double velocity_scale = m_velocity_scale;

  double residual_sum = 0.0, norm_sum = 0.0;
  m_worst_value[ud] = 0.0;
  m_worst_local[ud] = -1;
  std::vector<double> x(static_cast<std::size_t>(numbering.owned_rows()));
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row) {
    const int l = numbering.owned_locals[row];
    const int n = layout.neighbour(l, 2 * d + 1);
    const double half_c = 0.5 * width(l, d), half_n = 0.5 * width(n, d);
    const double area_d = face_area(l, d);
    const double volume = (half_c + half_n) * area_d;
    const double fraction = face_fraction(state, l, d);  // ε_g at this face velocity
    const auto& eps = state.gas_fraction;
    double a_p = 0.0, b = 0.0, neighbours_u = 0.0, neighbours_a = 0.0;
    std::int64_t columns[7];
    double values[7];
    int count = 0;

    for (int face = 0; face < 6; ++face) {
      const Link& link = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face)];
      const int e = parallel::face_direction(face);
      const int s = parallel::face_sign(face);
      double flux_out = 0.0, diffusion = 0.0;
      if (e == d) {
        // The control-volume face at the centre of n (s > 0) or of c (s < 0).
        const bool has_far = link.kind == LinkKind::unknown || link.kind == LinkKind::fixed;
        const double centre_fraction = eps[static_cast<std::size_t>(s > 0 ? n : l)];
        flux_out = s * rho * centre_fraction * area_d * 0.5 * (at(l) + (has_far ? at(link.local) : at(l)));
        diffusion = has_far ? fraction * mu * area_d / (s > 0 ? width(n, d) : width(l, d)) : 0.0;
      } else {
        // The face between the owning cells' faces along e: half of c's and half of n's.
        const int t = 3 - d - e;
        const auto& v = state.gas_velocity[static_cast<std::size_t>(e)];
        const int cv = s > 0 ? l : layout.neighbour(l, face);
        const int nv = s > 0 ? n : layout.neighbour(n, face);
        // Mass flux through those half faces: ε_g on each of them.
        const double vc = cv >= 0 ? v[static_cast<std::size_t>(cv)] * face_fraction(state, cv, e) : 0.0;
        const double vn = nv >= 0 ? v[static_cast<std::size_t>(nv)] * face_fraction(state, nv, e) : 0.0;
        flux_out = s * rho * (vc * half_c + vn * half_n) * width(l, t);
        const double area = (half_c + half_n) * width(l, t);
        if (link.kind == LinkKind::wall) {
          diffusion = fraction * mu * area / (0.5 * width(l, e));
        } else if (link.kind != LinkKind::zero_gradient) {
          diffusion = fraction * mu * area / (0.5 * (width(l, e) + width(link.local, e)));
        }
      }

      switch (link.kind) {
        case LinkKind::unknown: {
          const double a_nb = diffusion + std::max(-flux_out, 0.0);
          a_p += diffusion + std::max(flux_out, 0.0);
          columns[count] = numbering.global[static_cast<std::size_t>(link.local)];
          values[count++] = -a_nb;
          neighbours_u += a_nb * at(link.local);
          neighbours_a += a_nb;
          if (m_limiter != Limiter::upwind) {
            double upwind_upwind, upwind, downwind;
            if (flux_out > 0.0) {
              const Link& back = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face ^ 1)];
              upwind = at(l);
              downwind = at(link.local);
              upwind_upwind = back.kind == LinkKind::wall ? back.value
                              : back.kind == LinkKind::zero_gradient ? at(l) : at(back.local);
            } else {
              const int beyond = layout.neighbour(link.local, face);
              upwind = at(link.local);
              downwind = at(l);
              upwind_upwind = (beyond >= 0 && kind[static_cast<std::size_t>(beyond)] != FaceClass::none)
                                  ? at(beyond) : upwind;
            }
            b -= flux_out * tvd_correction(m_limiter, upwind_upwind, upwind, downwind);
          }
          break;
        }
        case LinkKind::fixed:
        case LinkKind::wall: {
          const double value = link.kind == LinkKind::fixed ? at(link.local) : link.value;
          const double a_nb = diffusion + std::max(-flux_out, 0.0);
          a_p += diffusion + std::max(flux_out, 0.0);
          b += a_nb * value;
          break;
        }
        case LinkKind::zero_gradient:
          // Open end: outflow leaves with u_P; inflow brings u_P in, lagged.
          a_p += std::max(flux_out, 0.0);
          b += std::max(-flux_out, 0.0) * at(l);
          break;
      }
    }

    b += fraction * (pressure[static_cast<std::size_t>(l)] - pressure[static_cast<std::size_t>(n)]) * area_d;
    b += fraction * rho * m_deck.physics.gravity[ud] * volume;
    if (!m_source[ud].empty()) b += m_source[ud][static_cast<std::size_t>(l)] * volume;
    const double a_transient = fraction * rho * volume / dt;
    a_p += a_transient;
    b += a_transient * u_old[static_cast<std::size_t>(l)];
    // Drag towards the solids velocity, implicit in u: β (u_s − u) V, β interpolated to the face.
    const double beta = (m_beta[static_cast<std::size_t>(l)] * half_n + m_beta[static_cast<std::size_t>(n)] * half_c) /
                        (half_c + half_n);
    a_p += beta * volume;
    b += beta * volume * state.solids_velocity[ud][static_cast<std::size_t>(l)];

    const double u_p = at(l);
    const double row_residual = std::abs(b + neighbours_u - a_p * u_p);
    residual_sum += row_residual;
    if (!(row_residual <= m_worst_value[ud])) {  // NaN is the worst
      m_worst_value[ud] = std::isnan(row_residual) ? INFINITY : row_residual;
      m_worst_local[ud] = l;
    }
    norm_sum += a_p * velocity_scale;

    const double a_relaxed = a_p / alpha;
    // SIMPLEC drops the neighbours' corrections consistently: d = A / (a_P − Σ a_nb).
    const double a_for_d = m_simplec && a_relaxed - neighbours_a > 1e-12 * a_relaxed
                               ? a_relaxed - neighbours_a : a_relaxed;
    d_coefficient[static_cast<std::size_t>(l)] = fraction * area_d / a_for_d;
    columns[count] = numbering.global[static_cast<std::size_t>(l)];
    values[count++] = a_relaxed;
    m_momentum_system[ud]->set_row(numbering.global[static_cast<std::size_t>(l)], columns, values,
                                   count, b + (1.0 - alpha) * a_relaxed * u_p);
    x[row] = u_p;
  }

  m_momentum_system[ud]->solve(x);
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    u[static_cast<std::size_t>(numbering.owned_locals[row])] = x[row];
  parallel::exchange_halo<double>(layout, u);
  parallel::exchange_halo<double>(layout, d_coefficient);

  const double residual = layout.comm().sum(residual_sum);
  const double norm = layout.comm().sum(norm_sum);
  return residual <= 1e-300 ? 0.0 : residual / std::max(norm, 1e-300);
}

}  // namespace bagnold::solver
