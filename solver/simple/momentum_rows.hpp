#pragma once
// Step 1a of the outer iteration: the momentum rows of one phase for one velocity component,
// before drag, relaxation and partial elimination (momentum_assembly.cpp).

#include <array>
#include <cstdint>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solids_wall.hpp"
#include "solver/simple/solver_settings.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// One assembled momentum row of one phase. reset() clears what an assembly accumulates (the
// entries are written before they are read), so refilling a row costs no more than filling it.
struct MomentumRow {
  void reset() {
    a = b = neighbours_a = neighbours_u = transient = fraction = area = volume = weight = force = wall_shear = viscous = 0.0;
    active = true;
    count = 0;
    cross_count = 0;
  }

  double a = 0.0;              // diagonal: convection, diffusion, transient
  double b = 0.0;              // sources: pressure, gravity, transient, TVD correction
  double neighbours_a = 0.0;   // Σ a_nb
  double neighbours_u = 0.0;   // Σ a_nb u_nb at the current iterate
  double transient = 0.0;      // ε ρ V/dt, the part of a from the time derivative
  double fraction = 0.0;       // ε of the phase at the face velocity
  double area = 0.0;           // face area normal to the velocity
  double volume = 0.0;         // control volume of the face velocity
  double weight = 0.0;         // ε ρ V |g|
  double force = 0.0;          // Σ |force| of weight, pressure, P_s, walls, body force, floor (not drag)
  double wall_shear = 0.0;     // the walls' tangential force along d on the control volume [N]
  double viscous = 0.0;        // the viscous force along d on the control volume at the iterate,
                               // walls' included, the dilatational term not [N]
  bool active = true;          // false: a solids row below the threshold, u_s = 0
  int count = 0;               // off-diagonal entries
  std::int64_t columns[7];     // the off-diagonal entries' columns, then room for the diagonal's
  double values[7];            // −a_nb, then the predictor's diagonal
  // The transpose's cross part, which b holds at the iterate, as its terms c u_e: the local cell
  // whose face carries u_e, the component e and c (coupled_solids_momentum.hpp).
  int cross_count = 0;
  int cross_cell[8];
  int cross_component[8];
  double cross_coefficient[8];
};

// What the assembly reads besides the iterate.
struct MomentumAssemblyInputs {
  const Discretization& discretization;
  const SolverSettings& settings;
  const run::FlowState& old;  // the step's start
  double dt;                  // [s]
  const ClosureFields& closures;
  const CarriedFractions& carried;
  // An extra gas momentum source [N/m³] per component (empty: none).
  const std::array<std::vector<double>, 3>& gas_source;
};

// Scratch of the assembly (sized there), per local cell: the mean viscosity of the cell and its
// + neighbour along d; under numerics.viscosity_average = "yield-bounded" (solids) instead, per
// direction e ≠ d, the viscosity of the edge between the cell, its + neighbour along d and the
// two cells above them along e, which the rows on both sides of the edge read; under
// numerics.viscosity_linearization = "newton" (solids), the pair means of the tangent
// viscosities μ_s f_de that the faces normal to each direction e take; and the mass flux per
// unit area and density through the cell's face along each e (its velocity times the fraction
// carried there), which the rows of up to four control volumes read.
struct MomentumAssemblyScratch {
  std::vector<double> secant;
  std::array<std::vector<double>, 3> bounded_edge;
  std::array<std::vector<double>, 3> tangent;
  std::array<std::vector<double>, 3> flux;
};

// Fills `rows` (one per owned unknown face along d, in row order) for `phase` from the iterate
// `state`. Partial-slip solids walls take c_w from `walls`, re-evaluated when
// refresh_wall_coefficients (the step's first outer iteration), else as held.
void assemble_momentum_rows(const MomentumAssemblyInputs& in, Phase phase, int d,
                            const run::FlowState& state, SolidsWallCoefficients* walls,
                            bool refresh_wall_coefficients, std::vector<MomentumRow>& rows,
                            MomentumAssemblyScratch& scratch);

}  // namespace bagnold::solver
