#pragma once
// Steady-shear rheology of Chialvo, Sun & Sundaresan (2012): report App. A Eqs. 7–15 with the
// constants of Tables I–II (φ_c, η_s, α_QS interpolated in μ, friction_table.hpp). Blended
// pressure over the quasi-static, intermediate and inertial regimes and the stress ratio
// η(I, γ̂); the formulas live in blended_rheology.hpp. Particle stiffness k: Material::stiffness.

#include <string>

#include "models/stress/blended_rheology.hpp"
#include "models/stress/dilute_limit.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::steady_shear {

// App. A's μ-independent constants (Table II), deck-overridable.
struct Constants {
  double inertial = 0.021;            // α_inert
  double intermediate = 0.099;        // α_int
  blended::StressRatio stress_ratio;  // I_0, α₁, β₁, γ̂_0, α₂, β₂: both models' defaults
  double onset_smoothing = default_onset_smoothing;  // x_s
};

// The blended constants at friction μ: App. A Tables I–II, ε = 2/3, χ = 2 (Eqs. 8–10).
blended::Constants constants_at(double friction, const Constants& constants);

class SteadyShear final : public SolidsStressModel {
 public:
  SteadyShear(const Constants& constants, const DiluteLimit& dilute, const ViscosityLimits& limits);
  std::string name() const override { return "steady-shear"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return false; }
  // φ_max = φ_c(μ) of App. A Table I, the rheology's critical fraction.
  double packing_limit(const Material& material) const override;

 private:
  Constants m_constants;
  DiluteLimit m_dilute;
  ViscosityLimits m_limits;
};

}  // namespace bagnold::models::steady_shear
