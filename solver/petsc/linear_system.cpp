#include "solver/petsc/linear_system.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

PetscSession::PetscSession(int* argc, char*** argv) {
  petsc_check(PetscInitialize(argc, argv, nullptr, nullptr), "PetscInitialize");
}

PetscSession::~PetscSession() { PetscFinalize(); }

void PetscSession::add_options(const std::string& options) {
  if (options.empty()) return;
  petsc_check(PetscOptionsInsertString(nullptr, options.c_str()), "PetscOptionsInsertString");
  PetscBool log_view = PETSC_FALSE;
  petsc_check(PetscOptionsHasName(nullptr, nullptr, "-log_view", &log_view), "PetscOptionsHasName");
  if (log_view) petsc_check(PetscLogDefaultBegin(), "PetscLogDefaultBegin");
}

LinearSystem::LinearSystem(MPI_Comm comm, std::int64_t rows, std::int64_t first_row,
                           const std::string& prefix, const KrylovSettings& settings)
    : m_comm(comm), m_rows(rows), m_first_row(first_row), m_prefix(prefix), m_settings(settings) {
  const auto n = static_cast<PetscInt>(rows);
  // At most 7 nonzeros per row (a cell and its 6 face neighbours) on and off the diagonal block.
  petsc_check(MatCreateAIJ(comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, 7, nullptr, 7, nullptr,
                           m_matrix.out()), "MatCreateAIJ");
  petsc_check(MatSetOption(m_matrix.get(), MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE),
              "MatSetOption");
  petsc_check(MatCreateVecs(m_matrix.get(), m_solution.out(), m_rhs.out()), "MatCreateVecs");
  create_ksp();
}

void LinearSystem::set_row(std::int64_t row, const std::int64_t* columns, const double* values,
                           int count, double rhs) {
  PetscInt r = static_cast<PetscInt>(row);
  PetscInt cols[8];
  PetscScalar vals[8];
  int used = 0;
  for (int i = 0; i < count; ++i) {
    const auto c = static_cast<PetscInt>(columns[i]);
    int j = 0;
    while (j < used && cols[j] != c) ++j;
    if (j == used) {
      cols[used] = c;
      vals[used++] = values[i];
    } else {
      vals[j] += values[i];
    }
  }
  petsc_check(MatSetValues(m_matrix.get(), 1, &r, used, cols, vals, INSERT_VALUES), "MatSetValues");
  petsc_check(VecSetValue(m_rhs.get(), r, rhs, INSERT_VALUES), "VecSetValue");
}

void LinearSystem::create_ksp() {
  petsc_check(KSPCreate(m_comm, m_ksp.out()), "KSPCreate");
  petsc_check(KSPSetOptionsPrefix(m_ksp.get(), m_prefix.c_str()), "KSPSetOptionsPrefix");
  petsc_check(KSPSetType(m_ksp.get(), m_settings.ksp_type.c_str()), "KSPSetType");
  PC pc = nullptr;
  petsc_check(KSPGetPC(m_ksp.get(), &pc), "KSPGetPC");
  petsc_check(PCSetType(pc, m_settings.pc_type.c_str()), "PCSetType");
  petsc_check(KSPSetTolerances(m_ksp.get(), m_settings.relative_tolerance,
                               m_settings.absolute_tolerance, PETSC_DEFAULT,
                               m_settings.max_iterations), "KSPSetTolerances");
  petsc_check(KSPSetInitialGuessNonzero(m_ksp.get(), PETSC_TRUE), "KSPSetInitialGuessNonzero");
  // The outer iteration hands over a good guess: reduce its residual by the relative tolerance
  // (PETSc's default measures against ||b||, which stalls the outer loop near that tolerance).
  petsc_check(KSPConvergedDefaultSetUIRNorm(m_ksp.get()), "KSPConvergedDefaultSetUIRNorm");
  petsc_check(KSPSetFromOptions(m_ksp.get()), "KSPSetFromOptions");
}

void LinearSystem::reuse_preconditioner(bool reuse) {
  petsc_check(KSPSetReusePreconditioner(m_ksp.get(), reuse ? PETSC_TRUE : PETSC_FALSE),
              "KSPSetReusePreconditioner");
}

SolveReport LinearSystem::solve(std::vector<double>& x) {
  petsc_check(MatAssemblyBegin(m_matrix.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(m_matrix.get(), MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  petsc_check(VecAssemblyBegin(m_rhs.get()), "VecAssemblyBegin");
  petsc_check(VecAssemblyEnd(m_rhs.get()), "VecAssemblyEnd");
  if (!m_assembled_once && m_settings.constant_null_space) {
    PetscNullSpace null_space;
    petsc_check(MatNullSpaceCreate(m_comm, PETSC_TRUE, 0, nullptr, null_space.out()),
                "MatNullSpaceCreate");
    petsc_check(MatSetNullSpace(m_matrix.get(), null_space.get()), "MatSetNullSpace");
    // The right-hand side of a closed domain sums to round-off; remove it exactly.
  }
  if (m_settings.constant_null_space) {
    MatNullSpace null_space = nullptr;
    petsc_check(MatGetNullSpace(m_matrix.get(), &null_space), "MatGetNullSpace");
    if (null_space) petsc_check(MatNullSpaceRemove(null_space, m_rhs.get()), "MatNullSpaceRemove");
  }
  m_assembled_once = true;
  petsc_check(KSPSetOperators(m_ksp.get(), m_matrix.get(), m_matrix.get()), "KSPSetOperators");
  PetscScalar* values = nullptr;
  petsc_check(VecGetArray(m_solution.get(), &values), "VecGetArray");
  std::copy(x.begin(), x.begin() + m_rows, values);
  petsc_check(VecRestoreArray(m_solution.get(), &values), "VecRestoreArray");
  petsc_check(KSPSolve(m_ksp.get(), m_rhs.get(), m_solution.get()), "KSPSolve");
  SolveReport report;
  PetscInt iterations = 0;
  KSPConvergedReason reason;
  petsc_check(KSPGetIterationNumber(m_ksp.get(), &iterations), "KSPGetIterationNumber");
  petsc_check(KSPGetConvergedReason(m_ksp.get(), &reason), "KSPGetConvergedReason");
  petsc_check(KSPGetResidualNorm(m_ksp.get(), &report.residual_norm), "KSPGetResidualNorm");
  report.iterations = static_cast<int>(iterations);
  report.converged = reason > 0;
  report.reason = KSPConvergedReasons[reason];
  const PetscScalar* solved = nullptr;
  petsc_check(VecGetArrayRead(m_solution.get(), &solved), "VecGetArrayRead");
  std::copy(solved, solved + m_rows, x.begin());
  petsc_check(VecRestoreArrayRead(m_solution.get(), &solved), "VecRestoreArrayRead");
  // A matrix with Inf or NaN (a diverging outer iteration) can leave the preconditioner failed
  // for every later solve, even of a healthy matrix: start the next solve from a fresh KSP.
  int finite = std::all_of(x.begin(), x.begin() + m_rows, [](double v) { return std::isfinite(v); });
  MPI_Allreduce(MPI_IN_PLACE, &finite, 1, MPI_INT, MPI_MIN, m_comm);
  if (reason == KSP_DIVERGED_NANORINF || reason == KSP_DIVERGED_PC_FAILED || !finite) create_ksp();
  return report;
}

}  // namespace bagnold::solver
