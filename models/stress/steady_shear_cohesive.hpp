#pragma once
// Cohesive steady-shear rheology of Gu, Chialvo & Sundaresan (2014): report App. D Eqs. 7–19
// with its Table I (Hookean contacts + van der Waals cohesion), used throughout — including its
// own refit of the non-cohesive part, so Bo* = 0 is App. D's non-cohesive limit, not App. A's
// (model-notes.md). The modified Bond number Bo* is Material::bond_number.
//
// Table I gives the μ-dependent constants at μ = 0.1, 0.3, 0.5 only: interpolated
// piecewise-linearly in μ and clamped to [0.1, 0.5] (docs/models.md).

#include <string>

#include "models/stress/blended_rheology.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::steady_shear_cohesive {

// App. D's μ-independent constants (Table I), deck-overridable.
struct Constants {
  double cohesive_onset_fraction = 0.45;  // φ_a
  double inertial = 0.015;                // α_inert
  double cohesive_2 = 0.008;              // α_coh,2
  blended::StressRatio stress_ratio;  // I_0, α₁, β₁, γ̂_0, α₂, β₂: both models' defaults
  double cohesive_rate = 0.1;         // α₄
  double onset_smoothing = default_onset_smoothing;  // x_s
};

// The blended constants at friction μ from App. D Table I.
blended::Constants constants_at(double friction, const Constants& constants);

class SteadyShearCohesive final : public SolidsStressModel {
 public:
  SteadyShearCohesive(const Constants& constants, const ViscosityLimits& limits);
  std::string name() const override { return "steady-shear-cohesive"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return false; }
  // φ_c(μ) of App. A Table I, as for steady-shear (what the walls used before the interface
  // had this call), not App. D Table I's own φ_c: see docs/models.md, "Packing limit".
  double packing_limit(const Material& material) const override;

 private:
  Constants m_constants;
  ViscosityLimits m_limits;
};

}  // namespace bagnold::models::steady_shear_cohesive
