#pragma once
// The limiter on a compressing solids volume fraction correction ε', applied after the linear
// solve of step 3 (volume_fraction_correction.cpp), cell by cell:
//   - ε' never takes ε_s below zero (ε' = −ε_s there: counted as fraction_clamped_at_zero);
//   - where ε' > 0, P_s is convex near packing, so the linearized correction (Newton from below)
//     overshoots into astronomically large pressures. While the closure's P_s at ε_s + λ ε'
//     exceeds overshoot_ratio × its linear prediction P_s + max(K, 0) λ ε' plus a pressure
//     floor, λ is halved (at most max_halvings times); ε' becomes λ ε' (counted as
//     compression_damped). The floor is the weight of one cell of packed solids,
//     ρ_s |g| h floor_fraction (h the smallest width of the rank's cells), at least
//     least_floor: below it the linearization need not be trusted.
// The outer iterations take the rest of the correction; at convergence ε' → 0 and the limiter
// stops acting.

#include <vector>

#include "solver/discretization.hpp"
#include "solver/simple/closures.hpp"
#include "solver/simple/solver_settings.hpp"
#include "solver/simple/step_record.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

class CompressionLimit {
 public:
  // P_s may exceed its linear prediction by this factor before ε' is damped: twice leaves the
  // convexity of a closure near packing room while catching the orders-of-magnitude overshoot.
  static constexpr double overshoot_ratio = 2.0;
  // The packed fraction of the floor's cell of solids (a random loose packing).
  static constexpr double floor_fraction = 0.6;
  static constexpr double least_floor = 1.0;  // [Pa]
  // 2⁻⁴⁰ ≈ 1e-12: a correction damped further would change nothing.
  static constexpr int max_halvings = 40;

  CompressionLimit(const Discretization& discretization, const SolverSettings& settings,
                   const Closures& closures);

  // Limits `correction` (local cells; owned fluid cells are read and changed) for the iterate
  // `state` whose P_s and γ̇_P the closures last evaluated; counts its interventions in `sums`.
  void apply(const run::FlowState& state, const ClosureFields& fields,
             std::vector<double>& correction, IterationSums& sums);

 private:
  const Discretization& m_discretization;
  const Closures& m_closures;
  double m_floor;  // [Pa]
  // Scratch, sized once: the compressed cells and the closure's inputs and outputs there.
  std::vector<int> m_cells;
  std::vector<double> m_lambda, m_candidate, m_rate, m_divergence;
  std::vector<double> m_pressure, m_derivative, m_shear, m_bulk, m_temperature;
};

}  // namespace bagnold::solver
