#pragma once
// The values the steps of one outer iteration hand each other (flow_solver.hpp, "One time
// step"). Each is written by one step and read by the ones after it; all are per local cell
// (owned and halo), indexed like the flow fields.

#include <array>
#include <vector>

namespace bagnold::solver {

// Step 0's output, the closures at cell centres on the current iterate.
struct ClosureFields {
  explicit ClosureFields(std::size_t local_count);
  std::vector<double> drag;                      // β [kg/(m³ s)]
  std::array<std::vector<double>, 2> viscosity;  // ε_g μ_g and μ_s [Pa s]
  std::vector<double> bulk_viscosity;            // λ_s [Pa s] of the closure (+ r μ_s)
  std::vector<double> pressure_derivative;       // dP_s/dε_s [Pa] at fixed strain rate
  std::vector<double> strain_rate;               // γ̇ = sqrt(2 D:D) of the solids [1/s]
  std::array<std::vector<double>, 2> divergence;  // ∇·u_g, ∇·u_s [1/s] (0 beyond fluid cells)
  // numerics.viscosity_linearization = "newton": per symmetric component (a, b) of D
  // (symmetric_component in strain_rate.hpp), the solids' tangent viscosity on the faces that
  // carry ∂_b u_a over μ_s: 1 + (n − 1) N_ab² (a = b) or 1 + 2 (n − 1) N_ab² (a ≠ b), with
  // n = dln τ/dln γ̇ and N = √2 D/γ̇ (closures.cpp). Empty under Picard.
  std::array<std::vector<double>, 6> tangent_factor;
  // Closures::evaluate_flow_index: per cell the flow index n = dln τ/dln γ̇ of the closure at its
  // strain rate (1 where the cell has none), and per symmetric component the strain direction
  // N_ab = D_ab/γ̇ (2 N:N = 1; 0 where γ̇ = 0). Empty until evaluated.
  std::vector<double> flow_index;
  std::array<std::vector<double>, 6> strain_direction;
};

// The fraction of each phase carried through each face (per phase, direction d, owning cell):
// the gas's linear face value, the solids' upwind value (carried_fraction in
// face_fractions.hpp). Refreshed whenever a velocity or fraction it depends on changes, so each
// face's value is computed once per change instead of by every stencil that reads it.
struct CarriedFractions {
  explicit CarriedFractions(std::size_t local_count);
  std::array<std::array<std::vector<double>, 3>, 2> value;  // [phase][d]
  const std::vector<double>& operator()(int phase, int d) const {
    return value[static_cast<std::size_t>(phase)][static_cast<std::size_t>(d)];
  }
};

// The momentum predictor's output for the corrections: on every unknown face along d,
//   u_m += d_m (p'_c − p'_n)    (both phases, pressure correction)
//   u_s += e (K_c ε'_c − K_n ε'_n)   (solids, volume-fraction correction; K = dP_s/dε_s of
//                                    each cell, so e is the response to a P_s difference).
struct CorrectionResponse {
  explicit CorrectionResponse(std::size_t local_count);
  std::array<std::array<std::vector<double>, 3>, 2> pressure;  // d_m [m³ s/kg] per [phase][d]
  std::array<std::vector<double>, 3> fraction;                 // e [m³ s/kg] per d
  std::array<std::vector<double>, 3> friction;                 // w [-] per d
};

}  // namespace bagnold::solver
