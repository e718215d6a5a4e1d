// The Newton solve of a whole time step (newton_step.hpp).
#include "solver/newton/newton_step.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace bagnold::solver {

namespace {
// Each Newton iteration's linear solve: until the residual of the exact (matrix-free) Jacobian
// has fallen by this, within this many Krylov iterations (each one evaluation of F).
constexpr double linear_relative_tolerance = 1e-3;
constexpr int max_linear_iterations = 100;

// SNES callbacks return PETSc error codes; a C++ exception must not cross PETSc's frames.
template <class Body>
PetscErrorCode guarded(Body&& body) {
  try {
    body();
    return 0;
  } catch (const std::exception& error) {
    return PetscError(PETSC_COMM_SELF, __LINE__, "newton_step", __FILE__, PETSC_ERR_LIB, PETSC_ERROR_INITIAL,
                      "%s", error.what());
  }
}
}  // namespace

NewtonStep::NewtonStep(const Discretization& discretization, const SolverSettings& settings, Closures& closures,
                       SolidsWallCoefficients* walls, const std::array<std::vector<double>, 3>& gas_source,
                       std::function<void(run::FlowState&)> boundary_values,
                       std::function<CellLocation(int)> worst_cell)
    : m_discretization(discretization), m_settings(settings),
      m_equations(discretization, settings, closures, walls, gas_source),
      m_boundary_values(std::move(boundary_values)), m_worst_cell(std::move(worst_cell)) {
  const MPI_Comm comm = discretization.layout().comm().get();
  const auto owned = static_cast<PetscInt>(m_equations.unknowns().owned_rows());
  const auto total = static_cast<PetscInt>(m_equations.unknowns().total_rows());
  petsc_check(VecCreateMPI(comm, owned, total, m_x.out()), "VecCreateMPI");
  petsc_check(VecDuplicate(m_x.get(), m_f.out()), "VecDuplicate");
  petsc_check(VecDuplicate(m_x.get(), m_evaluated_at.out()), "VecDuplicate");
  m_equations.create_matrix(m_jacobian.out());
  m_equations.create_matrix(m_correction.out());
  // A velocity in units of the reference speed, the gas pressure in units of the weight of a
  // packed column of the domain's height (ρ_s |g| L, or ρ_g U² without gravity).
  const double pressure_scale = std::max(settings.density[solids] * settings.gravity_magnitude * settings.extent,
                                         settings.density[gas] * settings.reference_speed * settings.reference_speed);
  m_equations.unknowns().set_scales(settings.reference_speed, pressure_scale > 0.0 ? pressure_scale : 1.0);
  petsc_check(VecDuplicate(m_x.get(), m_column_scales.out()), "VecDuplicate");
  m_equations.unknowns().fill_scales(m_column_scales.get());
  petsc_check(SNESCreate(comm, m_snes.out()), "SNESCreate");
  SNES snes = m_snes.get();
  petsc_check(SNESSetOptionsPrefix(snes, "newton_"), "SNESSetOptionsPrefix");
  petsc_check(SNESSetType(snes, SNESNEWTONLS), "SNESSetType");
  petsc_check(SNESSetFunction(snes, m_f.get(), form_function, this), "SNESSetFunction");
  petsc_check(MatCreateSNESMF(snes, m_matrix_free.out()), "MatCreateSNESMF");
  petsc_check(MatCreateShell(comm, owned, owned, total, total, this, m_operator.out()), "MatCreateShell");
  petsc_check(MatShellSetOperation(m_operator.get(), MATOP_MULT, reinterpret_cast<void (*)(void)>(apply_operator)),
              "MatShellSetOperation");
  petsc_check(SNESSetJacobian(snes, m_operator.get(), m_jacobian.get(), form_jacobian, this), "SNESSetJacobian");
  petsc_check(SNESSetConvergenceTest(snes, converged, this, nullptr), "SNESSetConvergenceTest");
  petsc_check(SNESSetTolerances(snes, 0.0, 0.0, 0.0, settings.max_outer_iterations, 100 * settings.max_outer_iterations),
              "SNESSetTolerances");
  petsc_check(SNESSetMaxLinearSolveFailures(snes, 1), "SNESSetMaxLinearSolveFailures");
  // Flexible GMRES preconditioned by an LU factorization of the assembled linearization.
  KSP ksp = nullptr;
  petsc_check(SNESGetKSP(snes, &ksp), "SNESGetKSP");
  petsc_check(KSPSetType(ksp, KSPFGMRES), "KSPSetType");
  petsc_check(KSPSetTolerances(ksp, linear_relative_tolerance, 0.0, PETSC_DEFAULT, max_linear_iterations),
              "KSPSetTolerances");
  PC pc = nullptr;
  petsc_check(KSPGetPC(ksp, &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, PCLU), "PCSetType");
  petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
  SNESLineSearch search = nullptr;
  petsc_check(SNESGetLineSearch(snes, &search), "SNESGetLineSearch");
  petsc_check(SNESLineSearchSetType(search, SNESLINESEARCHBT), "SNESLineSearchSetType");
  petsc_check(SNESSetFromOptions(snes), "SNESSetFromOptions");
  petsc_check(SNESLineSearchSetPostCheck(search, post_check, this), "SNESLineSearchSetPostCheck");
  if (m_equations.unknowns().present(StepUnknowns::fraction)) {
    m_compression = std::make_unique<CompressionLimit>(discretization, settings, closures);
    m_fraction_change.assign(static_cast<std::size_t>(discretization.layout().local_count()), 0.0);
    petsc_check(SNESLineSearchSetPreCheck(search, pre_check, this), "SNESLineSearchSetPreCheck");
  }
}

NewtonStep::~NewtonStep() = default;

void NewtonStep::evaluate(Vec x, Vec f) {
  m_equations.unknowns().scatter(x, *m_state);
  m_boundary_values(*m_state);
  IterationSums sums;
  m_equations.residual(*m_state, f, sums, *m_worst);
  sums.stop = m_stop_probe && m_stop_probe() ? 1.0 : 0.0;
  sums.reduce(m_discretization.layout().comm());
  if (sums.stop > 0.0) m_result.abandoned = true;
  StepResult& result = m_result;
  judge_momentum(sums, result);
  for (int c = 0; c < 2; ++c) {
    const auto& [imbalance, throughput] = sums.continuity[static_cast<std::size_t>(c)];
    const bool solved = m_equations.unknowns().present(c == 0 ? StepUnknowns::pressure : StepUnknowns::fraction);
    const bool in_forces = c == 1 && m_settings.residual_normalization == ResidualNormalization::force;
    const double least = in_forces ? 1e-300 : m_discretization.reference_area() * m_settings.least_speed;
    result.residuals.value[static_cast<std::size_t>(mixture_continuity + c)] =
        !solved || imbalance <= 1e-300 ? 0.0 : imbalance / std::max(throughput, least);
  }
  result.wall_shear = sums.wall_shear;
  result.judged = result.residuals.largest();
  if (result.iterations == 0 && !m_have_evaluation) result.first_largest = result.judged;
  petsc_check(VecCopy(x, m_evaluated_at.get()), "VecCopy");
  m_have_evaluation = true;
}

PetscErrorCode NewtonStep::form_function(SNES snes, Vec x, Vec f, void* context) {
  auto* self = static_cast<NewtonStep*>(context);
  return guarded([&] {
    self->evaluate(x, f);
    if (!std::isfinite(self->m_result.judged)) petsc_check(SNESSetFunctionDomainError(snes), "SNESSetFunctionDomainError");
  });
}

PetscErrorCode NewtonStep::form_jacobian(SNES, Vec x, Mat J, Mat P, void* context) {
  auto* self = static_cast<NewtonStep*>(context);
  return guarded([&] {
    // The Jacobian comes from the rows of an evaluation at x: the line search's last one is.
    PetscBool same = PETSC_FALSE;
    if (self->m_have_evaluation) petsc_check(VecEqual(x, self->m_evaluated_at.get(), &same), "VecEqual");
    if (!same) {
      PetscVec scratch;
      petsc_check(VecDuplicate(x, scratch.out()), "VecDuplicate");
      self->evaluate(x, scratch.get());
    }
    self->m_equations.jacobian(*self->m_state, P, self->m_correction.get(), self->m_settings.stress_velocity);
    // Columns in the vector's units (step_unknowns.hpp).
    petsc_check(MatDiagonalScale(P, nullptr, self->m_column_scales.get()), "MatDiagonalScale");
    petsc_check(MatDiagonalScale(self->m_correction.get(), nullptr, self->m_column_scales.get()), "MatDiagonalScale");
    // The differences of F start from x (MatCreateSNESMF takes SNES's current solution).
    petsc_check(MatAssemblyBegin(self->m_matrix_free.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    petsc_check(MatAssemblyEnd(self->m_matrix_free.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    petsc_check(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    petsc_check(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  });
}

PetscErrorCode NewtonStep::apply_operator(Mat A, Vec x, Vec y) {
  void* context = nullptr;
  PetscCall(MatShellGetContext(A, &context));
  auto* self = static_cast<NewtonStep*>(context);
  PetscCall(MatMult(self->m_matrix_free.get(), x, y));
  if (self->m_settings.stress_velocity) PetscCall(MatMultAdd(self->m_correction.get(), x, y, y));
  return 0;
}

PetscErrorCode NewtonStep::converged(SNES, PetscInt iteration, PetscReal, PetscReal, PetscReal,
                                     SNESConvergedReason* reason, void* context) {
  auto* self = static_cast<NewtonStep*>(context);
  self->m_result.iterations = static_cast<int>(iteration);
  // BAGNOLD_TRACE=1: every Newton iteration's residuals, as the outer iteration's (advance.cpp).
  if (std::getenv("BAGNOLD_TRACE")) {
    const int worst = self->m_result.residuals.worst();
    const CellLocation where = self->m_worst_cell(worst);  // collective
    if (self->m_discretization.layout().comm().is_root()) {
      std::fprintf(stderr, "  newton %d:", static_cast<int>(iteration));
      for (const double r : self->m_result.residuals.value) std::fprintf(stderr, " %.3e", r);
      std::fprintf(stderr, "  worst %s in %s\n", equation_name(worst), where.text().c_str());
    }
  }
  *reason = SNES_CONVERGED_ITERATING;
  const double judged = self->m_result.judged;
  // PETSc 3.18 has no reason of a user's own: the judged residual is recorded as converged.
  if (self->m_result.abandoned) *reason = SNES_DIVERGED_MAX_IT;
  else if (!std::isfinite(judged)) *reason = SNES_DIVERGED_FNORM_NAN;
  else if (judged < self->m_settings.tolerance) *reason = SNES_CONVERGED_FNORM_ABS, self->m_result.converged = true;
  else if (iteration >= self->m_settings.max_outer_iterations) *reason = SNES_DIVERGED_MAX_IT;
  return 0;
}

PetscErrorCode NewtonStep::pre_check(SNESLineSearch, Vec x, Vec y, PetscBool* changed, void* context) {
  auto* self = static_cast<NewtonStep*>(context);
  return guarded([&] {
    // The closures at x again (the matrix-free products evaluated F beside it since).
    PetscVec scratch;
    petsc_check(VecDuplicate(x, scratch.out()), "VecDuplicate");
    self->evaluate(x, scratch.get());
    const StepUnknowns& unknowns = self->m_equations.unknowns();
    const auto& locals = unknowns.owned_locals(StepUnknowns::fraction);
    const auto offset = unknowns.block_offset(StepUnknowns::fraction);
    PetscScalar* values = nullptr;
    petsc_check(VecGetArray(y, &values), "VecGetArray");
    auto& change = self->m_fraction_change;
    // SNES steps to x − λ y.
    for (std::size_t r = 0; r < locals.size(); ++r)
      change[static_cast<std::size_t>(locals[r])] = -values[offset + static_cast<std::int64_t>(r)];
    IterationSums sums;
    self->m_compression->apply(*self->m_state, self->m_equations.fields(), change, sums);
    bool limited = false;
    for (std::size_t r = 0; r < locals.size(); ++r) {
      auto& value = values[offset + static_cast<std::int64_t>(r)];
      const double limited_value = -change[static_cast<std::size_t>(locals[r])];
      if (limited_value != value) limited = true, value = limited_value;
    }
    petsc_check(VecRestoreArray(y, &values), "VecRestoreArray");
    for (const auto i : {compression_damped, fraction_clamped_at_zero})
      self->m_result.interventions[i] += self->m_discretization.layout().comm().sum(sums.interventions[i]);
    *changed = self->m_discretization.layout().comm().max(limited ? 1.0 : 0.0) > 0.0 ? PETSC_TRUE : PETSC_FALSE;
  });
}

PetscErrorCode NewtonStep::post_check(SNESLineSearch, Vec, Vec, Vec w, PetscBool*, PetscBool* changed_w,
                                      void* context) {
  auto* self = static_cast<NewtonStep*>(context);
  return guarded([&] {
    const StepUnknowns& unknowns = self->m_equations.unknowns();
    *changed_w = PETSC_FALSE;
    if (!unknowns.present(StepUnknowns::fraction)) return;
    PetscScalar* values = nullptr;
    petsc_check(VecGetArray(w, &values), "VecGetArray");
    const auto offset = unknowns.block_offset(StepUnknowns::fraction);
    const auto rows = static_cast<std::int64_t>(unknowns.owned_locals(StepUnknowns::fraction).size());
    double clamped = 0.0;
    for (std::int64_t r = offset; r < offset + rows; ++r)
      if (const double empty = unknowns.entry(r, 0.0); values[r] < empty) values[r] = empty, clamped += 1.0;
    petsc_check(VecRestoreArray(w, &values), "VecRestoreArray");
    self->m_result.interventions[fraction_clamped_at_zero] += clamped;
    if (clamped > 0.0) *changed_w = PETSC_TRUE;
  });
}

StepResult NewtonStep::advance(run::FlowState& state, const run::FlowState& old, double dt, WorstCells& worst,
                               bool (*stop_probe)()) {
  m_state = &state;
  m_worst = &worst;
  m_stop_probe = stop_probe;
  m_result = StepResult{};
  m_have_evaluation = false;
  m_boundary_values(state);
  m_equations.start_step(old, dt);
  m_equations.unknowns().set_origin(state);
  m_equations.unknowns().gather(state, m_x.get());
  petsc_check(SNESSolve(m_snes.get(), nullptr, m_x.get()), "SNESSolve");
  SNESConvergedReason reason = SNES_CONVERGED_ITERATING;
  petsc_check(SNESGetConvergedReason(m_snes.get(), &reason), "SNESGetConvergedReason");
  PetscInt linear = 0;
  petsc_check(SNESGetLinearSolveIterations(m_snes.get(), &linear), "SNESGetLinearSolveIterations");
  m_result.linear_iterations[momentum_systems] = static_cast<double>(linear);
  // The state of the last evaluation is the solution SNES returns (its line search evaluates there last).
  PetscBool same = PETSC_FALSE;
  petsc_check(VecEqual(m_x.get(), m_evaluated_at.get(), &same), "VecEqual");
  if (!same) evaluate(m_x.get(), m_f.get());
  m_result.converged = m_result.converged && reason == SNES_CONVERGED_FNORM_ABS;
  if (!m_result.converged && !m_result.abandoned && reason != SNES_DIVERGED_MAX_IT)
    m_result.failure = std::string("the Newton solve of the step stopped (") + SNESConvergedReasons[reason] + ")";
  return m_result;
}

}  // namespace bagnold::solver
