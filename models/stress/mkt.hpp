#pragma once
// Modified kinetic theory (Chialvo & Sundaresan 2013): report App. B, Table I (equations) and
// Table II (constants), with φ_c(μ) and η_s(μ) interpolated in friction_table.hpp.
//
// Under steady shear the algebraic granular energy balance "production by τ_inertial =
// dissipation Γ" (Eqs. 13, 47, 50) is solved per cell. With δ_Γ derived so that steady simple
// shear gives T = M (γ̇d)² (Eq. 29) — the printed Eq. 51 lacks a factor 1/φ, model-notes.md —
// and δ_τ, δ_Γ evaluated with the same I′, the balance has the closed-form root
//   T = M(φ) (γ̇_s d)²,   γ̇_s = sqrt(2 S:S) (the deviatoric rate, pointwise.hpp),
// in any 3-D strain field: production τ_inertial Ŝ:∇u = τ_inertial γ̇_s.
//
// Valid: 0 < φ < φ_c(μ), e < 1, inertial regime (k → ∞). Outside: the dense limit of
// dense_limit.hpp at and above φ_c − δ; zero stresses below the dilute cutoff.

#include <string>

#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"
#include "models/stress/dense_limit.hpp"
#include "models/stress/dilute_limit.hpp"
#include "models/stress/regularization.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::mkt {

// μ-independent constants of App. B Table II and the ψ exponent (model-notes.md).
struct Constants {
  double transition_inertial_number = 0.2;  // I_0 [-]
  double dense_slope = 0.36;                // α [-], dense prefactor of I′ in η (Eq. 42)
  double dense_temperature = 0.06;          // α₁ [-], Eq. 27
  double radial_distribution_scale = rdf::chialvo_sundaresan_scale;  // α₂ [-], Eq. 31
  double psi_exponent = -2.0 / 3.0;  // exponent of (1 − e²) in ψ, Eq. 32
};

// App. B Eqs. 22–23: e_eff = e − (3/2) μ exp(−3μ).
double effective_restitution(double restitution, double friction);

// App. B Eq. 32: ψ = 1 + (3/10)(1 − e²)^n [1 − exp(−8μ)], n = −2/3 as printed (default) or
// −3/2 as in the authors' OpenFOAM code.
double friction_factor_psi(double restitution, double friction, double psi_exponent);

// App. B Eq. 41 written as I′^1.5/(I_0^1.5 + I′^1.5), which is finite at I′ = 0.
template <class Real>
Real dense_to_dilute_chi(Real modified_inertial_number, double transition_inertial_number);

// Every quantity of Table I at one volume fraction under steady shear (Real = double or Dual).
// Dimensional ones are per (γ̇d)² so they do not depend on the shear rate (Bagnold scaling).
template <class Real>
struct SteadyState {
  Real radial_distribution;     // g0, Eq. 31, at min(φ, φ_c − δ)
  Real pressure_factor;         // H, Eq. 4
  Real shear_factor;            // J, Eq. 5
  Real dissipation_factor;      // K, Eq. 6
  Real friction_dissipation;    // K′, Eq. 25 (e_eff in place of e, in K only)
  Real beta;                    // β, Eq. 38
  Real temperature_factor;      // M = T/(γ̇d)², Eq. 30 (dense branch at the capped φ)
  Real inertial_number;         // I′ = 1/(φ √(H M)), Eq. 35 with p = ρ_s H M (γ̇d)²
  Real chi;                     // χ(I′), Eq. 41
  Real shear_correction;        // δ_τ, Eq. 49
  Real dissipation_correction;  // δ_Γ = β √H δ_τ/(φ K′ M): Eq. 51 with the missing 1/φ
  Real yield_ratio;             // τ_s/p = η_s χ_s, Eq. 45
  Real inertial_ratio;          // τ_inertial/p = β I′ δ_τ, Table I
};

// What Table I needs that depends on the material alone: evaluated once per call of evaluate(),
// not per cell.
struct MaterialTerms {
  double critical_fraction;      // φ_c(μ), App. A Table I
  double effective_restitution;  // e_eff, Eqs. 22–23
  double k_over_k_prime;         // K/K′ = (1 − e²)/(1 − e_eff²), Eq. 38
  double psi;                    // ψ, Eq. 32
  double yield_stress_ratio;     // η_s(μ), App. A Table II
};
MaterialTerms material_terms(const Material& material, const Constants& constants);

template <class Real>
SteadyState<Real> steady_state(Real phi, const Material& material, const MaterialTerms& terms,
                               const Constants& constants, const DenseLimit& dense);
// The same with the material terms evaluated for this call.
template <class Real>
SteadyState<Real> steady_state(Real phi, const Material& material, const Constants& constants,
                               const DenseLimit& dense) {
  return steady_state(phi, material, material_terms(material, constants), constants, dense);
}

class Mkt final : public SolidsStressModel {
 public:
  Mkt(const Constants& constants, const DenseLimit& dense, const DiluteLimit& dilute,
      const ViscosityLimits& limits);
  std::string name() const override { return "mkt"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return true; }
  // φ_max = φ_c(μ) of App. A Table I, where g0 is capped (dense_limit.hpp).
  double packing_limit(const Material& material) const override;

 private:
  Constants m_constants;
  DenseLimit m_dense;
  DiluteLimit m_dilute;
  ViscosityLimits m_limits;
};

}  // namespace bagnold::models::mkt
