#include "models/stress/dense_limit.hpp"

#include <cmath>

#include "models/dual.hpp"
#include "models/stress/friction_table.hpp"

namespace bagnold::models {

std::vector<CoefficientSpec> DenseLimit::specs() {
  const DenseLimit defaults;
  return {
      real_spec("jamming_margin", "-", defaults.jamming_margin, 1e-9, 0.1,
                "δ [-]: g0 (and the dense temperature branch) are evaluated at "
                "min(φ, φ_c(μ) − δ); the quasi-static pressure starts at φ_c − δ."),
      real_spec("quasi_static_scale", "-", defaults.quasi_static_scale, 0.0, 1e3,
                "s [-]: multiplies α_QS(μ) (App. A Table II) in the quasi-static pressure "
                "s α_QS (k/d) (φ − φ_c + δ)^{2/3} (App. A Eq. 8 form); 0 switches it off."),
      onset_smoothing_spec(defaults.onset_smoothing),
  };
}

DenseLimit DenseLimit::read(const Coefficients& c) {
  return {.jamming_margin = real_coefficient(c, "jamming_margin"),
          .quasi_static_scale = real_coefficient(c, "quasi_static_scale"),
          .onset_smoothing = read_onset_smoothing(c)};
}

template <class Real>
Real DenseLimit::capped(Real phi, double critical_fraction) const {
  const double cap = jamming_fraction(critical_fraction);
  return value_of(phi) < cap ? phi : Real(cap);
}

template <class Real>
Real DenseLimit::quasi_static_pressure(Real phi, double critical_fraction,
                                       double stiffness_over_diameter, double friction) const {
  if (quasi_static_scale == 0.0) return Real(0.0);
  // App. A Eq. 8 with the onset moved from φ_c to φ_c − δ, where the kinetic part stops stiffening.
  const double coefficient = quasi_static_scale * chialvo2012::quasi_static_coefficient(friction) *
                             stiffness_over_diameter;
  return coefficient *
         smoothed_power(phi - jamming_fraction(critical_fraction), 2.0 / 3.0, onset_smoothing);
}

KineticDensePressure kinetic_dense_pressure(double phi, double shear_rate, const Material& material,
                                            const Dual& pressure_factor,
                                            const Dual& temperature_factor,
                                            double critical_fraction, const DenseLimit& dense) {
  const double d = material.diameter;
  const double rate_d2 = shear_rate * shear_rate * d * d;
  const Dual kinetic = material.density * pressure_factor * temperature_factor * rate_d2;
  const Dual quasi_static = dense.quasi_static_pressure(Dual::variable(phi), critical_fraction,
                                                        material.stiffness / d, material.friction);
  return {kinetic.value + quasi_static.value, kinetic.slope + quasi_static.slope,
          temperature_factor.value * rate_d2, quasi_static.value};
}

template double DenseLimit::capped(double, double) const;
template Dual DenseLimit::capped(Dual, double) const;
template double DenseLimit::quasi_static_pressure(double, double, double, double) const;
template Dual DenseLimit::quasi_static_pressure(Dual, double, double, double) const;

}  // namespace bagnold::models
