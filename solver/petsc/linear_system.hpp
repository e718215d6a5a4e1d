#pragma once
// A distributed sparse linear system A x = b, assembled row by row with global indices and
// solved with a PETSc KSP. The nonzero pattern is given once, exactly (PETSc's COO
// preallocation; an entry outside it is an error), and each assembly fills a value array in
// that pattern's order, handed to PETSc in one MatSetValuesCOO call, so an outer iteration
// re-fills the matrix without searching or reallocating. Each system has an options prefix ("momentum_",
// "pressure_") so PETSc command-line options tune it alone; options given in code are defaults
// that the command line overrides.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
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
  // Rows whose off-diagonal values are all zero (a solids row where there are no solids) are
  // solved directly, x_i = b_i / a_ii, and left out of the Krylov solve, which sees their
  // values as known (moved to the other rows' right-hand sides). Only the coupled rows cost
  // Krylov work; the answer is the same system's.
  bool solve_decoupled_rows_directly = false;
  // PETSc options under the system's prefix, without it and its dash ({"pc_hypre_boomeramg_agg_nl",
  // "1"}), for pc_type: they hold unless the command line or PETSC_OPTIONS gives the same option
  // or another preconditioner, and never stay in PETSc's options database. One that PETSc does
  // not read (misspelled) throws std::logic_error when the KSP is made.
  std::vector<std::pair<std::string, std::string>> default_options;
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
  void keep_preconditioner();
  // A fresh KSP and preconditioner: the next solve builds its preconditioner from nothing, as the
  // first solve of a restarted run does. (GAMG carries state from one set-up of a KSP to the
  // next, so rebuilding it in place would make a continued run differ from a restarted one.)
  void renew_preconditioner();
  // Solves with `x` (owned entries, in row order) as the initial guess; x is overwritten.
  SolveReport solve(std::vector<double>& x);
  // The work units the next solve's assembly segment counts (busy_segments.hpp): by default
  // this rank's rows; a caller that assembles several systems before solving them gives the
  // first solved all their rows and the others none.
  void set_assembly_units(double units) { m_assembly_units = units; }
  // Rows in the last solve's Krylov system on this rank (all owned rows unless
  // solve_decoupled_rows_directly).
  std::int64_t krylov_rows() const;

 private:
  void create_ksp();  // (re)creates the KSP with the settings and the command-line options
  // KrylovSettings::default_options into PETSc's options database before KSPSetFromOptions
  // (those written), and out again after it; an unused one throws.
  std::vector<std::string> write_default_options() const;
  void take_back_default_options(const std::vector<std::string>& written) const;
  SolveReport solve_assembled(std::vector<double>& x);  // solve() after its busy segment's mark
  // KSPSolve of matrix · solution = rhs with m_ksp; a solution with Inf or NaN recreates the KSP.
  SolveReport run_ksp(Mat matrix, Vec rhs, Vec solution);
  // solve() under solve_decoupled_rows_directly, after the matrix and right-hand side are set.
  SolveReport solve_coupled_rows(std::vector<double>& x);
  // Fills m_next_coupled with this rank's coupled rows (global) and x at the others (b / a_ii).
  struct DecoupledRows {
    bool nonzero = false;  // a directly solved value is nonzero (the coupled rows see it)
    bool finite = true;    // every directly solved value is finite
  };
  DecoupledRows split_decoupled_rows(std::vector<double>& x);

  MPI_Comm m_comm;
  std::int64_t m_rows;
  std::int64_t m_first_row;
  SparsityPattern m_pattern;
  std::vector<double> m_values;  // in the pattern's order
  std::vector<double> m_rhs_values;
  std::string m_prefix;
  KrylovSettings m_settings;
  int m_assembly_segment, m_solve_segment;  // this system's busy segments (busy_segments.hpp)
  std::optional<double> m_assembly_units;  // set_assembly_units for the next solve; none: the rows
  PetscMat m_matrix;
  PetscVec m_rhs, m_solution;
  PetscKsp m_ksp;
  bool m_assembled_once = false;

  // The coupled rows' system (solve_decoupled_rows_directly): its rows, this rank's in global
  // numbering, and the submatrix, vectors and index set over them, rebuilt when the rows change.
  std::vector<PetscInt> m_coupled, m_next_coupled;
  bool m_coupled_built = false;
  PetscIs m_coupled_rows;
  PetscMat m_coupled_matrix;
  PetscVec m_coupled_rhs, m_coupled_solution, m_known, m_known_product;
};

}  // namespace bagnold::solver
