#pragma once
// The minimal closure of the two-fluid core (issue 4): MFIX's plastic pressure and a constant
// solids viscosity, nothing kinetic. For testing the solver on packed beds and settling, where
// what matters is that the packing limit is enforced:
//   P_s = A (ε_g* − ε_g)^n for ε_g < ε_g*, else 0   (MFIX's P*, A = 10²⁴ Pa, n = 10,
//   dP_s/dε_s = n A (ε_g* − ε_g)^(n−1)               plastic_pressure.hpp),
//   μ_s = μ_0 min(ε_s / ε_s*, 1), ε_s* = 1 − ε_g*  (constant in the packed bed; vanishing with
//   the solids, so that a dilute cloud is not a viscous one), λ_s = 0; no granular temperature.

#include <string>

#include "models/stress/plastic_pressure.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models::plastic {

struct Constants {
  PlasticPressure plastic;  // ε_g*, A, n
  double viscosity = 1.0;   // μ_0 [Pa s]
};

class Plastic final : public SolidsStressModel {
 public:
  explicit Plastic(const Constants& constants) : m_constants(constants) {}
  std::string name() const override { return "plastic"; }
  void evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const override;
  bool defines_temperature() const override { return false; }
  // φ_max = 1 − ε_g*: where the plastic pressure starts.
  double packing_limit(const Material& material) const override;

 private:
  Constants m_constants;
};

}  // namespace bagnold::models::plastic
