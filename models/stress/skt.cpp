// Standard kinetic theory (Garzó–Dufty), report App. B Eqs. 1–18. See skt.hpp.
#include "models/stress/skt.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <memory>
#include <string>

#include "models/stress/friction_table.hpp"
#include "models/stress/garzo_dufty.hpp"
#include "models/stress/pointwise.hpp"

namespace bagnold::models::skt {

template <class Real>
KineticState<Real> kinetic_state(Real phi, const Material& material, double critical,
                                 const rdf::RadialDistribution& radial, const DenseLimit& dense) {
  const double e = material.restitution;
  KineticState<Real> s;
  s.radial_distribution = rdf::evaluate(radial, dense.capped(phi, critical), critical);
  const Real& g0 = s.radial_distribution;
  s.pressure_factor = garzo_dufty::pressure_factor(phi, g0, e);
  s.shear_factor = garzo_dufty::shear_factor(phi, g0, e);
  s.dissipation_factor = garzo_dufty::dissipation_factor(phi, g0, e);
  s.bulk_factor = garzo_dufty::bulk_factor(phi, g0, e);
  // Eq. 15: production γ̇τ (Eq. 14) = dissipation Γ (Eq. 3) gives T = (J/K)(γ̇d)².
  s.temperature_factor = s.shear_factor / s.dissipation_factor;
  return s;
}

template KineticState<double> kinetic_state(double, const Material&, double,
                                            const rdf::RadialDistribution&, const DenseLimit&);
template KineticState<Dual> kinetic_state(Dual, const Material&, double,
                                          const rdf::RadialDistribution&, const DenseLimit&);

Skt::Skt(const rdf::RadialDistribution& radial, bool frictional_yield, const DenseLimit& dense,
         const DiluteLimit& dilute, const ViscosityLimits& limits, bool transport)
    : m_radial(&radial),
      m_frictional_yield(frictional_yield),
      m_dense(dense),
      m_dilute(dilute),
      m_limits(limits) {
  if (transport) m_transport.emplace(radial, dense);
}

void Skt::evaluate_at_temperature(const Material& material, const SolidsState& in,
                                  SolidsStress& out) const {
  const std::size_t n = in.solids_fraction.size();
  for (const std::size_t size :
       {in.strain_rate.size(), in.divergence.size(), in.temperature.size(), out.pressure.size(),
        out.pressure_derivative.size(), out.shear_viscosity.size(), out.bulk_viscosity.size(),
        out.granular_temperature.size()})
    if (size != n) throw std::invalid_argument("skt: a transported Θ needs Θ for every cell (arrays differ in length)");
  const double critical = chialvo2012::critical_fraction(material.friction);
  const double yield_ratio = m_frictional_yield ? chialvo2012::yield_stress_ratio(material.friction) : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = in.solids_fraction[i] > 0.0 ? in.solids_fraction[i] : 0.0;
    const double theta = in.temperature[i] > 0.0 ? in.temperature[i] : 0.0;
    const double root = std::sqrt(theta);
    const auto f = transport_factors(phi, material, critical, *m_radial, m_dense);
    const Dual quasi_static = phi > 0.0 ? m_dense.quasi_static_pressure(Dual::variable(phi), critical,
                                                                       material.stiffness / material.diameter,
                                                                       material.friction)
                                        : Dual(0.0);
    const double rate = deviatoric_shear_rate(in.strain_rate[i], in.divergence[i]);
    out.pressure[i] = f.pressure.value * theta + quasi_static.value;
    out.pressure_derivative[i] = f.pressure.slope * theta + quasi_static.slope;
    out.shear_viscosity[i] = m_limits.with_yield_stress(f.shear * root, yield_ratio * quasi_static.value, rate);
    out.bulk_viscosity[i] = f.bulk * root;
    out.granular_temperature[i] = theta;
  }
}

void Skt::evaluate(const Material& material, const SolidsState& in, SolidsStress& out) const {
  require_valid_material(material, name());
  if (m_transport && !in.temperature.empty()) {  // without Θ the algebraic form answers
    evaluate_at_temperature(material, in, out);
    return;
  }
  const double rho = material.density;
  const double d = material.diameter;
  const double critical = chialvo2012::critical_fraction(material.friction);
  const double yield_ratio =
      m_frictional_yield ? chialvo2012::yield_stress_ratio(material.friction) : 0.0;
  evaluate_cells_dilute_limited(m_dilute, material, in, out,
                                [&](double phi, double shear_rate, double) {
    PointStress p;
    const auto s = kinetic_state(Dual::variable(phi), material, critical, *m_radial, m_dense);
    // Eq. 1 with T = (J/K)(γ̇d)²: p = ρ_s H (J/K)(γ̇d)², differentiated at fixed γ̇.
    const auto k = kinetic_dense_pressure(phi, shear_rate, material, s.pressure_factor,
                                          s.temperature_factor, critical, m_dense);
    const double sqrt_temperature = std::sqrt(k.temperature);
    p.pressure = k.pressure;
    p.pressure_derivative = k.pressure_derivative;
    p.granular_temperature = k.temperature;
    // Eq. 2: τ = ρ_s d J √T γ̇, so μ_s = ρ_s d J √T; the quasi-static yield stress η_s P_qs
    // (frictional_yield) is rate independent and gets the regularized viscosity.
    const double kinetic_viscosity = rho * d * s.shear_factor.value * sqrt_temperature;
    p.shear_viscosity =
        m_limits.with_yield_stress(kinetic_viscosity, yield_ratio * k.quasi_static, shear_rate);
    p.bulk_viscosity = rho * d * s.bulk_factor.value * sqrt_temperature;
    return p;
  });
}

double Skt::packing_limit(const Material& material) const { return chialvo2012::critical_fraction(material.friction); }

namespace {
// "g0 [-]: a (its equation), b (…) or c (…), to share MKT's jamming point.", from the table.
std::string radial_distribution_doc() {
  const auto& table = rdf::radial_distributions();
  std::string doc = "g0 [-]: ";
  for (std::size_t i = 0; i < table.size(); ++i)
    doc += (i == 0 ? "" : i + 1 == table.size() ? " or " : ", ") + table[i].name + " (" +
           table[i].summary + ")";
  return doc + ", to share MKT's jamming point.";
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "skt",
     .summary = "Standard kinetic theory: Garzó–Dufty, algebraic temperature (App. B Eqs. 1–18)",
     .coefficients = concatenate(
         {{choice_spec("radial_distribution", "carnahan-starling",
                       rdf::radial_distribution_names(), radial_distribution_doc()),
           choice_spec("frictional_yield", "off", {"off", "on"},
                       "Quasi-static yield stress η_s(μ) P_qs [-] (App. A Table II) added to the "
                       "kinetic shear stress: off = the report's SKT, frictionless in shear; on "
                       "= Mohr-Coulomb friction in the packed bed (slows the bin ~2.6x at 10 mm)."),
           choice_spec("granular_energy", "algebraic", {"algebraic", "transport"},
                       "How T is found [-]: algebraic = the steady-shear balance (Eq. 15, the "
                       "report's SKT); transport = the granular energy equation with Garzó–Dufty's "
                       "conductivity (c* = 0), convection and the gas–solids exchange; needs "
                       "initial granular_temperature.")},
          DenseLimit::specs(),
          DiluteLimit::specs(),
          ViscosityLimits::specs()}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<Skt>(
           rdf::radial_distribution(string_coefficient(c, "radial_distribution")),
           string_coefficient(c, "frictional_yield") == "on", DenseLimit::read(c),
           DiluteLimit::read(c), ViscosityLimits::read(c),
           string_coefficient(c, "granular_energy") == "transport");
     }});
}  // namespace

}  // namespace bagnold::models::skt
