#pragma once
// Step 2 of the outer iteration: the pressure correction from the mixture volume continuity
// (pressure_correction.cpp).

#include <memory>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

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
