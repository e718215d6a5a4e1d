#include "models/stress/blended_rheology.hpp"

#include <cmath>

#include "models/stress/onset_smoothing.hpp"

namespace bagnold::models::blended {

double scaled_shear_rate(double shear_rate, const Material& material) {
  return shear_rate * material.diameter /
         std::sqrt(material.stiffness / (material.density * material.diameter));
}

namespace {
// Distances below 1e-12 are "at φ_c": the harmonic branch's |φ_c − φ|^−χ would overflow.
constexpr double at_critical = 1e-12;
}  // namespace

template <class Real>
Real scaled_pressure(Real phi, double scaled_rate, double bond_number, const Constants& c) {
  using std::abs;
  using std::pow;
  const double eps = c.quasi_static_exponent;
  const double chi = c.inertial_exponent;
  const Real excess = phi - c.critical_fraction;
  // Rate-dependent intermediate branch plus its cohesive floor (D Eqs. 8, 12).
  const double intermediate = c.intermediate * std::pow(scaled_rate, 2.0 * eps / (eps + chi)) +
                              c.cohesive_2 * std::pow(bond_number, eps / (eps + chi));
  if (value_of(excess) >= -at_critical) {
    // A Eq. 7 / D Eq. 10, additive blend; the QS power is smoothed at onset (finite dP/dφ).
    return c.quasi_static * smoothed_power(excess, eps, c.onset_smoothing) + intermediate;
  }
  const Real gap = -excess;
  const Real inertial = c.inertial * scaled_rate * scaled_rate / pow(gap, chi) +
                        c.cohesive_1 * bond_number * abs(phi - c.cohesive_onset_fraction) / gap;
  // Harmonic blend (w = −1); with both branches zero (γ̂ = 0, Bo* = 0) the limit is 0.
  if (value_of(inertial) == 0.0 || intermediate == 0.0) return Real(0.0);
  return inertial * intermediate / (inertial + intermediate);
}

template double scaled_pressure(double, double, double, const Constants&);
template Dual scaled_pressure(Dual, double, double, const Constants&);

double hard_stress_ratio(double inertial_number, const Constants& c) {
  const StressRatio& r = c.stress_ratio;
  const double rising = std::pow(inertial_number, r.hard_exponent);
  return c.yield_stress_ratio +
         r.hard_rise * rising / (std::pow(r.transition_inertial_number, r.hard_exponent) + rising);
}

double soft_stress_ratio(double scaled_rate, const Constants& c) {
  const StressRatio& r = c.stress_ratio;
  const double rising = std::pow(scaled_rate, r.soft_exponent);
  return r.soft_drop * rising / (std::pow(r.transition_shear_rate, r.soft_exponent) + rising);
}

double scaled_shear_stress(double phi, double scaled_rate, double scaled_pressure,
                           double bond_number, const Constants& c) {
  if (!(scaled_pressure > 0.0)) return 0.0;
  const double inertial_number = scaled_rate / std::sqrt(scaled_pressure);
  double ratio = hard_stress_ratio(inertial_number, c) - soft_stress_ratio(scaled_rate, c);
  if (ratio < 0.0) ratio = 0.0;
  double cohesive = 0.0;
  if (bond_number > 0.0) {
    // D Eq. 19 with γ̂ in the rate factor (as D Eq. 25): α₃ φ Bo* · α₄√Bo*/(γ̂ + α₄√Bo*).
    const double critical_rate = c.cohesive_rate * std::sqrt(bond_number);
    cohesive =
        c.cohesive_stress_ratio * phi * bond_number * critical_rate / (scaled_rate + critical_rate);
  }
  return ratio * scaled_pressure + cohesive;
}

PointStress point_stress(double phi, double shear_rate, const Material& material,
                         const Constants& c, const ViscosityLimits& limits) {
  const double stress_scale = material.stiffness / material.diameter;  // k/d [Pa]
  const double rate = scaled_shear_rate(shear_rate, material);
  const Dual pressure =
      scaled_pressure(Dual::variable(phi), rate, material.bond_number, c) * stress_scale;
  const double shear_stress =
      scaled_shear_stress(phi, rate, pressure.value / stress_scale, material.bond_number, c) *
      stress_scale;
  PointStress p;
  p.pressure = pressure.value;
  p.pressure_derivative = pressure.slope;
  // σ = p(I − η Ŝ): τ = η p in simple shear, μ_s = τ/γ̇ regularized as γ̇ → 0.
  p.shear_viscosity = limits.rate_independent_viscosity(shear_stress, shear_rate);
  return p;
}

std::vector<CoefficientSpec> stress_ratio_specs(const std::string& hard, const std::string& soft,
                                                const std::string& table) {
  const std::string of_hard = ", " + hard + ", " + table + ".";
  const std::string of_soft = ", " + soft + ", " + table + ".";
  const StressRatio d;
  return {
      real_spec("i0", "-", d.transition_inertial_number, 1e-6, 10.0,
                "I_0 [-]: transition inertial number of η_hard" + of_hard),
      real_spec("alpha_1", "-", d.hard_rise, 0.0, 10.0,
                "α₁ [-]: rise of η_hard above η_s" + of_hard),
      real_spec("beta_1", "-", d.hard_exponent, 0.1, 10.0,
                "β₁ [-]: exponent of η_hard" + of_hard),
      real_spec("gamma_hat_0", "-", d.transition_shear_rate, 1e-9, 10.0,
                "γ̂_0 [-]: transition scaled shear rate of η_soft" + of_soft),
      real_spec("alpha_2", "-", d.soft_drop, 0.0, 10.0, "α₂ [-]: softness drop of η" + of_soft),
      real_spec("beta_2", "-", d.soft_exponent, 0.1, 10.0,
                "β₂ [-]: exponent of η_soft" + of_soft),
  };
}

StressRatio read_stress_ratio(const Coefficients& c) {
  return {.transition_inertial_number = real_coefficient(c, "i0"),
          .hard_rise = real_coefficient(c, "alpha_1"),
          .hard_exponent = real_coefficient(c, "beta_1"),
          .transition_shear_rate = real_coefficient(c, "gamma_hat_0"),
          .soft_drop = real_coefficient(c, "alpha_2"),
          .soft_exponent = real_coefficient(c, "beta_2")};
}

}  // namespace bagnold::models::blended
