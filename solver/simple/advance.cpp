// One implicit-Euler time step: outer iterations (closures, momentum predictors, pressure
// correction, solids volume fraction correction) until every normalized residual is below
// numerics.tolerance, or numerics.max_outer_iterations.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "solver/simple/flow_solver.hpp"

namespace bagnold::solver {

StepResult FlowSolver::advance(run::FlowState& state, const run::FlowState& old, double dt) {
  StepResult result;
  apply_boundary_values(state);
  // BAGNOLD_TRACE=1: every outer iteration's residuals and the cell of the largest, on stderr.
  const bool trace = std::getenv("BAGNOLD_TRACE") != nullptr;
  const bool root = m_domain.layout.comm().is_root();
  // The residuals' velocity scale may follow the iterate up to 10× the step's start, no further:
  // an iterate that blows up must not make its own residuals look small and be accepted.
  const double largest_scale = 10.0 * residual_velocity_scale(old);
  for (int iteration = 1; iteration <= m_deck.numerics.max_outer_iterations; ++iteration) {
    m_outer_iteration = iteration;
    // The multigrid hierarchy of the pressure correction is built once per step and reused by
    // the later outer iterations (the matrix changes only through d); it dominated the run time.
    if (m_pressure_system) m_pressure_system->reuse_preconditioner(iteration > 1);
    m_velocity_scale = std::min(residual_velocity_scale(state), largest_scale);
    evaluate_drag(state);
    evaluate_solids_stress(state, old, dt);
    result.residuals = Residuals{};
    for (int d = 0; d < 3; ++d) predict_momentum(d, state, old, dt, result.residuals);
    if (m_moves[gas]) result.residuals.value[mixture_continuity] = correct_pressure(state);
    if (m_moves[solids])
      result.residuals.value[solids_continuity] = correct_volume_fraction(state, old, dt);
    result.iterations = iteration;
    const double largest = result.residuals.largest();
    if (trace) {
      const auto where = worst_cell(result.residuals.worst());  // collective
      if (root) {
        std::fprintf(stderr, "  it %d:", iteration);
        for (const double r : result.residuals.value) std::fprintf(stderr, " %.3e", r);
        std::fprintf(stderr, "  worst at (%d, %d, %d)\n", where.cell[0], where.cell[1],
                     where.cell[2]);
      }
    }
    if (!std::isfinite(largest)) return result;  // diverged: the caller backs off
    if (largest < m_deck.numerics.tolerance) {
      if (m_moves[solids]) conserve_solids(state, old, dt);
      result.converged = true;
      return result;
    }
  }
  return result;
}

}  // namespace bagnold::solver
