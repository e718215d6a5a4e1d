#pragma once
// Step 4 of the outer iteration where the closure transports Θ: the granular energy equation
// (models/stress/granular_energy.hpp), implicit Euler, finite volumes on the cells, after the
// volume fraction correction (as MFIX's SOLVE_GRANULAR_ENERGY follows its solids correction):
//   a_P Θ_P − Σ a_nb Θ_nb = b, with
//   a_nb = (3/2) max(−F_out, 0) + κ_f A/δ       F_out the solids mass flux out through the face
//                                               (ρ_s A ε_s,up u_s, the fraction it carries),
//                                               κ_f the harmonic mean of the two cells' κ_s
//   a_P  = (3/2) ρ_s ε_s° V/dt + Σ a_nb + V [P_s/Θ max(tr D, 0) + (3/2) c √Θ* + 3β]
//   b    = (3/2) ρ_s ε_s° V/dt Θ° + V [P_s/Θ Θ* max(−tr D, 0) + μ_s (γ̇² − ⅔ (tr D)²)
//          + λ_s (tr D)² + ½ c Θ*^{3/2} + S_slip]
// (° the step's start, * the iterate; convection in the form with the solids continuity
// subtracted, as MFIX's; the dissipation c Θ^{3/2} linearized by Newton about Θ*). Every a_nb
// ≥ 0, a_P ≥ Σ a_nb and b ≥ 0: an M-matrix with a non-negative right-hand side, so Θ ≥ 0 comes
// from the discretization; the linear solver's round-off below 0 is set to 0 and counted
// (temperature_clamped_at_zero). A wall whose solids_wall is johnson-jackson exchanges
// Johnson & Jackson's (1987) energy flux q_w = A √Θ − B Θ^{3/2} through each wall face
// (models/wall/johnson_jackson.hpp, at the cell's φ, the closure's wall g0 and φ_max and the
// centre's tangential slip): A √Θ* into b, B Θ^{3/2} linearized by Newton as the dissipation.
// Every other wall, opening and blocked cell conducts no energy (adiabatic); solids entering
// through an inflow bring Θ = 0. Cells where the theory holds Θ
// (mfix-default's plastic regime) or that hold no solids (ε_s ≤ numerics.vacant_fraction) get Θ = 0.
// Its residual is Σ|R_P| / Σ max(|a_P Θ*_P|, |b_P|) at the iterate, before the solve.

#include <memory>
#include <vector>

#include <optional>

#include "models/stress/solids_stress.hpp"
#include "models/wall/johnson_jackson.hpp"
#include "solver/discretization.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/closures.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class GranularEnergyEquation {
 public:
  static constexpr double linear_relative_tolerance = 1e-10;
  static constexpr double linear_absolute_tolerance = 1e-20;
  // Reads ρ_s and numerics.vacant_fraction (MFIX's ZERO_EP_S) from `settings`.
  GranularEnergyEquation(const Discretization& discretization, const SolverSettings& settings,
                         const Closures& closures);

  // Solves for Θ (state.granular_temperature) with the iterate's velocities, fractions and
  // closures; `old` is the step's start. Adds its residual's local sums, the clamp count and
  // the linear iterations. Returns false if the linear solve failed.
  bool solve(const run::FlowState& old, double dt, const ClosureFields& closures,
             const CarriedFractions& carried, run::FlowState& state, IterationSums& sums,
             WorstCells& worst, StepResult& record);

 private:
  void evaluate_terms(const run::FlowState& state, const ClosureFields& closures);
  // Johnson–Jackson's q_w = A √Θ − B Θ^{3/2} [W/m²] on the wall face of cell l towards `face`
  // (region r): {A, B}.
  std::array<double, 2> wall_flux_coefficients(const run::FlowState& state, int l, int face, int r) const;

  const Discretization& m_discretization;
  const models::GranularEnergyTheory& m_theory;
  const models::SolidsStressModel& m_closure;
  // Per boundary region: its Johnson–Jackson wall, or none (adiabatic).
  std::vector<std::optional<models::wall::JohnsonJacksonWall>> m_walls;
  models::Material m_material;
  double m_density;        // ρ_s
  double m_gas_viscosity;  // μ_g, 0 without moving gas
  double m_vacant_fraction;  // numerics.vacant_fraction
  std::unique_ptr<LinearSystem> m_system;
  std::vector<double> m_x;  // owned rows
  // The theory's terms at every local cell (0 outside fluid cells), and its inputs.
  std::vector<double> m_fraction, m_temperature, m_drag, m_slip;
  std::vector<double> m_pressure_per_temperature, m_shear, m_bulk, m_conductivity,
      m_dissipation, m_slip_production, m_held;
};

}  // namespace bagnold::solver
