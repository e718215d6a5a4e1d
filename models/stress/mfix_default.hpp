#pragma once
// MFIX's default dense treatment, so the report's "MFIX default" comparisons can be rerun:
//  - viscous regime (ε_g ≥ ε_g*): an algebraic kinetic theory, Carnahan–Starling g0 (App. B
//    Eq. 11), T from the local balance −P tr D + 2μ S:S + λ (tr D)² = Γ (a quadratic in √T), with
//    Γ = 12(1 − e²) ρ_s φ² g0 T^{3/2}/(√π d). The key kinetic_theory picks the stresses:
//      syamlal (default): MFIX's GT_ALGEBRAIC (calc_mu_s.f), P = 2(1 + e) ρ_s g0 φ² T;
//      lun: Lun et al. (1984), P = ρ_s φ T (1 + 2(1 + e) φ g0), their μ and μ_b (the .cpp);
//  - plastic regime (ε_g < ε_g*): the plastic pressure P* = A (ε_g* − ε_g)^n
//    (A = 10²⁴ Pa, n = 10: MFIX's 10²⁵ dyn/cm²; plastic_pressure.hpp) with Schaeffer's (1987)
//    frictional viscosity μ = P* sin φ_f /(2 √I₂D) = P* sin φ_f / γ̇_s, capped (MFIX: 1000 poise =
//    100 Pa s), and MFIX's zero second viscosity with it (its stress 2 μ D: a bulk viscosity
//    λ = ⅔ μ here); the kinetic stresses and T are zero there, as in MFIX.
// The switch at ε_g* is discontinuous in P_s, exactly as in MFIX (docs/models.md).
// With granular_energy = "transport" (kinetic_theory "lun" only: MFIX solves its granular
// energy equation with LUN_1984, and Syamlal's theory is algebraic) Θ is transported
// (lun_granular_energy.hpp) and the stresses are MFIX's with GRANULAR_ENERGY = .TRUE.:
// P_s = the kinetic pressure at Θ (+ P* in the plastic regime), μ_s = the kinetic viscosity
// (+ Schaeffer's frictional one in the plastic regime, where Θ is held at 0 as MFIX's
// SOLVE_GRANULAR_ENERGY does), λ_s = η μ_b (+ ⅔ of the frictional μ); no dilute limit (the stresses at a given Θ vanish
// as φ → 0 on their own). Called without Θ (the rheometer, the deck checks) it answers as the
// algebraic form with the same kinetic_theory.

#include <optional>
#include <string>

#include "models/stress/dilute_limit.hpp"
#include "models/stress/lun_granular_energy.hpp"
#include "models/stress/plastic_pressure.hpp"
#include "models/stress/regularization.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::mfix_default {

enum class KineticTheory { syamlal, lun };

struct Constants {
  PlasticPressure plastic;                // ε_g*, A, n
  double internal_friction_angle = 30.0;  // φ_f [deg]
  KineticTheory theory = KineticTheory::syamlal;
  bool transport = false;  // granular_energy = "transport"
  double slip_temperature_floor = lun1984::default_slip_temperature_floor;  // [m²/s²]
};

class MfixDefault final : public SolidsStressModel {
 public:
  MfixDefault(const Constants& constants, const DiluteLimit& dilute, const ViscosityLimits& limits);
  std::string name() const override { return "mfix-default"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return true; }
  // φ_max = 1 − ε_g*: where the plastic regime starts.
  double packing_limit(const Material& material) const override;
  const GranularEnergyTheory* granular_energy() const override {
    return m_transport ? &*m_transport : nullptr;
  }

 private:
  void evaluate_at_temperature(const Material& material, const SolidsState& in,
                               SolidsStress& out) const;

  Constants m_constants;
  std::optional<lun1984::GranularEnergy> m_transport;
  DiluteLimit m_dilute;
  ViscosityLimits m_limits;
};

}  // namespace bagnold::models::mfix_default
