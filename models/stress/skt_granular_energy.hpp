#pragma once
// The standard kinetic theory (skt.hpp: Garzó–Dufty as the report writes it, App. B Eqs. 1–10)
// in transport form, for the granular energy equation (granular_energy.hpp): at the transported
// Θ, with H, J, J_b, K and the conductivity factor J_κ of garzo_dufty.hpp at g0(φ_j),
// φ_j = min(φ, φ_c − δ) (dense_limit.hpp):
//   P_s = ρ_s H Θ (+ the quasi-static P_qs, which does no work on the fluctuations),
//   μ_s = ρ_s d J √Θ,  λ_s = ρ_s d J_b √Θ,  κ_s = ρ_s d J_κ √Θ,  Γ = (ρ_s/d) K Θ^{3/2}.
// A dry granular theory: no drag-modified coefficients and no slip production (the equation
// still takes the exchange −3βΘ); Θ is never held.

#include <string>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/dense_limit.hpp"
#include "models/stress/granular_energy.hpp"

namespace bagnold::models::skt {

// ρ_s H, ρ_s d J, ρ_s d J_b, ρ_s d J_κ and (ρ_s/d) K at φ: the coefficients of Θ, √Θ and Θ^{3/2}.
struct TransportFactors {
  Dual pressure;  // P_s/Θ, with d/dφ at fixed Θ
  double shear = 0.0, bulk = 0.0, conductivity = 0.0, dissipation = 0.0;
};
// critical: φ_c(μ) of the material (chialvo2012::critical_fraction), computed once per call.
TransportFactors transport_factors(double phi, const Material& material, double critical,
                                   const rdf::RadialDistribution& radial, const DenseLimit& dense);

class GranularEnergy final : public GranularEnergyTheory {
 public:
  GranularEnergy(const rdf::RadialDistribution& radial, const DenseLimit& dense)
      : m_radial(&radial), m_dense(dense) {}
  std::string name() const override { return "garzo-dufty"; }
  void evaluate(const Material& material, const KineticInput& in, KineticTerms& out) const override;

 private:
  const rdf::RadialDistribution* m_radial;
  DenseLimit m_dense;
};

}  // namespace bagnold::models::skt
