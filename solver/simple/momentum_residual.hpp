#pragma once
// The normalized residual of one phase's momentum equation for one velocity component, which
// advance.cpp compares with numerics.tolerance. Row by row, with A the diagonal (drag included),
// L u = A u − Σ a_nb u_nb the row's operator on the current iterate, L1 = A − Σ a_nb what it
// gives for a uniform unit field, and s = b + βV u_other the rest of the row:
//
//   residual = Σ |s − L u| / norm, where norm is
//
//   "velocity-scale" (the default): Σ A U, U the residual velocity scale (the largest |u|).
//     With μ_s of 10⁴–10⁵ Pa s in an unsheared dense layer A is ~10⁴ × its transient part, and
//     an iterate with a wrong acceleration passes (cases/chute/README.md, "False convergence").
//   "deviation": Σ (|L u − L1 ū| + |s − L1 ū|) + Σ (ε ρ V/dt) U_min, with ū the mean of the
//     phase's velocity over its solved rows (OpenFOAM's normalization factor). The parts of a
//     row that cancel for a uniform field (viscous and convective exchange with the neighbours)
//     enter only through the velocity's deviation from its mean, so a large viscosity cannot
//     hide an unbalanced force: a layer translating as a plug is judged against the forces that
//     accelerate it (gravity, walls, inertia). U_min = 10⁻³ of the reference speed keeps a fluid
//     at rest (hydrostatic: s ≈ 0) judged against a small velocity change instead of
//     round-off. The normalized residual is at most about 1 (triangle inequality). Not the
//     default: the 10 mm bin takes 1.6x the steps with it (381 against 238 to 0.2 s, the same
//     rate within 0.04 %; docs/stability.md).
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
  // The local sums of one phase and component: Σ|s − L u|, the normalization, Σ (s − L u) and
  // Σ ε ρ V |g|. Added over the ranks with every other residual of the outer iteration
  // (IterationSums::reduce), then turned into the normalized residual by value().
  struct Sums {
    static constexpr std::size_t size = 4;
    std::array<double, size> values{};
  };

  MomentumResidual() = default;
  // mean: ū over the phase's solved rows (all ranks); velocity_scale: U; least_speed: U_min;
  // net_force: whether value() also bounds the net residual against the weight.
  MomentumResidual(ResidualNormalization kind, double mean, double velocity_scale, double least_speed,
                   bool net_force = false)
      : m_kind(kind), m_mean(mean), m_velocity_scale(velocity_scale), m_least_speed(least_speed),
        m_net_force(net_force) {}

  // One row (arguments as above; transient = ε ρ V/dt; weight = ε ρ V |g|) added to `sums`.
  // Returns the row's residual |s − L u|.
  double add(Sums& sums, double diagonal, double operator_u, double operator_one, double source,
             double transient, double weight = 0.0) const;

  // The normalized residual from sums over all ranks (0 without any residual).
  double value(const Sums& total) const;

 private:
  ResidualNormalization m_kind = ResidualNormalization::deviation;
  double m_mean = 0.0, m_velocity_scale = 1.0, m_least_speed = 0.0;
  bool m_net_force = false;
};

}  // namespace bagnold::solver
