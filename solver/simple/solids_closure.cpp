// Step 0 of the outer iteration: the closures on the current iterate, at cell centres.
//   - the gas's effective viscosity ε_g μ_g;
//   - the solids' P_s, dP_s/dε_s, μ_s and Θ from the deck's solids-stress model
//     (models/stress/), given ε_s and the strain-rate invariants of the solids velocity
//     (solver/strain_rate.*). Evaluated over every local fluid cell (the halo included, since
//     the strain rate is exchanged), so the momentum stencils need no further exchange.
// P_s and Θ are stored in the state (written to snapshots); μ_s and dP_s/dε_s stay here.
#include "solver/simple/flow_solver.hpp"
#include "solver/strain_rate.hpp"

#include <algorithm>

namespace bagnold::solver {

void FlowSolver::evaluate_solids_stress(run::FlowState& state) {
  const auto& layout = m_domain.layout;
  const double mu_g = m_deck.gas.viscosity;
  for (int l = 0; l < layout.local_count(); ++l)
    m_viscosity[gas][static_cast<std::size_t>(l)] = state.gas_fraction[static_cast<std::size_t>(l)] * mu_g;
  if (!m_stress) return;

  compute_strain_rate(m_domain, state.solids_velocity, m_strain_rate, m_divergence, m_no_slip_strain_regions);
  std::vector<int> cells;
  std::vector<double> fraction, rate, divergence;
  for (int l = 0; l < layout.local_count(); ++l) {
    if (layout.kind(l) != grid::CellKind::fluid) continue;
    const auto i = static_cast<std::size_t>(l);
    cells.push_back(l);
    fraction.push_back(std::max(state.solids_fraction[i], 0.0));  // round-off below 0 at an emptying cell
    rate.push_back(m_strain_rate[i]);
    divergence.push_back(m_divergence[i]);
  }
  const std::size_t n = cells.size();
  std::vector<double> pressure(n), derivative(n), shear(n), bulk(n), temperature(n);
  models::SolidsStress out{pressure, derivative, shear, bulk, temperature};
  m_stress->evaluate(m_deck.solids.material, {fraction, rate, divergence}, out);
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(cells[k]);
    state.solids_pressure[i] = pressure[k];
    state.granular_temperature[i] = temperature[k];
    m_pressure_derivative[i] = derivative[k];
    m_viscosity[solids][i] = shear[k];
  }
}

}  // namespace bagnold::solver
