// Step 0 of the outer iteration: the closures on the current iterate, at cell centres.
//   - the gas's effective viscosity ε_g μ_g;
//   - the solids' P_s, dP_s/dε_s, μ_s and Θ from the deck's solids-stress model
//     (models/stress/), given ε_s and the strain-rate invariants of the solids velocity
//     (solver/strain_rate.*). Evaluated over every local fluid cell (the halo included, since
//     the strain rate is exchanged), so the momentum stencils need no further exchange.
// With numerics.pressure_shear_rate_relaxation_time τ_P > 0, P_s and dP_s/dε_s come from a second
// evaluation at γ̇_P, the strain rate relaxed in time: implicit Euler of dγ̇_P/dt = (γ̇ − γ̇_P)/τ_P
// per cell, from the step's old γ̇_P (γ̇_P = γ̇ where old has none: a fresh start, or a restart
// from a snapshot written before the field existed). μ_s and Θ keep the current rate.
// P_s, γ̇_P and Θ are stored in the state (written to snapshots); μ_s and dP_s/dε_s stay here.
#include "solver/simple/flow_solver.hpp"
#include "solver/strain_rate.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

void FlowSolver::evaluate_solids_stress(run::FlowState& state, const run::FlowState& old,
                                        double dt) {
  const auto& layout = m_domain.layout;
  const double mu_g = m_deck.gas.viscosity;
  for (int l = 0; l < layout.local_count(); ++l)
    m_viscosity[gas][static_cast<std::size_t>(l)] = state.gas_fraction[static_cast<std::size_t>(l)] * mu_g;
  if (!m_stress) return;

  compute_strain_rate(m_domain, state.solids_velocity, m_strain_rate, m_divergence, m_no_slip_strain_regions);
  const double relaxation_time = m_deck.numerics.pressure_shear_rate_relaxation_time;
  const double weight = relaxation_time > 0.0 ? dt / relaxation_time : 0.0;
  std::vector<int> cells;
  std::vector<double> fraction, rate, pressure_rate, divergence;
  for (int l = 0; l < layout.local_count(); ++l) {
    if (layout.kind(l) != grid::CellKind::fluid) continue;
    const auto i = static_cast<std::size_t>(l);
    cells.push_back(l);
    fraction.push_back(std::max(state.solids_fraction[i], 0.0));  // round-off below 0 at an emptying cell
    rate.push_back(m_strain_rate[i]);
    divergence.push_back(m_divergence[i]);
    const double before = old.pressure_shear_rate[i];
    pressure_rate.push_back(relaxation_time > 0.0 && std::isfinite(before)
                                ? (before + weight * m_strain_rate[i]) / (1.0 + weight)
                                : m_strain_rate[i]);
  }
  const std::size_t n = cells.size();
  std::vector<double> pressure(n), derivative(n), shear(n), bulk(n), temperature(n);
  models::SolidsStress out{pressure, derivative, shear, bulk, temperature};
  m_stress->evaluate(m_deck.solids.material, {fraction, rate, divergence}, out);
  if (relaxation_time > 0.0) {
    std::vector<double> unused_shear(n), unused_bulk(n), unused_temperature(n);
    models::SolidsStress at_relaxed_rate{pressure, derivative, unused_shear, unused_bulk,
                                         unused_temperature};
    m_stress->evaluate(m_deck.solids.material, {fraction, pressure_rate, divergence},
                       at_relaxed_rate);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(cells[k]);
    state.solids_pressure[i] = pressure[k];
    state.pressure_shear_rate[i] = pressure_rate[k];
    state.granular_temperature[i] = temperature[k];
    m_pressure_derivative[i] = derivative[k];
    m_viscosity[solids][i] = shear[k];
  }
}

}  // namespace bagnold::solver
