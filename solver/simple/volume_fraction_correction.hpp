#pragma once
// Step 3 of the outer iteration: the solids volume fraction correction
// (volume_fraction_correction.cpp).

#include <memory>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/compression_limit.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class VolumeFractionCorrection {
 public:
  // The linear solve's tolerances: ε' must be accurate far below the outer tolerance, since
  // the conservative update after convergence takes the fluxes this correction leaves.
  static constexpr double linear_relative_tolerance = 1e-8;
  static constexpr double linear_absolute_tolerance = 1e-14;

  VolumeFractionCorrection(const Discretization& discretization, const SolverSettings& settings,
                           const Closures& closures);

  // Corrects ε_s, ε_g and u_s in `state` after the pressure correction; `old` is the step's
  // start, `response` the predictor's e, `carried` the fractions the corrected velocities
  // carry. Adds the solids continuity residual's local sums, the limiters' counts and the
  // linear iterations. Returns false if the linear solve failed.
  bool correct(const run::FlowState& old, double dt, const ClosureFields& closures,
               const CorrectionResponse& response, const CarriedFractions& carried,
               run::FlowState& state, IterationSums& sums, WorstCells& worst, StepResult& record);

 private:
  const Discretization& m_discretization;
  const SolverSettings& m_settings;  // the residual's norm, and ρ_s, |g|, a_min for its forces
  CompressionLimit m_limit;
  std::unique_ptr<LinearSystem> m_system;
  std::vector<double> m_x, m_correction;  // scratch: owned rows, local cells
};

// ε_g = 1 − ε_s in every local fluid cell.
void update_gas_fraction(const Discretization& discretization, run::FlowState& state);

}  // namespace bagnold::solver
