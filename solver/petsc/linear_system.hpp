#pragma once
// A distributed sparse linear system A x = b, assembled row by row with global indices and
// solved with a PETSc KSP. The nonzero pattern is given once, exactly (PETSc's COO
// preallocation; an entry outside it is an error), and each assembly fills a value array in
// that pattern's order, handed to PETSc in one MatSetValuesCOO call, so an outer iteration
// re-fills the matrix without searching or reallocating. Each system has an options prefix ("momentum_",
// "pressure_") so PETSc command-line options tune it alone; options given in code are defaults
// that the command line overrides.

#include <cstdint>
#include <string>
#include <vector>

#include "solver/petsc/handle.hpp"
#include "solver/sparsity_pattern.hpp"

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
  // `pattern`: the rows owned by this rank (contiguous global block starting at `first_row`).
  LinearSystem(MPI_Comm comm, SparsityPattern pattern, std::int64_t first_row,
               const std::string& prefix, const KrylovSettings& settings);

  // One row: global column indices within its pattern (duplicates are summed, in the order
  // given) and values; and its right-hand side. Throws std::logic_error for a column outside
  // the pattern.
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
  SparsityPattern m_pattern;
  std::vector<double> m_values;  // in the pattern's order
  std::vector<double> m_rhs_values;
  std::string m_prefix;
  KrylovSettings m_settings;
  PetscMat m_matrix;
  PetscVec m_rhs, m_solution;
  PetscKsp m_ksp;
  bool m_assembled_once = false;
};

}  // namespace bagnold::solver
