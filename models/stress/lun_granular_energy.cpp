// Lun et al. (1984) in MFIX's LUN_1984 transport form. See the header.
#include "models/stress/lun_granular_energy.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/rdf/radial_distribution.hpp"

namespace bagnold::models::lun1984 {

PointTerms point_terms(double phi, double temperature, double drag, double slip_speed,
                       double gas_viscosity, const Material& m, double slip_temperature_floor) {
  using std::numbers::pi;
  PointTerms t;
  if (!(phi > 0.0)) return t;
  const double rho = m.density, d = m.diameter;
  const double eta = 0.5 * (1.0 + m.restitution);
  const Dual fraction = Dual::variable(phi);
  const Dual g0_dual = rdf::carnahan_starling(fraction);
  t.pressure_per_temperature = rho * fraction * (1.0 + 4.0 * eta * fraction * g0_dual);
  const double g0 = g0_dual.value;
  const double phi_g0 = phi * g0;
  t.dissipation_coefficient =
      12.0 * (1.0 - m.restitution * m.restitution) * rho * phi * phi_g0 / (std::sqrt(pi) * d);
  const double theta = temperature > 0.0 ? temperature : 0.0;
  t.slip_production = 81.0 * phi * std::pow(gas_viscosity * slip_speed, 2) /
                      (g0 * d * d * d * rho * std::sqrt(pi) * std::sqrt(theta + slip_temperature_floor));
  if (theta <= 0.0) return t;
  const double collision = rho * phi_g0 * theta;  // ρ_s φ g0 Θ
  const double dilute_viscosity = 5.0 * rho * d * std::sqrt(pi * theta) / 96.0;
  const double bulk = 256.0 * dilute_viscosity * phi * phi_g0 / (5.0 * pi);
  const double viscosity_star =
      collision * dilute_viscosity / (collision + 2.0 * drag * dilute_viscosity / (rho * phi));
  t.shear_viscosity = (2.0 + mfix_alpha) / 3.0 *
                      (viscosity_star / (eta * (2.0 - eta) * g0) * (1.0 + 1.6 * eta * phi_g0) *
                           (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * phi_g0) +
                       0.6 * eta * bulk);
  t.bulk_viscosity = eta * bulk;
  const double dilute_conductivity =
      75.0 * rho * d * std::sqrt(pi * theta) / (48.0 * eta * (41.0 - 33.0 * eta));
  const double conductivity_star =
      collision * dilute_conductivity / (collision + 1.2 * drag * dilute_conductivity / (rho * phi));
  t.conductivity = conductivity_star / g0 *
                   ((1.0 + 2.4 * eta * phi_g0) * (1.0 + 2.4 * eta * eta * (4.0 * eta - 3.0) * phi_g0) +
                    64.0 / (25.0 * pi) * (41.0 - 33.0 * eta) * std::pow(eta * phi_g0, 2));
  return t;
}

void GranularEnergy::evaluate(const Material& material, const KineticInput& in,
                              KineticTerms& out) const {
  const std::size_t n = in.solids_fraction.size();
  for (const std::size_t size :
       {in.temperature.size(), in.drag.size(), in.slip_speed.size(), out.pressure_per_temperature.size(),
        out.shear_viscosity.size(), out.bulk_viscosity.size(), out.conductivity.size(),
        out.dissipation_coefficient.size(), out.slip_production.size(), out.held.size()})
    if (size != n) throw std::invalid_argument("lun-1984: input and output arrays differ in length");
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = in.solids_fraction[i];
    const bool held = phi > m_held_above;
    const PointTerms t = point_terms(phi, held ? 0.0 : in.temperature[i], in.drag[i],
                                     in.slip_speed[i], in.gas_viscosity, material,
                                     m_slip_temperature_floor);
    out.pressure_per_temperature[i] = t.pressure_per_temperature.value;
    out.shear_viscosity[i] = t.shear_viscosity;
    out.bulk_viscosity[i] = t.bulk_viscosity;
    out.conductivity[i] = t.conductivity;
    out.dissipation_coefficient[i] = t.dissipation_coefficient;
    out.slip_production[i] = held ? 0.0 : t.slip_production;
    out.held[i] = held ? 1.0 : 0.0;
  }
}

}  // namespace bagnold::models::lun1984
