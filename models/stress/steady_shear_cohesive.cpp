// Cohesive steady-shear rheology, report App. D Eqs. 7–19. See steady_shear_cohesive.hpp.
#include "models/stress/steady_shear_cohesive.hpp"

#include <memory>

#include "models/stress/friction_table.hpp"

namespace bagnold::models::steady_shear_cohesive {

namespace {
// App. D Table I, μ-dependent rows, at μ = 0.1, 0.3, 0.5.
const FrictionTable& table_critical_fraction() {
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.614, 0.596, 0.587}};
  return t;
}
const FrictionTable& table_inertial_exponent() {  // χ
  static const FrictionTable t{{0.1, 0.3, 0.5}, {2.08, 2.09, 2.14}};
  return t;
}
const FrictionTable& table_quasi_static_exponent() {  // ε
  static const FrictionTable t{{0.1, 0.3, 0.5}, {1.00, 0.92, 0.67}};
  return t;
}
const FrictionTable& table_quasi_static() {  // α_QS
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.36, 0.36, 0.20}};
  return t;
}
const FrictionTable& table_intermediate() {  // α_int
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.15, 0.13, 0.10}};
  return t;
}
const FrictionTable& table_cohesive_1() {  // α_coh,1
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.15, 0.32, 0.26}};
  return t;
}
const FrictionTable& table_yield_stress_ratio() {  // η_s
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.268, 0.357, 0.382}};
  return t;
}
const FrictionTable& table_cohesive_stress_ratio() {  // α₃
  static const FrictionTable t{{0.1, 0.3, 0.5}, {0.23, 0.23, 0.15}};
  return t;
}
}  // namespace

blended::Constants constants_at(double friction, const Constants& k) {
  blended::Constants c;
  c.critical_fraction = table_critical_fraction()(friction);
  c.quasi_static_exponent = table_quasi_static_exponent()(friction);
  c.inertial_exponent = table_inertial_exponent()(friction);
  c.quasi_static = table_quasi_static()(friction);
  c.intermediate = table_intermediate()(friction);
  c.yield_stress_ratio = table_yield_stress_ratio()(friction);
  c.cohesive_1 = table_cohesive_1()(friction);
  c.cohesive_stress_ratio = table_cohesive_stress_ratio()(friction);
  c.inertial = k.inertial;
  c.stress_ratio = k.stress_ratio;
  c.cohesive_onset_fraction = k.cohesive_onset_fraction;
  c.cohesive_2 = k.cohesive_2;
  c.cohesive_rate = k.cohesive_rate;
  c.onset_smoothing = k.onset_smoothing;
  return c;
}

SteadyShearCohesive::SteadyShearCohesive(const Constants& constants, const ViscosityLimits& limits)
    : m_constants(constants), m_limits(limits) {}

void SteadyShearCohesive::evaluate(const Material& material, const SolidsState& in,
                                   SolidsStress& out) const {
  require_valid_material(material, name());
  const blended::Constants c = constants_at(material.friction, m_constants);
  evaluate_cells(in, out, [&](double phi, double shear_rate, double /*divergence*/) {
    return blended::point_stress(phi, shear_rate, material, c, m_limits);
  }, RateMeasure::whole);
}

double SteadyShearCohesive::packing_limit(const Material& material) const { return chialvo2012::critical_fraction(material.friction); }

namespace {
Constants read_constants(const Coefficients& c) {
  return {.cohesive_onset_fraction = real_coefficient(c, "phi_a"),
          .inertial = real_coefficient(c, "alpha_inert"),
          .cohesive_2 = real_coefficient(c, "alpha_coh_2"),
          .stress_ratio = blended::read_stress_ratio(c),
          .cohesive_rate = real_coefficient(c, "alpha_4"),
          .onset_smoothing = read_onset_smoothing(c)};
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "steady-shear-cohesive",
     .summary = "Cohesive blended rheology (Gu, Chialvo & Sundaresan 2014; App. D Eqs. 7–19)",
     .coefficients = concatenate(
         {{real_spec("phi_a", "-", Constants{}.cohesive_onset_fraction, 0.0, 0.7,
                     "φ_a [-]: cohesive pressure p d/k = α_coh,1 Bo* |φ − φ_a|/|φ_c − φ|, "
                     "App. D Eq. 11, Table I."),
           real_spec("alpha_inert", "-", Constants{}.inertial, 0.0, 10.0,
                     "α_inert [-]: inertial pressure α_inert γ̂²/|φ_c − φ|^χ, App. D Eq. 9, "
                     "Table I."),
           real_spec("alpha_coh_2", "-", Constants{}.cohesive_2, 0.0, 10.0,
                     "α_coh,2 [-]: cohesive floor of the intermediate pressure α_coh,2 "
                     "Bo*^{ε/(ε+χ)}, App. D Eq. 12, Table I."),
           real_spec("alpha_4", "-", Constants{}.cohesive_rate, 1e-9, 10.0,
                     "α₄ [-]: cohesive-to-inertial scaled shear rate α₄√Bo* in η, App. D Eq. 19, "
                     "Table I."),
           onset_smoothing_spec(Constants{}.onset_smoothing)},
          blended::stress_ratio_specs("App. D Eq. 14", "App. D Eq. 15", "Table I"),
          ViscosityLimits::specs()}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<SteadyShearCohesive>(read_constants(c), ViscosityLimits::read(c));
     }});
}  // namespace

}  // namespace bagnold::models::steady_shear_cohesive
