#pragma once
// The onset of a rate-independent (quasi-static) pressure, written once for every model that has
// one: App. A Eq. 8's p̂_QS = α_QS |φ − φ_c|^{2/3} (steady-shear), App. D Eq. 7's α_QS |φ − φ_c|^ε
// (steady-shear-cohesive) and the kinetic models' dense limit s α_QS (k/d)(φ − φ_c + δ)^{2/3}
// (dense_limit.hpp). A power x^n with n < 1 has an infinite slope at x = 0, so dP_s/dε_s, which
// the volume-fraction correction needs (DESIGN.md step 4), would be infinite at onset. It is
// replaced by
//   g(x) = x² (x² + x_s²)^{n/2 − 1}  for x > 0, else 0,
// which is x^n (1 + O(x_s²/x²)) away from onset and has a finite slope at it. x_s is the deck
// coefficient onset_smoothing of each of those models, declared here once with one default for
// all of them, 10⁻⁴: the pressure is then within 0.03 % of the published power law wherever
// φ − φ_c ≥ 0.005, and tightening it to 10⁻⁵ moves the bins' discharge by less than 0.1 %
// (docs/models.md, "The onset smoothing"; docs/benchmarks.md).

#include "models/coefficients.hpp"

namespace bagnold::models {

// x_s [-]: the default onset_smoothing of every model with a quasi-static pressure.
inline constexpr double default_onset_smoothing = 1e-4;

// g(x) above, for exponent n and smoothing x_s; x_s = 0 gives x^n exactly. Real = double or Dual.
template <class Real>
Real smoothed_power(Real excess, double exponent, double smoothing);

// The declaration of the coefficient onset_smoothing, and its value in resolved coefficients.
CoefficientSpec onset_smoothing_spec(double default_value);
double read_onset_smoothing(const Coefficients& c);

}  // namespace bagnold::models
