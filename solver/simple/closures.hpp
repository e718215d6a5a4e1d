#pragma once
// Step 0 of the outer iteration: the closures on the current iterate, at cell centres.
//   β        the drag law (models/drag/) at ε_g and the slip speed |u_g − u_s| between the
//            phases' centre velocities (centre_velocity, discretization.hpp);
//   ε_g μ_g  the gas's effective viscosity, and ∇·u_g (velocity_divergence);
//   P_s, dP_s/dε_s, μ_s, λ_s, Θ   the solids-stress model (models/stress/) at ε_s and the
//            strain-rate invariants of the solids velocity (solver/strain_rate.hpp); λ_s gains
//            r μ_s with numerics.solids_bulk_viscosity_ratio r > 0, in the steps that start
//            before numerics.solids_bulk_viscosity_until (set_step_start).
// Evaluated over every local fluid cell (the halo included, since the strain rate is
// exchanged), so the momentum stencils need no further exchange.
// With numerics.pressure_shear_rate_relaxation_time τ_P > 0, P_s and dP_s/dε_s come from a second
// evaluation at γ̇_P, the strain rate relaxed in time: implicit Euler of dγ̇_P/dt = (γ̇ − γ̇_P)/τ_P
// per cell, from the step's old γ̇_P (γ̇_P = γ̇ where old has none: a fresh start, or a restart
// from a snapshot written before the field existed). μ_s and Θ keep the current rate.
// P_s, γ̇_P and Θ go into the state (written to snapshots); the rest into ClosureFields. The
// outflow cells of a pressure_outflow region with solids_pressure = "zero-gradient" take the P_s
// of their fluid neighbour (MFIX's set_outflow), so the solids leave without a P_s drop across
// the outlet face; with "zero" (the default) their P_s stays 0.
// With numerics.viscosity_linearization = "newton" the closure is evaluated a second time at
// the strain-rate tensor scaled by 1 + h (h = 10⁻⁴), which gives the flow index
// n = 1 + dln μ_s/dln γ̇ per cell, and with the strain direction N = √2 D/γ̇ the tangent factors
// of ClosureFields (the Newton linearization of τ = 2 μ_s(γ̇) D: δτ = 2 μ_s (δD + (n − 1) N (N:δD))).
// Where the closure transports Θ (models::SolidsStressModel::granular_energy()), it takes the
// iterate's Θ (the granular energy equation's, granular_energy_equation.hpp) and β instead of
// its algebraic balance, and hands Θ back unchanged (0 where the theory holds it there).

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "models/drag/drag_law.hpp"
#include "models/stress/solids_stress.hpp"
#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/strain_rate.hpp"
#include "src/deck/deck.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// |u_g − u_s| at the centre of local cell l, from both phases' centre velocities.
double centre_slip_speed(const parallel::Layout& layout, const run::FlowState& state, int l);

// The tangent viscosity factors of ClosureFields::tangent_factor, 1 + w (n − 1) N_ab S_ab per
// symmetric component (w = 2 on the diagonal, 4 off it), from the fields' flow index n and strain
// direction N, with `direction` S in place of the second N: S = N gives the Newton tangent of
// τ = 2 μ_s(γ̇) D; the stress–velocity linearization (step_equations.hpp) takes its own S.
void tangent_factors(const ClosureFields& fields, const std::array<std::vector<double>, 6>& direction,
                     std::array<std::vector<double>, 6>& factors);

class Closures {
 public:
  Closures(const deck::Deck& deck, const Discretization& discretization);

  // Fills `fields` (and state's P_s, γ̇_P, Θ) from the iterate `state`; `old` holds the step's
  // start (its γ̇_P), dt the step.
  void evaluate(const Discretization& discretization, run::FlowState& state,
                const run::FlowState& old, double dt, ClosureFields& fields);

  // The time at which the step being solved starts [s] (where the bulk viscosity ends).
  void set_step_start(double time) { m_step_start = time; }

  // ClosureFields::flow_index and strain_direction at the state of the last evaluate() (a second
  // closure evaluation; kept only when the solids move and the tensor is kept: under
  // numerics.viscosity_linearization = "newton" or numerics.step_solver = "newton").
  void evaluate_flow_index(ClosureFields& fields);

  // The solids-stress model, null unless the solids move.
  const models::SolidsStressModel* stress() const { return m_stress.get(); }
  const models::Material& material() const { return m_material; }
  double gas_viscosity() const { return m_gas_moves ? m_gas_viscosity : 0.0; }

 private:
  void evaluate_drag(const Discretization& discretization, const run::FlowState& state,
                     ClosureFields& fields);
  void evaluate_solids_stress(const Discretization& discretization, run::FlowState& state,
                              const run::FlowState& old, double dt, ClosureFields& fields);

  models::Material m_material;
  models::DragProperties m_drag_properties;
  double m_gas_viscosity;
  double m_relaxation_time;  // τ_P [s], 0: off
  double m_bulk_viscosity_ratio;  // r of numerics.solids_bulk_viscosity_ratio: λ_s += r μ_s
  double m_bulk_viscosity_until;  // numerics.solids_bulk_viscosity_until [s]
  double m_step_start = 0.0;      // [s]
  bool m_gas_moves;
  // (outflow cell, its fluid neighbour): P_s copied across a zero-gradient solids outlet.
  std::vector<std::pair<int, int>> m_outflow_copies;
  std::unique_ptr<models::DragLaw> m_drag;              // null without both phases
  std::unique_ptr<models::SolidsStressModel> m_stress;  // null unless the solids move
  std::vector<WallGhost> m_strain_rate_ghosts;  // per local cell: its ghost in γ̇ (empty: none)
  // Scratch, sized once: the fluid cells and the closures' inputs and outputs over them.
  std::vector<int> m_cells;
  std::vector<double> m_fraction, m_rate, m_pressure_rate, m_divergence, m_slip;
  std::vector<double> m_pressure, m_derivative, m_shear, m_bulk, m_temperature;
  std::vector<double> m_transported, m_drag_at;  // Θ and β in, where Θ is transported
  std::array<std::vector<double>, 3> m_unused;  // outputs of the second evaluation at γ̇_P
  bool m_newton = false;  // numerics.viscosity_linearization = "newton"
  StrainTensor m_tensor;  // D per local cell (Newton only)
  std::vector<double> m_probe_rate, m_probe_divergence, m_probe_shear;  // the evaluation at (1 + h) D

  bool m_keep_tensor = false;  // D per cell kept: for the tangent or the Newton step
  models::SolidsState m_last_input;  // the last evaluation's inputs (spans into the scratch above)
  void evaluate_tangent_factors(ClosureFields& fields);
};

}  // namespace bagnold::solver
