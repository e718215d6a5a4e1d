// One implicit-Euler time step of the gas solver: SIMPLE outer iterations until every
// normalized residual is below numerics.tolerance, or numerics.max_outer_iterations.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "solver/simple/gas_solver.hpp"

namespace bagnold::solver {

StepResult GasSolver::advance(run::FlowState& state, const run::FlowState& old, double dt) {
  StepResult result;
  apply_boundary_values(state);
  for (int iteration = 1; iteration <= m_deck.numerics.max_outer_iterations; ++iteration) {
    // The multigrid hierarchy of the pressure correction is built once per step and reused by
    // the later outer iterations (the matrix changes only through d); it dominated the run time.
    m_pressure_system->reuse_preconditioner(iteration > 1);
    m_velocity_scale = residual_velocity_scale(state);
    evaluate_drag(state);
    for (int d = 0; d < 3; ++d)
      result.residuals.momentum[static_cast<std::size_t>(d)] = predict_momentum(d, state, old, dt);
    result.residuals.continuity = correct_pressure(state);
    result.iterations = iteration;
    const double largest = result.residuals.largest();
    if (std::getenv("BAGNOLD_TRACE") && m_domain.layout.comm().is_root())
      std::fprintf(stderr, "  it %d: u %.3e v %.3e w %.3e mass %.3e\n", iteration,
                   result.residuals.momentum[0], result.residuals.momentum[1],
                   result.residuals.momentum[2], result.residuals.continuity);
    if (!std::isfinite(largest)) return result;  // diverged: the caller backs off
    if (largest < m_deck.numerics.tolerance) {
      result.converged = true;
      return result;
    }
  }
  return result;
}

}  // namespace bagnold::solver
