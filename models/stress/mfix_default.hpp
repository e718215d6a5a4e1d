#pragma once
// MFIX's default dense treatment, so the report's "MFIX default" comparisons can be rerun:
//  - viscous regime (ε_g ≥ ε_g*): Lun et al. (1984) kinetic theory, η = (1 + e)/2,
//      P = ρ_s φ T (1 + 4ηφ g0),
//      μ = μ*/(η(2 − η) g0) (1 + (8/5)ηφ g0)(1 + (8/5)η(3η − 2)φ g0) + (3/5)η μ_b,
//      λ = η μ_b,  μ* = 5ρ_s d √(πT)/96,  μ_b = 256 μ* φ² g0/(5π),
//      Γ = 12(1 − e²) ρ_s φ² g0 T^{3/2}/(√π d),  g0 Carnahan–Starling (App. B Eq. 11);
//    T from MFIX's algebraic balance −P tr D + 2μ S:S + λ (tr D)² = Γ, a quadratic in √T;
//  - plastic regime (ε_g < ε_g*): the plastic pressure P* = A (ε_g* − ε_g)^n
//    (A = 10²⁴ Pa, n = 10: MFIX's 10²⁵ dyn/cm²; plastic_pressure.hpp) with Schaeffer's (1987)
//    frictional viscosity μ = P* sin φ_f /(2 √I₂D) = P* sin φ_f / γ̇_s, capped (MFIX: 1000 poise =
//    100 Pa s); the kinetic stresses and T are zero there, as in MFIX.
// The switch at ε_g* is discontinuous in P_s, exactly as in MFIX (docs/models.md).

#include <string>

#include "models/stress/dilute_limit.hpp"
#include "models/stress/plastic_pressure.hpp"
#include "models/stress/regularization.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::mfix_default {

struct Constants {
  PlasticPressure plastic;                // ε_g*, A, n
  double internal_friction_angle = 30.0;  // φ_f [deg]
};

class MfixDefault final : public SolidsStressModel {
 public:
  MfixDefault(const Constants& constants, const DiluteLimit& dilute, const ViscosityLimits& limits);
  std::string name() const override { return "mfix-default"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return true; }
  // φ_max = 1 − ε_g*: where the plastic regime starts.
  double packing_limit(const Material& material) const override;

 private:
  Constants m_constants;
  DiluteLimit m_dilute;
  ViscosityLimits m_limits;
};

}  // namespace bagnold::models::mfix_default
