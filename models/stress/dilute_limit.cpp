#include "models/stress/dilute_limit.hpp"

#include <string>

namespace bagnold::models {

namespace {
// The value of dilute_stress that keeps the printed formulas.
const char* printed_choice(DiluteLimit::Anchor anchor) {
  return anchor == DiluteLimit::Anchor::tangent ? "printed" : "kinetic";
}
}  // namespace

std::vector<CoefficientSpec> DiluteLimit::specs(Anchor anchor) {
  const std::string treatment =
      anchor == Anchor::tangent
          ? "Dilute treatment [-] below the fraction φ_d where P_s/φ at fixed shear rate is "
            "smallest (≈ 0.2): ideal-gas = the stresses of φ_d scaled by φ/φ_d (P_s → 0 as "
            "φ → 0, dP_s/dε_s continuous); cooling = scaled by (φ/φ_d)² (the stress force "
            "per unit solids mass vanishes as φ → 0); printed = App. A as printed, whose P_s "
            "stays finite in an empty cell."
          : "Dilute treatment [-] below the fraction φ_d where P_s at fixed shear rate is "
            "smallest (≈ 0.17): ideal-gas = the stresses of φ_d scaled by φ/φ_d at the "
            "temperature of φ_d (P_s non-decreasing in φ); cooling = T of φ_d scaled by "
            "φ/φ_d and the stresses by (φ/φ_d)², so the stress force per unit solids mass "
            "vanishes in a near-empty cell; kinetic = the formulas as printed, whose P_s ~ 1/φ "
            "makes dilute regions unstable.";
  return {
      real_spec("dilute_cutoff", "-", 1e-6, 1e-12, 0.01,
                "φ_min [-]: below this solids fraction the stresses and T are zero."),
      choice_spec("dilute_stress", "ideal-gas", {"ideal-gas", "cooling", printed_choice(anchor)},
                  treatment),
  };
}

DiluteLimit DiluteLimit::read(const Coefficients& c, Anchor anchor) {
  DiluteLimit limit;
  limit.cutoff = real_coefficient(c, "dilute_cutoff");
  const std::string treatment = string_coefficient(c, "dilute_stress");
  limit.treatment = treatment == "ideal-gas" ? Treatment::ideal_gas
                    : treatment == "cooling" ? Treatment::cooling
                                             : Treatment::printed;
  limit.anchor = anchor;
  return limit;
}

}  // namespace bagnold::models
