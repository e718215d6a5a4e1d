// The smoothed onset of a quasi-static pressure and its one coefficient. See the header.
#include "models/stress/onset_smoothing.hpp"

#include <cmath>

#include "models/dual.hpp"

namespace bagnold::models {

template <class Real>
Real smoothed_power(Real excess, double exponent, double smoothing) {
  using std::pow;
  if (!(value_of(excess) > 0.0)) return Real(0.0);
  if (smoothing == 0.0) return pow(excess, exponent);
  return excess * excess * pow(excess * excess + smoothing * smoothing, 0.5 * exponent - 1.0);
}

template double smoothed_power(double, double, double);
template Dual smoothed_power(Dual, double, double);

CoefficientSpec onset_smoothing_spec(double default_value) {
  return real_spec("onset_smoothing", "-", default_value, 0.0, 0.1,
                   "x_s [-]: volume-fraction width over which the power law of the quasi-static "
                   "pressure (App. A Eq. 8, App. D Eq. 7, the kinetic models' dense limit) is "
                   "smoothed at its onset (quadratic below x_s) so that dP_s/dε_s is finite "
                   "there: it lowers the quasi-static pressure where φ − φ_c is within a few x_s "
                   "(at 1e-4, by less than 0.03 % where φ − φ_c ≥ 0.005 and by 0.7 % at 0.001; "
                   "at 1e-2, by 11-65 % at the states a packed bed sits in). 0: the published "
                   "power law (docs/models.md).");
}

double read_onset_smoothing(const Coefficients& c) {
  return real_coefficient(c, "onset_smoothing");
}

}  // namespace bagnold::models
