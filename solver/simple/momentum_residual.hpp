#pragma once
// The normalized residual of one phase's momentum equation for one velocity component, which
// advance.cpp compares with numerics.tolerance. Row by row, with A the diagonal (drag included),
// L u = A u − Σ a_nb u_nb the row's operator on the current iterate, L1 = A − Σ a_nb what it
// gives for a uniform unit field, and s = b + βV u_other the rest of the row:
//
//   residual = Σ |s − L u| / norm, where norm is
//
//   "force": Σ F, F the sum of the magnitudes of the forces that act on the row's
//     control volume: its weight ε ρ V |g|, the pressure force ε (P_c − P_n) A, for the solids
//     the P_s force (P_s,c − P_s,n) A, the drag βV (u_other − u), the stress of a wall or a given
//     velocity a_b (u_b − u), a given body force, and ε ρ V a_min. The
//     exchange between neighbouring rows (viscous, convective and dilatational stress, the
//     deferred TVD and cross terms) is left out: it cancels for a layer translating as a plug,
//     however large μ_s, so a plug whose acceleration is wrong by δa is judged against its
//     weight (residual ≈ δa/|g|) and cannot hide behind a large viscosity or a short step.
//     a_min (SolverSettings::least_acceleration, 10⁻³ |g| under gravity) keeps a row on which
//     nothing acts (a fluid at rest without gravity) judged against a small acceleration instead
//     of round-off; it does not depend on dt, so a short step loosens nothing.
//   "velocity-scale" (the default): Σ A U, U the residual velocity scale (the largest |u|).
//     With μ_s of 10⁴–10⁵ Pa s in an unsheared dense layer A is ~10⁴ × its transient part, and
//     an iterate with a wrong acceleration passes (cases/chute/README.md, "False convergence").
//   "deviation": Σ (|L u − L1 ū| + |s − L1 ū|) + Σ (ε ρ V/dt) U_min, with ū the mean of the
//     phase's velocity over its solved rows (OpenFOAM's normalization factor). The parts of a
//     row that cancel for a uniform field enter only through the velocity's deviation from its
//     mean; but at small dt the transient part (ε ρ V/dt)|u − ū| of a sheared layer outweighs
//     the weight per row, and the free-slip chute accepts steps 6.6 % short of g sin θ over 20 ms.
//   "mfix": MFIX 21.3's CALC_RESID_U/V/W: Σ |A_e| |u|, A_e the diagonal after the drag's partial
//     elimination (unrelaxed) and |u| the phase's velocity magnitude from the three components
//     stored at the row's cell; rows with |u| ≤ 10⁻¹⁵, and solids rows with ε_s ≤ 10⁻⁴ (MFIX's
//     DIL_EP_S), count in neither sum. advance.cpp then also takes the continuity residuals
//     relative to the step's first outer iteration and compares their sum with the momentum
//     residuals' with numerics.tolerance, as MFIX's CHECK_CONVERGENCE does with TOL_RESID.
#include <array>
#include <cstddef>
#include <string>

#include "src/deck/choices.hpp"

namespace bagnold::solver {

using ResidualNormalization = deck::ResidualNormalization;  // named in deck::residual_normalization_choices
inline ResidualNormalization residual_normalization_from_name(const std::string& name) {
  return deck::choice_value(deck::residual_normalization_choices, name, "residual normalization");
}

// With numerics.net_force_residual the value is at least |Σ (s − L u)| / Σ ε ρ V |g|: the force
// the iterate leaves unbalanced on the whole phase, against its weight. Exchange between rows
// cancels in that sum, so it is what a sum of magnitudes can hide: at small dt the deviation
// norm's transient part, (ε ρ V/dt)|u − ū| in a sheared layer, outweighs gravity per row by
// 10⁴ (the free-slip chute accepted steps 6 % short of g sin θ at tolerance 1e-4).
class MomentumResidual {
 public:
  // The local sums of one phase and component: Σ|s − L u|, the normalization, Σ (s − L u),
  // Σ ε ρ V |g|, and over every row (those "mfix" leaves out too) Σ|s − L u| and Σ F. Added over
  // the ranks with every other residual of the outer iteration (IterationSums::reduce), then
  // turned into the normalized residual by value() and the force balance by force_balance().
  struct Sums {
    static constexpr std::size_t size = 6;
    std::array<double, size> values{};
  };

  // One row's terms: diagonal A; operator_u = L u; operator_one = L1; source = s; transient =
  // ε ρ V/dt; weight = ε ρ V |g|; force = F, the magnitudes of the forces that act (above,
  // a_min's share included).
  struct Row {
    double diagonal = 0.0, operator_u = 0.0, operator_one = 0.0, source = 0.0, transient = 0.0;
    double weight = 0.0, force = 0.0;
    double mfix_scale = 0.0;   // "mfix": |A_e| |u|
    bool mfix_counted = true;  // "mfix": whether the row counts (|u| and ε_s above MFIX's floors)
    // "mfix": (βV/A_o) r_o, the other phase's row residual carried by the drag's partial
    // elimination, which MFIX's CALC_RESID_U adds to the row's residual (only there).
    double mfix_coupling = 0.0;
  };

  MomentumResidual() = default;
  // mean: ū over the phase's solved rows (all ranks); velocity_scale: U; least_speed: U_min;
  // net_force: whether value() also bounds the net residual against the weight.
  MomentumResidual(ResidualNormalization kind, double mean, double velocity_scale, double least_speed,
                   bool net_force = false)
      : m_kind(kind), m_mean(mean), m_velocity_scale(velocity_scale), m_least_speed(least_speed),
        m_net_force(net_force) {}

  // One row added to `sums`. Returns the row's residual |s − L u|.
  double add(Sums& sums, const Row& row) const;

  // The normalized residual from sums over all ranks (0 without any residual).
  double value(const Sums& total) const;

  // Whatever the normalization: Σ|s − L u| / Σ F over every row, the "force" norm's residual
  // (without numerics.net_force_residual's bound; 0 without any residual). The monitor's
  // `force_residual` column reports it for the state each accepted step was judged on, so a step
  // that another norm accepted with its forces unbalanced shows.
  static double force_balance(const Sums& total);

 private:
  ResidualNormalization m_kind = ResidualNormalization::velocity_scale;
  double m_mean = 0.0, m_velocity_scale = 1.0, m_least_speed = 0.0;
  bool m_net_force = false;
};

}  // namespace bagnold::solver
