// Steady-shear rheology, report App. A Eqs. 7–15. See steady_shear.hpp.
#include "models/stress/steady_shear.hpp"

#include <memory>

#include "models/stress/friction_table.hpp"

namespace bagnold::models::steady_shear {

blended::Constants constants_at(double friction, const Constants& k) {
  blended::Constants c;
  c.critical_fraction = chialvo2012::critical_fraction(friction);    // A Table I
  c.quasi_static_exponent = 2.0 / 3.0;                               // a = 2/3, A Eq. 8
  c.inertial_exponent = 2.0;                                         // A Eq. 10
  c.quasi_static = chialvo2012::quasi_static_coefficient(friction);  // A Table II
  c.intermediate = k.intermediate;
  c.yield_stress_ratio = chialvo2012::yield_stress_ratio(friction);  // A Table II
  c.inertial = k.inertial;
  c.stress_ratio = k.stress_ratio;
  c.onset_smoothing = k.onset_smoothing;
  return c;  // no cohesion: α_coh = α₃ = 0
}

SteadyShear::SteadyShear(const Constants& constants, const DiluteLimit& dilute,
                         const ViscosityLimits& limits)
    : m_constants(constants), m_dilute(dilute), m_limits(limits) {}

void SteadyShear::evaluate(const Material& material, const SolidsState& in,
                           SolidsStress& out) const {
  require_valid_material(material, name());
  Material non_cohesive = material;
  non_cohesive.bond_number = 0.0;  // App. A has no cohesion; Bo* belongs to the cohesive model
  const blended::Constants c = constants_at(material.friction, m_constants);
  // App. A's P_s stays finite as φ → 0 (the inertial branch at φ = 0); the dilute limit makes it
  // vanish linearly below the tangent point (dilute_limit.hpp, docs/models.md).
  evaluate_cells_dilute_limited(m_dilute, material, in, out,
                                [&](double phi, double shear_rate, double /*divergence*/) {
                                  return blended::point_stress(phi, shear_rate, non_cohesive, c,
                                                               m_limits);
                                }, RateMeasure::whole);
}

double SteadyShear::packing_limit(const Material& material) const { return chialvo2012::critical_fraction(material.friction); }

namespace {
Constants read_constants(const Coefficients& c) {
  return {.inertial = real_coefficient(c, "alpha_inert"),
          .intermediate = real_coefficient(c, "alpha_int"),
          .stress_ratio = blended::read_stress_ratio(c),
          .onset_smoothing = read_onset_smoothing(c)};
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "steady-shear",
     .summary = "Blended steady-shear rheology (Chialvo, Sun & Sundaresan 2012; App. A Eqs. 7–15)",
     .coefficients = concatenate(
         {{real_spec("alpha_inert", "-", Constants{}.inertial, 0.0, 10.0,
                     "α_inert [-]: inertial pressure p d/k = α_inert γ̂²/|φ − φ_c|², App. A Eq. 10, "
                     "Table II."),
           real_spec("alpha_int", "-", Constants{}.intermediate, 0.0, 10.0,
                     "α_int [-]: intermediate pressure p d/k = α_int γ̂^{1/2}, App. A Eq. 9, "
                     "Table II."),
           onset_smoothing_spec(Constants{}.onset_smoothing)},
          blended::stress_ratio_specs("App. A Eq. 11", "App. A Eq. 12", "Table II"),
          DiluteLimit::specs(DiluteLimit::Anchor::tangent),
          ViscosityLimits::specs()}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<SteadyShear>(
           read_constants(c), DiluteLimit::read(c, DiluteLimit::Anchor::tangent),
           ViscosityLimits::read(c));
     }});
}  // namespace

}  // namespace bagnold::models::steady_shear
