#pragma once
// The two-fluid (Euler–Euler) solver on the staggered grid, as MFIX solves it: gas and one
// solids phase share the gas pressure P, are coupled by drag β, and the solids carry a pressure
// P_s and viscosity μ_s from the solids-stress closure (DESIGN.md, "Equations and algorithm"):
//   ∂(ε_g ρ_g u_g)/∂t + ∇·(ε_g ρ_g u_g u_g) = −ε_g ∇P + ∇·(ε_g μ_g ∇u_g) + ε_g ρ_g g + β (u_s − u_g)
//   ∂(ε_s ρ_s u_s)/∂t + ∇·(ε_s ρ_s u_s u_s) = −ε_s ∇P − ∇P_s + ∇·(μ_s ∇u_s) + ε_s ρ_s g + β (u_g − u_s)
//   ∂ε_s/∂t + ∇·(ε_s u_s) = 0,   ε_g = 1 − ε_s,   ∇·(ε_g u_g + ε_s u_s) = 0 (both incompressible).
// Either phase may be absent: gas alone (solids.enabled = false: ε_g = 1, β = 0, the single-phase
// solver), frozen solids (solids.momentum = false: a fixed bed), or solids in vacuum
// (gas.enabled = false: no gas momentum, no pressure correction).
//
// One time step (advance.cpp), outer iterations until every normalized residual is below
// numerics.tolerance. Each step is an object or function whose inputs and outputs are its
// arguments; what they hand each other is in iteration_fields.hpp:
//   0. closures on the current iterate (closures.hpp) → ClosureFields: β, ε_g μ_g, μ_s, λ_s,
//      dP_s/dε_s, γ̇, ∇·u_s (and P_s, γ̇_P, Θ in the state);
//   1. momentum predictors of both phases per direction (momentum_rows.hpp,
//      momentum_predictor.hpp) with partial elimination of the drag coupling → the velocities
//      and the CorrectionResponse d_m, e;
//   2. pressure correction from the mixture volume continuity (pressure_correction.hpp); both
//      phases' velocities respond to p' through their d coefficients;
//   3. solids volume fraction correction (volume_fraction_correction.hpp): solids continuity
//      with the solids-pressure gradient linearized through dP_s/dε_s, limited by
//      compression_limit.hpp; ε_g = 1 − ε_s;
//   4. where the closure transports Θ, the granular energy equation
//      (granular_energy_equation.hpp) on the corrected velocities and fractions;
// the fractions each face carries (CarriedFractions) are refreshed whenever a velocity or
// fraction changes. After convergence ε_s follows from the converged fluxes in conservative
// form (solids_conservation.hpp: solids mass conserved to round-off). The residuals of an
// iteration are reduced over the ranks in one Allreduce (step_record.hpp).

#include <array>
#include <memory>
#include <vector>

#include "solver/discretization.hpp"
#include "solver/newton/newton_step.hpp"
#include "solver/simple/anderson_mixing.hpp"
#include "solver/simple/closures.hpp"
#include "solver/simple/granular_energy_equation.hpp"
#include "solver/simple/momentum_predictor.hpp"
#include "solver/simple/pressure_correction.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "solver/simple/volume_fraction_correction.hpp"
#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class FlowSolver {
 public:
  FlowSolver(const deck::Deck& deck, const parallel::Domain& domain);

  // Sets the boundary values every stencil reads: given face velocities, boundary pressures,
  // the solids fraction of boundary cells.
  void apply_boundary_values(run::FlowState& state) const;
  // Advances `state` (holding the last iterate, initially `old`) by one time step dt. After
  // every outer iteration, if `stop_probe` returns true on any rank, all ranks abandon the step
  // together (StepResult::abandoned; `state` is then not a solution).
  StepResult advance(run::FlowState& state, const run::FlowState& old, double dt,
                     bool (*stop_probe)() = nullptr);
  // The time at which the next steps start [s], for what acts only over part of a run
  // (numerics.solids_bulk_viscosity_until). 0 until set.
  void set_step_start(double time) { m_closures.set_step_start(time); }

  // An extra gas momentum source [N/m³] at each face velocity of direction d (local_count()
  // entries, indexed by the owning cell), e.g. a manufactured solution's forcing. Empty: none.
  void set_momentum_source(int d, std::vector<double> source) {
    m_predictor.set_gas_source(d, std::move(source));
  }

  // The next step builds the pressure preconditioner afresh (numerics.pressure_preconditioner_steps):
  // the time loop calls it after a snapshot, where a restart from it builds its own, and before a
  // redone step, which then gets a hierarchy of its own matrix.
  void renew_preconditioners() {
    if (m_pressure) m_pressure->renew();
  }

  // Collective: the cell with the largest residual of `equation` in the last outer iteration.
  CellLocation worst_cell(int equation) const;

  // Net mass flux [kg/s] of a phase out through each boundary region (monitor).
  std::vector<double> boundary_mass_flux(const run::FlowState& state, Phase phase) const;
  // The solids mass flux per region [kg/s] through which the last converged step changed the
  // inventory: the fluxes conserve_solids used (before it updated ε_s, which changes the upwind
  // ε_s at an outlet), so the monitor's outflow balances the inventory to round-off. Falls back
  // to boundary_mass_flux(state, solids) where the solids do not move.
  std::vector<double> stepped_solids_flux(const run::FlowState& state) const;
  // max over both phases' stored face velocities of |u| dt/δ, δ the distance between the
  // centres of the two cells the face lies between (collective).
  double courant_number(const run::FlowState& state, double dt) const;

 private:
  // What the steps of an outer iteration hand each other.
  struct IterationFields {
    explicit IterationFields(std::size_t local_count)
        : closures(local_count), carried(local_count), response(local_count) {}
    ClosureFields closures;
    CarriedFractions carried;
    CorrectionResponse response;
    WorstCells worst;  // where each equation's row residual is largest, for the messages
  };

  // The velocity residuals are measured against: the largest face velocity in the domain, but at
  // least SolverSettings::least_speed (1e-3 of the reference speed: the fastest wall or inflow,
  // or sqrt(|g| L)); and at
  // most `cap` (10× the step start's), so that an iterate that blows up cannot make its own
  // residuals look small and be accepted. Counts the floor and the cap in `sums`.
  double residual_velocity_scale(const run::FlowState& state, double cap, IterationSums* sums) const;
  static constexpr double scale_growth_cap = 10.0;  // the cap, of the step start's scale
  // One outer iteration; false if a linear solve failed.
  bool iterate(run::FlowState& state, const run::FlowState& old, double dt, bool first,
               double velocity_scale, IterationSums& sums, StepResult& result);

  Discretization m_discretization;
  SolverSettings m_settings;
  Closures m_closures;
  MomentumPredictor m_predictor;
  std::unique_ptr<PressureCorrection> m_pressure;        // null without moving gas
  std::unique_ptr<VolumeFractionCorrection> m_fraction;  // null unless the solids move
  std::unique_ptr<GranularEnergyEquation> m_energy;      // null unless Θ is transported
  IterationFields m_fields;
  std::vector<double> m_stepped_solids_flux;  // set by conserve_solids
  std::unique_ptr<AndersonMixing> m_anderson;  // null: Picard (numerics.anderson_depth = 0)
  // numerics.step_solver = "newton" (newton_step.hpp): the walls' coefficients it holds, and it.
  std::unique_ptr<SolidsWallCoefficients> m_newton_walls;
  std::unique_ptr<NewtonStep> m_newton;
};

}  // namespace bagnold::solver
