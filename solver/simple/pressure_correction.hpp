#pragma once
// Step 2 of the outer iteration: the pressure correction from the mixture volume continuity
// (pressure_correction.cpp).

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// The pressure's BoomerAMG settings under numerics.pressure_preconditioner = "hypre" (PETSc
// option names without the "pressure_" prefix): HMIS coarsening, extended+i interpolation with at
// most 4 entries per row, and one level of aggressive coarsening, as hypre's users' guide advises
// for 3-D problems, with its strong threshold left at 0.25 (0.5 cost more here). More CG
// iterations than PETSc's defaults (Falgout coarsening, classical interpolation), each far
// cheaper: on the 2.5 mm bin on 2 ranks cut along gravity the preconditioner's applications take
// 0.37 of the time (docs/benchmarks.md, "The pressure multigrid's coarsening").
// -pressure_pc_hypre_boomeramg_* options override each.
std::vector<std::pair<std::string, std::string>> boomeramg_options();

class PressureCorrection {
 public:
  PressureCorrection(const deck::Deck& deck, const Discretization& discretization,
                     const SolverSettings& settings);

  // A new time step: the next solve builds its preconditioner afresh if renew() was called
  // since the last build, or numerics.pressure_preconditioner_steps steps have started since.
  void start_step();
  // The next step builds the preconditioner afresh: after a snapshot, where a restart from it
  // builds its own, and for a redone step, which gets a hierarchy of its own matrix.
  void renew() { m_steps_since_build = m_preconditioner_steps; }
  // Corrects P and both phases' velocities in `state` from the predicted velocities, the
  // predictor's responses d_m and the carried fractions; adds the continuity residual's local
  // sums and the linear iterations. Returns false if the linear solve failed.
  bool correct(const CorrectionResponse& response, const CarriedFractions& carried,
               run::FlowState& state, IterationSums& sums, WorstCells& worst, StepResult& record);

 private:
  const Discretization& m_discretization;
  const SolverSettings& m_settings;
  std::unique_ptr<LinearSystem> m_system;
  int m_preconditioner_steps = 1;  // numerics.pressure_preconditioner_steps
  // Steps started with the current preconditioner; at m_preconditioner_steps the next step
  // builds it (renew() sets it there, and so does the constructor).
  int m_steps_since_build = 0;
  std::vector<double> m_x, m_correction;  // scratch: owned rows, local cells
};

}  // namespace bagnold::solver
