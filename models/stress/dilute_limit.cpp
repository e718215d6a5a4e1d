#include "models/stress/dilute_limit.hpp"

namespace bagnold::models {

std::vector<CoefficientSpec> DiluteLimit::specs() {
  return {
      real_spec("dilute_cutoff", "-", 1e-6, 1e-12, 0.01,
                "φ_min [-]: below this solids fraction the stresses and T are zero."),
      choice_spec("dilute_stress", "ideal-gas", {"ideal-gas", "kinetic"},
                  "Dilute treatment [-] below the fraction φ_d where P_s at fixed shear rate is smallest (≈ 0.17): "
                  "ideal-gas = the stresses of φ_d scaled by φ/φ_d at the temperature of φ_d "
                  "(P_s non-decreasing in φ); kinetic = the formulas as printed, whose P_s ~ 1/φ "
                  "makes dilute regions unstable."),
  };
}

DiluteLimit DiluteLimit::read(const Coefficients& c) {
  DiluteLimit limit;
  limit.cutoff = real_coefficient(c, "dilute_cutoff");
  limit.ideal_gas = string_coefficient(c, "dilute_stress") == "ideal-gas";
  return limit;
}

}  // namespace bagnold::models
