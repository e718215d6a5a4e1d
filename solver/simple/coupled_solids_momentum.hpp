#pragma once
// The three solids momentum components solved as one linear system (numerics.solids_momentum =
// "coupled"), so that the transpose's cross part ∂_e(μ_s ∂_d u_e), e ≠ d, is in the matrix
// instead of on the right-hand side at the iterate.
//
// Why: where a stagnant, packed zone meets a flowing one, the edge viscosity (the mean of the
// four cells around an edge) takes the stagnant cells' large μ_s into the flowing cells' edges,
// and the cross part there carries forces many times a cell's weight that only cancel once u_d
// and u_e agree. Solved one component at a time, with the cross part explicit, that agreement
// converges by about 0.98 per outer iteration on the bins (docs/solver.md, "Residual norm");
// in one system it is the linear solver's job.
//
// The rows are the segregated predictor's (momentum_predictor.cpp): the same diagonal, drag
// elimination and relaxation, with each cross term c u_e moved from b (where the assembly put
// it at the iterate) to the matrix. Row numbering: each rank's rows of component 0, then 1,
// then 2, contiguous, so the system is PETSc's usual block of owned rows per rank.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class CoupledSolidsMomentum {
 public:
  CoupledSolidsMomentum(const Discretization& discretization, const KrylovSettings& krylov);

  // Row r (in component d's row order) of the solids: its assembled row with its off-diagonal
  // entries (global indices of d), the predictor's diagonal and right-hand side; inactive rows
  // (no solids) as an identity row. `velocity` is the iterate the cross terms were taken at.
  void set_row(int d, std::size_t r, const MomentumRow& row, double diagonal, double rhs,
               const std::array<std::vector<double>, 3>& velocity);
  // Solves from the iterate and writes all three components into `velocity` (owned faces and
  // halos).
  SolveReport solve(std::array<std::vector<double>, 3>& velocity);

 private:
  // The coupled global row of component e's unknown with global index g (of e's numbering).
  std::int64_t coupled(int e, std::int64_t g) const;
  // The same of the e-face stored at a local cell (owned or halo); -1 for none or cell < 0.
  std::int64_t coupled_at(int e, int cell) const;

  const Discretization& m_discretization;
  // Per rank: its first coupled row, and per component its first row and row count.
  std::vector<std::int64_t> m_rank_first;
  std::array<std::vector<std::int64_t>, 3> m_component_first, m_component_rows;
  std::array<std::int64_t, 3> m_offset{};  // this rank's first row of each component, 0-based
  std::array<std::vector<std::int64_t>, 3> m_index;  // per component and local cell: coupled_at
  SparsityPattern m_pattern;
  std::unique_ptr<LinearSystem> m_system;
  std::vector<double> m_x;
  std::vector<std::int64_t> m_columns;  // scratch of set_row
  std::vector<double> m_values;
};

}  // namespace bagnold::solver
