// Step 2 of the outer iteration: the pressure correction from the mixture volume continuity.
//
// Both phases are incompressible and ε_g + ε_s = 1, so the sum of their continuity equations is
// ∇·(ε_g u_g + ε_s u_s) = 0 (the transient terms cancel). With, on every unknown face,
// u_m = u*_m + d_m (p'_c − p'_n) (d_m from the predictors' 2 × 2 drag-coupled response) and
// p' = 0 in pressure-boundary cells, continuity in each fluid cell P becomes
//     Σ_faces A (ε_g d_g + ε_s d_s) (p'_P − p'_nb) = −Σ_faces A (ε_g u*_g + ε_s u*_s)_out,
// with ε_m the fractions the phases carry through the face (flux_fraction): symmetric positive
// (semi-)definite, CG with algebraic multigrid (GAMG or BoomerAMG); a closed domain has the
// constant null space, removed in the solve. Then P += α_p p' in fluid cells, and both phases'
// velocities are corrected. Without solids this is the single-phase pressure correction.
// Returns the volume imbalance before the correction, Σ|Σ_faces Q_out| / Σ ½ Σ_faces |Q| (at
// least the volume flux of the residual velocity scale through every face).
#include <algorithm>
#include <cmath>

#include "solver/simple/flow_solver.hpp"

namespace bagnold::solver {

double FlowSolver::correct_pressure(run::FlowState& state) {
  const auto& layout = m_domain.layout;
  const auto& numbering = *m_pressure_numbering;
  double imbalance = 0.0, throughput = 0.0;
  m_worst_value[mixture_continuity] = 0.0;
  m_worst_local[mixture_continuity] = -1;

  for (const int l : numbering.owned_locals) {
    double a_p = 0.0, b = 0.0;
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    for (int face = 0; face < 6; ++face) {
      const int d = parallel::face_direction(face);
      const auto ud = static_cast<std::size_t>(d);
      const int s = parallel::face_sign(face);
      const int m = layout.neighbour(l, face);
      const int owner = s > 0 ? l : m;  // the cell that owns this face's velocity
      if (owner < 0) continue;
      const auto uo = static_cast<std::size_t>(owner);
      const double area = face_area(l, d);
      const double eps_g = flux_fraction(state, gas, owner, d);
      const double eps_s = flux_fraction(state, solids, owner, d);
      const double flux_out = s * area * (eps_g * state.gas_velocity[ud][uo] +
                                          eps_s * state.solids_velocity[ud][uo]);
      b -= flux_out;
      throughput += 0.5 * std::abs(flux_out);
      if (faces(gas).kind[ud][uo] != FaceClass::unknown) continue;
      const double coefficient = area * (eps_g * m_d[gas][ud][uo] + eps_s * m_d[solids][ud][uo]);
      a_p += coefficient;
      if (layout.kind(m) == grid::CellKind::fluid) {
        columns[count] = numbering.global[static_cast<std::size_t>(m)];
        values[count++] = -coefficient;
      }
    }
    imbalance += std::abs(b);
    record_worst(mixture_continuity, std::abs(b), l);
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
  for (const Phase phase : {gas, solids}) {
    if (!m_moves[phase]) continue;
    auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      auto& u = velocity[ud];
      const auto& response = m_d[phase][ud];
      for (const int l : m_velocity_numbering[ud]->owned_locals) {
        const int n = layout.neighbour(l, 2 * d + 1);
        u[static_cast<std::size_t>(l)] += response[static_cast<std::size_t>(l)] *
                                          (correction[static_cast<std::size_t>(l)] -
                                           correction[static_cast<std::size_t>(n)]);
      }
      parallel::exchange_halo<double>(layout, u);
    }
  }

  const double total_imbalance = layout.comm().sum(imbalance);
  // A flow at rest has no throughput: measure against the flux the velocity scale would carry.
  const double total_throughput =
      std::max(layout.comm().sum(throughput), m_reference_area * m_velocity_scale);
  return total_imbalance <= 1e-300 ? 0.0 : total_imbalance / total_throughput;
}

}  // namespace bagnold::solver
