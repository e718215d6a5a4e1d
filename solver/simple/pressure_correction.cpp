// Step 2 of the outer iteration: the pressure correction (SIMPLE).
//
//   1. With u = u* + d (p'_c − p'_n) on every unknown face (d = ε_g A / a_P from step 1) and
//      p' = 0 in pressure-boundary cells, continuity in each fluid cell P becomes
//        Σ_faces ρ ε_g A d (p'_P − p'_nb) = −Σ_faces ρ ε_g A u*_out,
//      symmetric positive (semi-)definite: CG with algebraic multigrid (GAMG or BoomerAMG); a
//      closed domain has the constant null space, removed in the solve.
//   2. P += α_p p' in fluid cells; u += d (p'_c − p'_n) on unknown faces; exchange the halo.
// Returns the mass imbalance before the correction, Σ|Σ_faces F_out| / Σ ½ Σ_faces |F| (at least
// the flux of the residual velocity scale through every face).
#include <algorithm>
#include <cmath>

#include "solver/simple/gas_solver.hpp"

namespace bagnold::solver {

double GasSolver::correct_pressure(run::FlowState& state) {
  const auto& layout = m_domain.layout;
  const double rho = m_deck.gas.density;
  const auto& numbering = *m_pressure_numbering;
  double imbalance = 0.0, throughput = 0.0;
  m_worst_value[3] = 0.0;
  m_worst_local[3] = -1;

  for (const int l : numbering.owned_locals) {
    double a_p = 0.0, b = 0.0;
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    for (int face = 0; face < 6; ++face) {
      const int d = parallel::face_direction(face);
      const int s = parallel::face_sign(face);
      const int m = layout.neighbour(l, face);
      const int owner = s > 0 ? l : m;  // the cell that owns this face's velocity
      if (owner < 0) continue;
      const auto uo = static_cast<std::size_t>(owner);
      const double area = face_fraction(state, owner, d) * face_area(l, d);  // open to the gas
      const double flux_out = s * rho * area * state.gas_velocity[static_cast<std::size_t>(d)][uo];
      b -= flux_out;
      throughput += 0.5 * std::abs(flux_out);
      if (m_faces.kind[static_cast<std::size_t>(d)][uo] != FaceClass::unknown) continue;
      const double coefficient = rho * area * m_d[static_cast<std::size_t>(d)][uo];
      a_p += coefficient;
      if (layout.kind(m) == grid::CellKind::fluid) {
        columns[count] = numbering.global[static_cast<std::size_t>(m)];
        values[count++] = -coefficient;
      }
    }
    imbalance += std::abs(b);
    if (!(std::abs(b) <= m_worst_value[3])) {
      m_worst_value[3] = std::isnan(b) ? INFINITY : std::abs(b);
      m_worst_local[3] = l;
    }
    columns[count] = numbering.global[static_cast<std::size_t>(l)];
    values[count++] = a_p;
    m_pressure_system->set_row(numbering.global[static_cast<std::size_t>(l)], columns, values, count, b);
  }

  std::vector<double> x(static_cast<std::size_t>(numbering.owned_rows()), 0.0);
  m_pressure_system->solve(x);
  std::vector<double> correction(static_cast<std::size_t>(layout.local_count()), 0.0);
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    correction[static_cast<std::size_t>(numbering.owned_locals[row])] = x[row];
  parallel::exchange_halo<double>(layout, correction);

  const double alpha_p = m_deck.numerics.relax_pressure;
  for (const int l : numbering.owned_locals)
    state.gas_pressure[static_cast<std::size_t>(l)] += alpha_p * correction[static_cast<std::size_t>(l)];
  parallel::exchange_halo<double>(layout, state.gas_pressure);
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    auto& u = state.gas_velocity[ud];
    for (const int l : m_velocity_numbering[ud]->owned_locals) {
      const int n = layout.neighbour(l, 2 * d + 1);
      u[static_cast<std::size_t>(l)] += m_d[ud][static_cast<std::size_t>(l)] *
                                        (correction[static_cast<std::size_t>(l)] -
                                         correction[static_cast<std::size_t>(n)]);
    }
    parallel::exchange_halo<double>(layout, u);
  }

  const double total_imbalance = layout.comm().sum(imbalance);
  // A flow at rest has no throughput: measure against the flux the velocity scale would carry.
  const double total_throughput =
      std::max(layout.comm().sum(throughput), m_reference_flux * m_velocity_scale);
  return total_imbalance <= 1e-300 ? 0.0 : total_imbalance / total_throughput;
}

}  // namespace bagnold::solver
