#pragma once
// A distributed sparse linear system A x = b, assembled row by row with global indices and
// solved with a PETSc KSP. The matrix keeps its nonzero pattern between assemblies, so an outer
// iteration re-fills it without reallocating. Each system has an options prefix ("momentum_",
// "pressure_") so PETSc command-line options tune it alone; options given in code are defaults
// that the command line overrides.

#include <cstdint>
#include <string>
#include <vector>

#include "solver/petsc/handle.hpp"

namespace bagnold::solver {

struct KrylovSettings {
  std::string ksp_type = "bcgs";     // PETSc KSPType
  std::string pc_type = "bjacobi";   // PETSc PCType
  double relative_tolerance = 1e-3;
  double absolute_tolerance = 1e-12;
  int max_iterations = 500;
  bool constant_null_space = false;  // pure Neumann pressure problem
};

struct SolveReport {
  int iterations = 0;
  bool converged = false;
  double residual_norm = 0.0;
  std::string reason;  // PETSc's KSPConvergedReason, as text
};

class LinearSystem {
 public:
  // `rows`: rows owned by this rank (contiguous global block starting at `first_row`).
  LinearSystem(MPI_Comm comm, std::int64_t rows, std::int64_t first_row, const std::string& prefix,
               const KrylovSettings& settings);

  // One row: global column indices (duplicates are summed) and values; and its right-hand side.
  void set_row(std::int64_t row, const std::int64_t* columns, const double* values, int count,
               double rhs);
  // Keep the preconditioner built for an earlier matrix (e.g. within one time step, where the
  // pressure matrix changes little between outer iterations) instead of rebuilding it.
  void reuse_preconditioner(bool reuse);
  // Solves with `x` (owned entries, in row order) as the initial guess; x is overwritten.
  SolveReport solve(std::vector<double>& x);

 private:
  void create_ksp();  // (re)creates the KSP with the settings and the command-line options

  MPI_Comm m_comm;
  std::int64_t m_rows;
  std::int64_t m_first_row;
  std::string m_prefix;
  KrylovSettings m_settings;
  PetscMat m_matrix;
  PetscVec m_rhs, m_solution;
  PetscKsp m_ksp;
  bool m_assembled_once = false;
};

}  // namespace bagnold::solver
