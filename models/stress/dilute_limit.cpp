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
            "φ → 0, dP_s/dε_s continuous); printed = App. A as printed, whose P_s stays "
            "finite in an empty cell."
          : "Dilute treatment [-] below the fraction φ_d where P_s at fixed shear rate is "
            "smallest (≈ 0.17): ideal-gas = the stresses of φ_d scaled by φ/φ_d at the "
            "temperature of φ_d (P_s non-decreasing in φ); kinetic = the formulas as printed, "
            "whose P_s ~ 1/φ makes dilute regions unstable.";
  return {
      real_spec("dilute_cutoff", "-", DiluteLimit{}.cutoff, 1e-12, 0.01,
                "φ_min [-]: below this solids fraction the stresses and T are zero."),
      choice_spec("dilute_stress", "ideal-gas", {"ideal-gas", printed_choice(anchor)}, treatment),
  };
}

DiluteLimit DiluteLimit::read(const Coefficients& c, Anchor anchor) {
  DiluteLimit limit;
  limit.cutoff = real_coefficient(c, "dilute_cutoff");
  limit.ideal_gas = string_coefficient(c, "dilute_stress") == "ideal-gas";
  limit.anchor = anchor;
  return limit;
}

}  // namespace bagnold::models
