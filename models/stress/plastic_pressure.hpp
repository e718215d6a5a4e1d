#pragma once
// MFIX's plastic solids pressure, the stiff branch that keeps a packed bed from over-packing
// (DESIGN.md, "Dense regime"), written once for the two closures that use it (plastic,
// mfix-default):
//   P* = A (ε_g* − ε_g)^n = A (φ − ε_s*)^n   for φ > ε_s* = 1 − ε_g*, else 0,
//   dP*/dε_s = n A (φ − ε_s*)^(n−1),
// with MFIX's constants A = 10²⁴ Pa (10²⁵ dyn/cm²), n = 10 and ε_g* its EP_STAR.

#include <vector>

#include "models/coefficients.hpp"

namespace bagnold::models {

struct PlasticPressure {
  double packed_gas_fraction = 0.4;  // ε_g* [-] (MFIX EP_STAR)
  double coefficient = 1e24;         // A [Pa]
  double exponent = 10.0;            // n [-]

  // The deck coefficients packed_gas_fraction, plastic_coefficient, plastic_exponent.
  // packed_gas_fraction_required: ε_g* has no default (mfix-default, as MFIX's EP_STAR).
  static std::vector<CoefficientSpec> specs(bool packed_gas_fraction_required = false);
  static PlasticPressure read(const Coefficients& c);

  double packed_fraction() const { return 1.0 - packed_gas_fraction; }  // ε_s* [-]

  struct Value {
    double pressure = 0.0;    // P* [Pa]
    double derivative = 0.0;  // dP*/dε_s [Pa]
  };
  // P* and its derivative at φ = phi; zero at and below ε_s*.
  Value at(double phi) const;
};

}  // namespace bagnold::models
