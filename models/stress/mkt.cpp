// Modified kinetic theory, report App. B Tables I–II. See mkt.hpp.
#include "models/stress/mkt.hpp"

#include <cmath>
#include <memory>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/friction_table.hpp"
#include "models/stress/garzo_dufty.hpp"
#include "models/stress/pointwise.hpp"

namespace bagnold::models::mkt {

double effective_restitution(double restitution, double friction) {
  return restitution - 1.5 * friction * std::exp(-3.0 * friction);
}

double friction_factor_psi(double restitution, double friction, double psi_exponent) {
  return 1.0 + 0.3 * std::pow(1.0 - restitution * restitution, psi_exponent) *
                   (1.0 - std::exp(-8.0 * friction));
}

template <class Real>
Real dense_to_dilute_chi(Real modified_inertial_number, double transition_inertial_number) {
  const Real rising = three_halves_power(modified_inertial_number);
  return rising / (three_halves_power(transition_inertial_number) + rising);
}

MaterialTerms material_terms(const Material& material, const Constants& constants) {
  const double e = material.restitution;
  const double mu = material.friction;
  MaterialTerms t;
  t.critical_fraction = chialvo2012::critical_fraction(mu);
  t.effective_restitution = effective_restitution(e, mu);
  // Eq. 38 with K/K′ = (1 − e²)/(1 − e_eff²), which avoids 0/0 at e = 1.
  t.k_over_k_prime = (1.0 - e * e) / (1.0 - t.effective_restitution * t.effective_restitution);
  t.psi = friction_factor_psi(e, mu, constants.psi_exponent);
  t.yield_stress_ratio = chialvo2012::yield_stress_ratio(mu);
  return t;
}

template <class Real>
SteadyState<Real> steady_state(Real phi, const Material& material, const MaterialTerms& terms,
                               const Constants& constants, const DenseLimit& dense) {
  using std::sqrt;
  const double e = material.restitution;
  const double critical = terms.critical_fraction;
  const double e_eff = terms.effective_restitution;
  const Real phi_jammed = dense.capped(phi, critical);

  SteadyState<Real> s;
  s.radial_distribution =
      rdf::chialvo_sundaresan(phi_jammed, critical, constants.radial_distribution_scale);
  const Real& g0 = s.radial_distribution;
  s.pressure_factor = garzo_dufty::pressure_factor(phi, g0, e);
  s.shear_factor = garzo_dufty::shear_factor(phi, g0, e);
  s.dissipation_factor = garzo_dufty::dissipation_factor(phi, g0, e);
  // e_eff replaces e only in K (App. B Sec. IV.C.1; Fig. 6b shows H keeps e).
  s.friction_dissipation = garzo_dufty::dissipation_factor(phi, g0, e_eff);
  s.beta = phi * terms.psi * s.shear_factor * sqrt(terms.k_over_k_prime / s.pressure_factor);
  // Eq. 30: dilute and dense temperatures, the larger wins (Eq. 28).
  const Real dilute_temperature = s.shear_factor / s.friction_dissipation;
  const Real dense_temperature = constants.dense_temperature / sqrt(critical - phi_jammed);
  s.temperature_factor = value_of(dilute_temperature) > value_of(dense_temperature)
                             ? dilute_temperature
                             : dense_temperature;
  // Eq. 35 with p = ρ_s H T and T = M (γ̇d)²: I′ = γ̇d/(φ √(H M) γ̇d), rate independent.
  s.inertial_number = 1.0 / (phi * sqrt(s.pressure_factor * s.temperature_factor));
  s.chi = dense_to_dilute_chi(s.inertial_number, constants.transition_inertial_number);
  const double alpha = constants.dense_slope;
  // Eq. 49.
  s.shear_correction = alpha / s.beta + (1.0 - alpha / s.beta) * s.chi;
  // Eq. 51 corrected: production β I′ p δ_τ γ̇ = (ρ_s/d) K′ T^{3/2} δ_Γ with T = M(γ̇d)² and
  // I′ = γ̇d/(φ√(HT)) gives δ_Γ = β √H δ_τ/(φ K′ M). The print drops the 1/φ, which would give
  // T = M(γ̇d)²/φ and miss Garzó–Dufty in the dilute frictionless limit.
  s.dissipation_correction = s.beta * sqrt(s.pressure_factor) * s.shear_correction /
                             (phi * s.friction_dissipation * s.temperature_factor);
  // Eqs. 43, 45: τ_s = η_s (1 − χ) p.
  s.yield_ratio = terms.yield_stress_ratio * (1.0 - s.chi);
  // Table I: τ_inertial = β I′ p δ_τ (= B(α, β) I′ p, Eq. 46; not Eq. 48's τ_GD δ_τ).
  s.inertial_ratio = s.beta * s.inertial_number * s.shear_correction;
  return s;
}

template double dense_to_dilute_chi(double, double);
template Dual dense_to_dilute_chi(Dual, double);
template SteadyState<double> steady_state(double, const Material&, const MaterialTerms&,
                                          const Constants&, const DenseLimit&);
template SteadyState<Dual> steady_state(Dual, const Material&, const MaterialTerms&,
                                        const Constants&, const DenseLimit&);

Mkt::Mkt(const Constants& constants, const DenseLimit& dense, const DiluteLimit& dilute,
         const ViscosityLimits& limits)
    : m_constants(constants), m_dense(dense), m_dilute(dilute), m_limits(limits) {}

void Mkt::evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const {
  require_valid_material(material, name());
  const double rho = material.density;
  const double d = material.diameter;
  const MaterialTerms terms = material_terms(material, m_constants);
  const double critical = terms.critical_fraction;
  const double yield_ratio = terms.yield_stress_ratio;
  evaluate_cells_dilute_limited(m_dilute, material, in, out,
                                [&](double phi, double shear_rate, double) {
    PointStress p;
    const auto s = steady_state(Dual::variable(phi), material, terms, m_constants, m_dense);
    // Table I: p = ρ_s H T with T = M (γ̇d)².
    const auto k = kinetic_dense_pressure(phi, shear_rate, material, s.pressure_factor,
                                          s.temperature_factor, critical, m_dense);
    const double temperature = k.temperature;
    p.pressure = k.pressure;
    p.pressure_derivative = k.pressure_derivative;
    p.granular_temperature = temperature;
    // τ = (τ_s + τ_inertial)/p · p with p ∝ γ̇²: the viscosity (τ/γ̇) is written without dividing
    // by γ̇, so it is exact (and zero) at γ̇ = 0.
    const double kinetic_viscosity = (s.yield_ratio.value + s.inertial_ratio.value) * rho *
                                     s.pressure_factor.value * s.temperature_factor.value * d * d *
                                     shear_rate;
    p.shear_viscosity =
        m_limits.with_yield_stress(kinetic_viscosity, yield_ratio * k.quasi_static, shear_rate);
    // The report leaves the bulk viscosity unmodified: Garzó–Dufty's, with e.
    p.bulk_viscosity =
        rho * d * garzo_dufty::bulk_factor(phi, s.radial_distribution.value, material.restitution) *
        std::sqrt(temperature);
    return p;
  });
}

double Mkt::packing_limit(const Material& material) const { return chialvo2012::critical_fraction(material.friction); }

namespace {
Constants read_constants(const Coefficients& c) {
  return {.transition_inertial_number = real_coefficient(c, "i0"),
          .dense_slope = real_coefficient(c, "alpha"),
          .dense_temperature = real_coefficient(c, "alpha_1"),
          .radial_distribution_scale = real_coefficient(c, "alpha_2"),
          .psi_exponent = string_coefficient(c, "psi_exponent") == "openfoam" ? -1.5 : -2.0 / 3.0};
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "mkt",
     .summary = "Modified kinetic theory (Chialvo & Sundaresan 2013; App. B Tables I–II)",
     .coefficients = concatenate(
         {{real_spec("i0", "-", Constants{}.transition_inertial_number, 1e-6, 10.0,
                     "I_0 [-]: transition modified inertial number of χ(I′), App. B Eq. 41, "
                     "Table II."),
           real_spec("alpha", "-", Constants{}.dense_slope, 0.0, 10.0,
                     "α [-]: dense-regime slope of η in I′, App. B Eqs. 42, 49, Table II."),
           real_spec("alpha_1", "-", Constants{}.dense_temperature, 0.0, 10.0,
                     "α₁ [-]: dense temperature T = α₁(γ̇d)²/(φ_c − φ)^{1/2}, App. B Eq. 27, "
                     "Table II."),
           real_spec("alpha_2", "-", Constants{}.radial_distribution_scale, 0.0, 10.0,
                     "α₂ [-]: dense part of g0 = g0_CS + α₂φ²/(φ_c − φ)^{3/2}, App. B Eq. 31, "
                     "Table II."),
           choice_spec("psi_exponent", "report", {"report", "openfoam"},
                       "n [-], exponent of (1 − e²) in ψ, App. B Eq. 32: report = −2/3 as printed, "
                       "openfoam = −3/2 as in the authors' OpenFOAM code.")},
          DenseLimit::specs(),
          DiluteLimit::specs(),
          ViscosityLimits::specs()}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<Mkt>(read_constants(c), DenseLimit::read(c), DiluteLimit::read(c),
                                    ViscosityLimits::read(c));
     }});
}  // namespace

}  // namespace bagnold::models::mkt
