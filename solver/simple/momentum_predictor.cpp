// Step 1b of the outer iteration: the momentum predictors of both phases for the component d,
// with partial elimination of the drag coupling (Spalding's PEA, as MFIX).
//
// Row by row, with A_m = a_m + βV the diagonal including drag and R_m = b_m + Σ a_nb u_nb the
// rest of the row at the current iterate, the pair
//     A_g u_g − βV u_s = R_g,      A_s u_s − βV u_g = R_s
// is solved for each phase with the other phase's own row eliminated:
//     (A_g − (βV)²/A_s) u_g = b_g + Σ a_nb u_nb + βV R_s / A_s       (and likewise the solids),
// so a strong drag couples the phases within the predictor instead of across outer iterations.
// Then Patankar under-relaxation (diag / α_u, b + (1 − α_u) diag u*), and one BiCGStab solve per
// phase. Where the solids are below the threshold their velocity is zero (and the gas sees
// β (0 − u_g)); a frozen solids phase enters with its given velocity.
//
// The corrections' velocity responses come from the same 2 × 2 system with the relaxed
// diagonals D_m (SIMPLEC: D_m − Σ a_nb):
//   [D_g, −βV; −βV, D_s] (u'_g, u'_s) = (ε_g A, ε_s A) (p'_c − p'_n)  →  d_g, d_s,
//   [D_g, −βV; −βV, D_s] (u'_g, u'_s) = (0, K A) (ε'_c − ε'_n)       →  e (solids), K = dP_s/dε_s.
// Residuals: Σ|R_m + βV u_other − A_m u_m| per phase, normalized as numerics.residual_normalization
// says (momentum_residual.hpp).
#include <algorithm>
#include <cmath>

#include "solver/simple/flow_solver.hpp"

namespace bagnold::solver {

namespace {
// The relaxed diagonal that the corrections see: SIMPLEC drops the neighbours' corrections.
double correction_diagonal(double relaxed, double neighbours, bool simplec) {
  return simplec && relaxed - neighbours > 1e-12 * relaxed ? relaxed - neighbours : relaxed;
}
}  // namespace

void FlowSolver::predict_momentum(int d, run::FlowState& state, const run::FlowState& old,
                                  double dt, Residuals& residuals) {
  const auto& layout = m_domain.layout;
  const auto ud = static_cast<std::size_t>(d);
  const auto& numbering = *m_velocity_numbering[ud];
  if (numbering.total_rows == 0) return;  // e.g. no fluid faces along d
  const double alpha = m_deck.numerics.relax_velocity;
  const bool coupled = m_moves[gas] && m_moves[solids];
  auto& u_g = state.gas_velocity[ud];
  auto& u_s = state.solids_velocity[ud];

  std::array<std::vector<MomentumRow>, 2> rows;
  for (const Phase phase : {gas, solids})
    if (m_moves[phase]) assemble_momentum(phase, d, state, old, dt, rows[phase]);

  // The deviation normalization measures each row about the phase's mean velocity over its
  // solved rows (two collectives per phase, so only when that normalization is chosen).
  std::array<double, 2> mean{0, 0};
  if (m_residual_normalization == ResidualNormalization::deviation) {
    std::array<double, 2> sum{0, 0}, count{0, 0};
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      const auto ul = static_cast<std::size_t>(numbering.owned_locals[r]);
      if (m_moves[gas]) sum[gas] += u_g[ul], count[gas] += 1;
      if (m_moves[solids] && rows[solids][r].active) sum[solids] += u_s[ul], count[solids] += 1;
    }
    for (const Phase phase : {gas, solids}) {
      const double n = layout.comm().sum(count[phase]);
      mean[phase] = n > 0 ? layout.comm().sum(sum[phase]) / n : 0.0;
    }
  }
  const double least_speed = 1e-3 * m_reference_speed;
  std::array<MomentumResidual, 2> residual;
  for (const Phase phase : {gas, solids})
    residual[phase] = MomentumResidual(m_residual_normalization, mean[phase], m_velocity_scale,
                                       least_speed, m_deck.numerics.net_force_residual);
  auto weight = [&](Phase phase, const MomentumRow& row) {
    return row.fraction * density(phase) * row.volume * m_gravity;
  };
  std::array<std::vector<double>, 2> x;
  for (auto& v : x) v.resize(numbering.owned_locals.size());
  for (const int e : {gas_momentum_x + d, solids_momentum_x + d}) {
    m_worst_value[static_cast<std::size_t>(e)] = 0.0;
    m_worst_local[static_cast<std::size_t>(e)] = -1;
  }
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    const int l = numbering.owned_locals[r];
    const auto ul = static_cast<std::size_t>(l);
    const int n = layout.neighbour(l, 2 * d + 1);
    const MomentumRow* g = m_moves[gas] ? &rows[gas][r] : nullptr;
    const MomentumRow* s = m_moves[solids] && rows[solids][r].active ? &rows[solids][r] : nullptr;
    const MomentumRow& any = g ? *g : rows[solids][r];
    const double half_c = 0.5 * width(l, d), half_n = 0.5 * width(n, d);
    const double beta = (m_beta[ul] * half_n + m_beta[static_cast<std::size_t>(n)] * half_c) / (half_c + half_n);
    const double beta_v = coupled || (m_moves[gas] && m_drag) ? beta * any.volume : 0.0;
    const double A_g = g ? g->a + beta_v : 0.0, A_s = s ? s->a + beta_v : 0.0;
    const double R_g = g ? g->b + g->neighbours_u : 0.0, R_s = s ? s->b + s->neighbours_u : 0.0;

    if (g) {
      const double row_residual = residual[gas].add(A_g, A_g * u_g[ul] - g->neighbours_u,
                                                    A_g - g->neighbours_a, g->b + beta_v * u_s[ul],
                                                    g->transient, weight(gas, *g));
      record_worst(gas_momentum_x + d, row_residual, l);
      double diagonal = A_g, rhs = g->b;
      if (s) {
        diagonal -= beta_v * beta_v / A_s;
        rhs += beta_v * R_s / A_s;
      } else {
        rhs += beta_v * u_s[ul];  // frozen solids, or none here (u_s = 0)
      }
      const double relaxed = diagonal / alpha;
      std::int64_t columns[7];
      double values[7];
      std::copy(g->columns, g->columns + g->count, columns);
      std::copy(g->values, g->values + g->count, values);
      columns[g->count] = numbering.global[ul];
      values[g->count] = relaxed;
      m_momentum_system[gas][ud]->set_row(numbering.global[ul], columns, values, g->count + 1,
                                          rhs + (1.0 - alpha) * relaxed * u_g[ul]);
      x[gas][r] = u_g[ul];
    }
    if (m_moves[solids]) {
      const MomentumRow& row = rows[solids][r];
      double diagonal = 1.0, rhs = 0.0;
      if (s) {
        const double row_residual = residual[solids].add(A_s, A_s * u_s[ul] - s->neighbours_u,
                                                         A_s - s->neighbours_a, s->b + beta_v * u_g[ul],
                                                         s->transient, weight(solids, *s));
        record_worst(solids_momentum_x + d, row_residual, l);
        diagonal = A_s;
        rhs = s->b;
        if (g) {
          diagonal -= beta_v * beta_v / A_g;
          rhs += beta_v * R_g / A_g;
        }
        diagonal /= alpha;
        rhs += (1.0 - alpha) * diagonal * u_s[ul];
      }
      std::int64_t columns[7];
      double values[7];
      std::copy(row.columns, row.columns + row.count, columns);
      std::copy(row.values, row.values + row.count, values);
      columns[row.count] = numbering.global[ul];
      values[row.count] = diagonal;
      m_momentum_system[solids][ud]->set_row(numbering.global[ul], columns, values, row.count + 1, rhs);
      x[solids][r] = s ? u_s[ul] : 0.0;
    }

    // Velocity responses to the pressure and volume-fraction corrections.
    const double D_g = g ? correction_diagonal(A_g / alpha, g->neighbours_a, m_simplec) : 0.0;
    const double D_s = s ? correction_diagonal(A_s / alpha, s->neighbours_a, m_simplec) : 0.0;
    const double eps_g = g ? g->fraction : 0.0;
    const double eps_s = m_moves[solids] ? rows[solids][r].fraction : 0.0;
    // K ≥ 0: a closure whose P_s falls with ε_s at fixed strain rate (kinetic theory in its
    // dilute range) would make the correction anti-diffusive; that part stays explicit. At an
    // outlet (P_s = 0 beyond it) the fluid cell's K alone.
    const bool l_fluid = layout.kind(l) == grid::CellKind::fluid, n_fluid = layout.kind(n) == grid::CellKind::fluid;
    const double K_l = l_fluid ? m_pressure_derivative[ul] : 0.0;
    const double K_n = n_fluid ? m_pressure_derivative[static_cast<std::size_t>(n)] : 0.0;
    const double K = std::max(l_fluid && n_fluid ? 0.5 * (K_l + K_n) : K_l + K_n, 0.0);
    double d_g = 0.0, d_s = 0.0, e = 0.0;
    if (g && s) {
      const double det = D_g * D_s - beta_v * beta_v;
      d_g = any.area * (eps_g * D_s + eps_s * beta_v) / det;
      d_s = any.area * (eps_s * D_g + eps_g * beta_v) / det;
      e = any.area * K * D_g / det;
    } else if (g) {
      d_g = eps_g * any.area / D_g;
    } else if (s) {
      d_s = eps_s * any.area / D_s;
      e = any.area * K / D_s;
    }
    m_d[gas][ud][ul] = d_g;
    m_d[solids][ud][ul] = d_s;
    m_e[ud][ul] = e;
  }

  for (const Phase phase : {gas, solids}) {
    if (!m_moves[phase]) continue;
    auto& u = phase == gas ? u_g : u_s;
    m_momentum_system[phase][ud]->solve(x[phase]);
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r)
      u[static_cast<std::size_t>(numbering.owned_locals[r])] = x[phase][r];
    parallel::exchange_halo<double>(layout, u);
    parallel::exchange_halo<double>(layout, m_d[phase][ud]);
    residuals.value[static_cast<std::size_t>((phase == gas ? gas_momentum_x : solids_momentum_x) + d)] =
        residual[phase].value(layout.comm());
  }
  if (m_moves[solids]) parallel::exchange_halo<double>(layout, m_e[ud]);
}

}  // namespace bagnold::solver
