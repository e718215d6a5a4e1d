// The standard kinetic theory in transport form. See the header.
#include "models/stress/skt_granular_energy.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "models/stress/friction_table.hpp"
#include "models/stress/garzo_dufty.hpp"

namespace bagnold::models::skt {

TransportFactors transport_factors(double phi, const Material& m, double critical,
                                   const rdf::RadialDistribution& radial, const DenseLimit& dense) {
  TransportFactors f;
  if (!(phi > 0.0)) return f;
  const double e = m.restitution, rho = m.density, d = m.diameter;
  const Dual fraction = Dual::variable(phi);
  const Dual g0 = rdf::evaluate(radial, dense.capped(fraction, critical), critical);
  f.pressure = rho * garzo_dufty::pressure_factor(fraction, g0, e);
  f.shear = rho * d * garzo_dufty::shear_factor(phi, g0.value, e);
  f.bulk = rho * d * garzo_dufty::bulk_factor(phi, g0.value, e);
  f.conductivity = rho * d * garzo_dufty::conductivity_factor(phi, g0.value, e);
  f.dissipation = rho / d * garzo_dufty::dissipation_factor(phi, g0.value, e);
  return f;
}

void GranularEnergy::evaluate(const Material& material, const KineticInput& in, KineticTerms& out) const {
  const std::size_t n = in.solids_fraction.size();
  for (const std::size_t size :
       {in.temperature.size(), out.pressure_per_temperature.size(), out.shear_viscosity.size(),
        out.bulk_viscosity.size(), out.conductivity.size(), out.dissipation_coefficient.size(),
        out.slip_production.size(), out.held.size()})
    if (size != n) throw std::invalid_argument("garzo-dufty: input and output arrays differ in length");
  const double critical = chialvo2012::critical_fraction(material.friction);
  for (std::size_t i = 0; i < n; ++i) {
    const auto f = transport_factors(in.solids_fraction[i], material, critical, *m_radial, m_dense);
    const double root = std::sqrt(std::max(in.temperature[i], 0.0));
    out.pressure_per_temperature[i] = f.pressure.value;
    out.shear_viscosity[i] = f.shear * root;
    out.bulk_viscosity[i] = f.bulk * root;
    out.conductivity[i] = f.conductivity * root;
    out.dissipation_coefficient[i] = f.dissipation;
    out.slip_production[i] = 0.0;
    out.held[i] = 0.0;
  }
}

}  // namespace bagnold::models::skt
