#pragma once
// Step 1 of the outer iteration: the momentum predictors of both phases for one velocity
// component, with partial elimination of the drag coupling (momentum_predictor.cpp).

#include <array>
#include <memory>
#include <vector>

#include "solver/petsc/linear_system.hpp"
#include "solver/simple/coupled_solids_momentum.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "solver/simple/row_trace.hpp"
#include "solver/simple/step_record.hpp"

namespace bagnold::solver {

class MomentumPredictor {
 public:
  // `deck` for the linear solvers' tolerance and the solids wall laws; `closure` the solids-stress
  // model the wall laws ask (null unless the solids move), which must outlive this.
  MomentumPredictor(const deck::Deck& deck, const Discretization& discretization,
                    const SolverSettings& settings, const models::SolidsStressModel* closure);

  // An extra gas momentum source [N/m³] at each face velocity of direction d (local_count()
  // entries, indexed by the owning cell), e.g. a manufactured solution's forcing. Empty: none.
  void set_gas_source(int d, std::vector<double> source) {
    m_gas_source[static_cast<std::size_t>(d)] = std::move(source);
  }

  const std::array<std::vector<double>, 3>& gas_source() const { return m_gas_source; }

  struct Inputs {
    const run::FlowState& old;  // the step's start
    double dt;                  // [s]
    const ClosureFields& closures;
    const CarriedFractions& carried;
    double velocity_scale;            // U of the residual normalization [m/s]
    bool refresh_wall_coefficients;   // the step's first outer iteration
  };

  // Solves both phases' component d into `state`, fills the corrections' responses for d, adds
  // the residuals' local sums and the linear iterations. Returns false if a linear solve failed
  // (state then holds what the solver returned).
  bool predict(int d, const Inputs& in, run::FlowState& state, CorrectionResponse& response,
               IterationSums& sums, WorstCells& worst, StepResult& record);

  // numerics.solids_momentum = "coupled": predict() assembles the solids rows of each component
  // into one system, which this solves (after predict() for d = 0, 1, 2) into `state`.
  bool coupled_solids() const { return m_coupled != nullptr; }
  bool solve_coupled_solids(run::FlowState& state, StepResult& record);

 private:
  const Discretization& m_discretization;
  const SolverSettings& m_settings;
  std::unique_ptr<SolidsWallCoefficients> m_walls;  // null unless the solids move
  std::array<std::array<std::unique_ptr<LinearSystem>, 3>, 2> m_systems;  // [phase][d]
  std::unique_ptr<CoupledSolidsMomentum> m_coupled;  // null unless numerics.solids_momentum = "coupled"
  std::array<std::vector<double>, 3> m_gas_source;
  std::array<std::vector<MomentumRow>, 2> m_rows;  // scratch, per phase
  std::array<std::vector<double>, 2> m_x;          // scratch, per phase
  MomentumAssemblyScratch m_assembly_scratch;      // scratch of the assembly
  RowTrace m_row_trace;                            // BAGNOLD_TRACE_ROWS (row_trace.hpp)
};

}  // namespace bagnold::solver
