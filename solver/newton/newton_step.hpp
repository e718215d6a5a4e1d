#pragma once
// numerics.step_solver = "newton": one implicit-Euler time step solved as one nonlinear system
// F(x) = 0 over all its unknowns at once (both phases' velocities, the gas pressure, the solids
// fraction; step_equations.hpp) with PETSc's SNES: Newton iterations with a backtracking line
// search on ‖F‖. Each Newton iteration solves with the Jacobian — the exact one, applied
// matrix-free as a difference of F along the Krylov vector, plus under
// numerics.newton_linearization = "stress-velocity" the stress–velocity correction of the solids'
// rate-independent stress (step_equations.hpp) — by flexible GMRES to a relative 10⁻³,
// preconditioned by an LU factorization (MUMPS) of the assembled linearization. Every SNES, KSP
// and PC option can be given with the prefix newton_ (e.g. -newton_snes_monitor). The step has converged when the residuals, judged as the outer
// iteration judges them (numerics.residual_normalization, numerics.tolerance), are below the
// tolerance; it fails (and is redone with a smaller dt) after numerics.max_outer_iterations Newton
// iterations, or when the line search finds no decrease. Before the line search, each cell's
// share of the Newton update of ε_s is limited as the outer iteration limits its fraction
// correction (compression_limit.hpp): never below ε_s = 0, and where it compresses, not into
// a P_s above twice its linear prediction (near packing P_s is convex, and a full Newton step
// from below lands at pressures orders of magnitude too high, which the line search would
// otherwise answer by shortening the step everywhere). The limit shapes the path only: a
// converged step satisfies the same equations. After each line search step ε_s is kept ≥ 0
// (counted as fraction_clamped_at_zero); a trial state on which a closure is not finite is a
// domain error, which shortens the line search's step.

#include <petscsnes.h>

#include <functional>
#include <memory>

#include "solver/newton/step_equations.hpp"
#include "solver/petsc/handle.hpp"
#include "solver/simple/compression_limit.hpp"

namespace bagnold::solver {

class NewtonStep {
 public:
  // `boundary_values` sets what every stencil reads at the boundaries; `worst_cell` locates the
  // largest row of an equation (collective), for BAGNOLD_TRACE (FlowSolver's, both).
  NewtonStep(const Discretization& discretization, const SolverSettings& settings, Closures& closures,
             SolidsWallCoefficients* walls, const std::array<std::vector<double>, 3>& gas_source,
             std::function<void(run::FlowState&)> boundary_values, std::function<CellLocation(int)> worst_cell);
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
  static PetscErrorCode pre_check(SNESLineSearch search, Vec x, Vec y, PetscBool* changed, void* context);
  static PetscErrorCode post_check(SNESLineSearch search, Vec x, Vec y, Vec w, PetscBool* changed_y,
                                   PetscBool* changed_w, void* context);
  // F at x into f, the judged residuals into m_result.
  void evaluate(Vec x, Vec f);

  const Discretization& m_discretization;
  const SolverSettings& m_settings;
  StepEquations m_equations;
  std::unique_ptr<CompressionLimit> m_compression;  // null unless the solids move
  std::vector<double> m_fraction_change;            // per local cell, the Newton update's ε_s change
  std::function<void(run::FlowState&)> m_boundary_values;
  std::function<CellLocation(int)> m_worst_cell;
  PetscHandle<SNES, SNESDestroy> m_snes;
  // The operator: the exact Jacobian (m_matrix_free, differences of F) plus the stress–velocity
  // correction m_correction (step_equations.hpp); m_jacobian, the assembled linearization, is
  // its preconditioner.
  static PetscErrorCode apply_operator(Mat A, Vec x, Vec y);
  PetscMat m_jacobian, m_correction, m_matrix_free, m_operator;
  PetscVec m_x, m_f, m_evaluated_at, m_column_scales;
  // The step being solved.
  run::FlowState* m_state = nullptr;
  WorstCells* m_worst = nullptr;
  StepResult m_result;
  bool (*m_stop_probe)() = nullptr;
  bool m_have_evaluation = false;
};

}  // namespace bagnold::solver
