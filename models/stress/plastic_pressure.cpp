// MFIX's plastic pressure P* = A (ε_g* − ε_g)^n. See the header.
#include "models/stress/plastic_pressure.hpp"

#include <cmath>

namespace bagnold::models {

std::vector<CoefficientSpec> PlasticPressure::specs(bool packed_gas_fraction_required) {
  const PlasticPressure defaults;
  auto packed = real_spec("packed_gas_fraction", "-", defaults.packed_gas_fraction, 0.2, 0.6,
                          "ε_g* [-] (MFIX EP_STAR): below this gas fraction the plastic pressure "
                          "acts." +
                              std::string(packed_gas_fraction_required
                                              ? " Required: MFIX has no default for EP_STAR "
                                                "either (its bin deck and tutorials give 0.42)."
                                              : ""));
  return {
      packed_gas_fraction_required ? required(packed) : packed,
      real_spec("plastic_coefficient", "Pa", defaults.coefficient, 0.0, 1e30,
                "A [Pa]: plastic pressure P* = A (ε_g* − ε_g)^n (MFIX: 10²⁵ dyn/cm²)."),
      real_spec("plastic_exponent", "-", defaults.exponent, 1.0, 20.0,
                "n [-]: exponent of the plastic pressure (MFIX: 10)."),
  };
}

PlasticPressure PlasticPressure::read(const Coefficients& c) {
  return {.packed_gas_fraction = real_coefficient(c, "packed_gas_fraction"),
          .coefficient = real_coefficient(c, "plastic_coefficient"),
          .exponent = real_coefficient(c, "plastic_exponent")};
}

PlasticPressure::Value PlasticPressure::at(double phi) const {
  Value v;
  const double excess = phi - packed_fraction();  // ε_g* − ε_g
  if (excess > 0.0) {
    v.pressure = coefficient * std::pow(excess, exponent);
    v.derivative = coefficient * exponent * std::pow(excess, exponent - 1.0);
  }
  return v;
}

}  // namespace bagnold::models
