#pragma once
// numerics.step_solver = "newton": one implicit-Euler time step solved as one nonlinear system
// F(x) = 0 over all its unknowns at once (both phases' velocities, the gas pressure, the solids
// fraction; step_equations.hpp) with PETSc's SNES: Newton iterations with a backtracking line
// search on ‖F‖, each a linear solve of the Jacobian of step_equations.hpp (by default an LU
// factorization, MUMPS; every SNES, KSP and PC option can be given with the prefix newton_, e.g.
// -newton_snes_mf_operator for the exact, matrix-free Jacobian preconditioned by the assembled
// one, or -newton_snes_monitor). The step has converged when the residuals, judged as the outer
// iteration judges them (numerics.residual_normalization, numerics.tolerance), are below the
// tolerance; it fails (and is redone with a smaller dt) after numerics.max_outer_iterations Newton
// iterations, or when the line search finds no decrease. After each Newton update ε_s is kept
// ≥ 0 (counted as fraction_clamped_at_zero); a trial state on which a closure is not finite is
// a domain error, which shortens the line search's step.

#include <petscsnes.h>

#include <functional>
#include <memory>

#include "solver/newton/step_equations.hpp"
#include "solver/petsc/handle.hpp"

namespace bagnold::solver {

class NewtonStep {
 public:
  // `boundary_values` sets what every stencil reads at the boundaries (FlowSolver's).
  NewtonStep(const Discretization& discretization, const SolverSettings& settings, Closures& closures,
             SolidsWallCoefficients* walls, const std::array<std::vector<double>, 3>& gas_source,
             std::function<void(run::FlowState&)> boundary_values);
  ~NewtonStep();
  NewtonStep(const NewtonStep&) = delete;
  NewtonStep& operator=(const NewtonStep&) = delete;

  // Solves the step from `state` (the first iterate) into `state`; `worst` gets the largest rows
  // of the last evaluation. On return `result` holds what the outer iteration's would: iterations
  // (Newton iterations), the residuals of the last evaluated state, its force balance.
  StepResult advance(run::FlowState& state, const run::FlowState& old, double dt, WorstCells& worst,
                     bool (*stop_probe)());
  // The fractions carried in the last evaluation (conserve_solids after convergence).
  const CarriedFractions& carried() const { return m_equations.carried(); }

 private:
  static PetscErrorCode form_function(SNES snes, Vec x, Vec f, void* context);
  static PetscErrorCode form_jacobian(SNES snes, Vec x, Mat J, Mat P, void* context);
  static PetscErrorCode converged(SNES snes, PetscInt iteration, PetscReal xnorm, PetscReal step_norm,
                                  PetscReal fnorm, SNESConvergedReason* reason, void* context);
  static PetscErrorCode post_check(SNESLineSearch search, Vec x, Vec y, Vec w, PetscBool* changed_y,
                                   PetscBool* changed_w, void* context);
  // F at x into f, the judged residuals into m_result.
  void evaluate(Vec x, Vec f);

  const Discretization& m_discretization;
  const SolverSettings& m_settings;
  StepEquations m_equations;
  std::function<void(run::FlowState&)> m_boundary_values;
  PetscHandle<SNES, SNESDestroy> m_snes;
  PetscMat m_jacobian;
  PetscVec m_x, m_f, m_evaluated_at;
  // The step being solved.
  run::FlowState* m_state = nullptr;
  WorstCells* m_worst = nullptr;
  StepResult m_result;
  bool (*m_stop_probe)() = nullptr;
  bool m_have_evaluation = false;
};

}  // namespace bagnold::solver
