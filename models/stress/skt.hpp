#pragma once
// Standard kinetic theory: Garzó–Dufty with an algebraic granular energy balance,
// report App. B Sec. II, Eqs. 1–18. No friction corrections; the interparticle friction only
// enters through φ_c(μ) of the Torquato and MKT radial distribution functions (so SKT and MKT
// can share a jamming point, as the report's bin comparison did) and the dense limit.
//
// Valid: frictionless, moderately inelastic spheres, 0 < φ ≲ φ_f = 0.49 (App. B Fig. 1).
// Outside: at and above φ_c(μ) − δ the dense limit of dense_limit.hpp applies; below the dilute
// cutoff the stresses are zero.

#include <optional>
#include <string>

#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"
#include "models/stress/dense_limit.hpp"
#include "models/stress/dilute_limit.hpp"
#include "models/stress/regularization.hpp"
#include "models/stress/skt_granular_energy.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::skt {

// Steady-shear kinetic quantities at one point (Real = double, or Dual for d/dφ).
template <class Real>
struct KineticState {
  Real radial_distribution;  // g0 at the capped fraction
  Real pressure_factor;      // H, Eq. 4
  Real shear_factor;         // J, Eq. 5
  Real dissipation_factor;   // K, Eq. 6
  Real bulk_factor;          // J_b (garzo_dufty.hpp)
  Real temperature_factor;   // T/(γ̇ d)² = J/K, Eq. 15
};

// critical: φ_c(μ) of the material (App. A Table I), where g0 is capped.
template <class Real>
KineticState<Real> kinetic_state(Real phi, const Material& material, double critical,
                                 const rdf::RadialDistribution& radial, const DenseLimit& dense);

class Skt final : public SolidsStressModel {
 public:
  // frictional_yield: add the quasi-static yield stress η_s(μ) P_qs of the dense limit (off in
  // the report's SKT, which "does not consider ... the role of frictional contact").
  // transport: Θ from the granular energy equation (skt_granular_energy.hpp) instead of the
  // algebraic balance; evaluate() then takes Θ (and answers algebraically without it).
  Skt(const rdf::RadialDistribution& radial, bool frictional_yield, const DenseLimit& dense,
      const DiluteLimit& dilute, const ViscosityLimits& limits, bool transport = false);
  std::string name() const override { return "skt"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return true; }
  // φ_max = φ_c(μ) of App. A Table I, where g0 is capped (dense_limit.hpp).
  double packing_limit(const Material& material) const override;
  const GranularEnergyTheory* granular_energy() const override {
    return m_transport ? &*m_transport : nullptr;
  }

 private:
  void evaluate_at_temperature(const Material& material, const SolidsState& in, SolidsStress& out) const;

  const rdf::RadialDistribution* m_radial;  // an entry of rdf::radial_distributions()
  bool m_frictional_yield;
  DenseLimit m_dense;
  DiluteLimit m_dilute;
  ViscosityLimits m_limits;
  std::optional<GranularEnergy> m_transport;
};

}  // namespace bagnold::models::skt
