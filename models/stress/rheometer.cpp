#include "models/stress/rheometer.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace bagnold::models {

namespace {
constexpr double not_defined = std::numeric_limits<double>::quiet_NaN();

std::string csv_number(double x) {
  if (std::isnan(x)) return "";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x);
  return buffer;
}
}  // namespace

std::vector<RheometerRow> shear_rheometer(const SolidsStressModel& model, const Material& material,
                                          const std::vector<double>& phis,
                                          const std::vector<double>& shear_rates) {
  const std::size_t n = phis.size() * shear_rates.size();
  std::vector<double> phi(n), rate(n), divergence(n, 0.0);
  for (std::size_t i = 0; i < phis.size(); ++i)
    for (std::size_t j = 0; j < shear_rates.size(); ++j) {
      phi[i * shear_rates.size() + j] = phis[i];
      rate[i * shear_rates.size() + j] = shear_rates[j];
    }
  std::vector<double> pressure(n), derivative(n), shear_viscosity(n), bulk_viscosity(n),
      temperature(n);
  const SolidsState in{phi, rate, divergence};
  SolidsStress out{pressure, derivative, shear_viscosity, bulk_viscosity, temperature};
  model.evaluate(material, in, out);

  std::vector<RheometerRow> rows;
  rows.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double shear_stress = shear_viscosity[k] * rate[k];
    const bool has_pressure = pressure[k] > 0.0;
    rows.push_back(
        {.model = model.name(),
         .phi = phi[k],
         .shear_rate = rate[k],
         .pressure = pressure[k],
         .shear_stress = shear_stress,
         .stress_ratio = has_pressure ? shear_stress / pressure[k] : not_defined,
         .granular_temperature = model.defines_temperature() ? temperature[k] : not_defined,
         .inertial_number =
             has_pressure ? rate[k] * material.diameter / std::sqrt(pressure[k] / material.density)
                          : not_defined});
  }
  return rows;
}

RheometerRow shear_rheometer(const SolidsStressModel& model, const Material& material, double phi,
                             double shear_rate) {
  return shear_rheometer(model, material, std::vector<double>{phi}, std::vector<double>{shear_rate})
      .front();
}

void write_rheometer_csv(std::ostream& out, const std::vector<RheometerRow>& rows, bool header) {
  if (header)
    out << "model,phi,shear_rate,pressure,shear_stress,stress_ratio,granular_temperature,"
           "inertial_number\n";
  for (const auto& r : rows)
    out << r.model << ',' << csv_number(r.phi) << ',' << csv_number(r.shear_rate) << ','
        << csv_number(r.pressure) << ',' << csv_number(r.shear_stress) << ','
        << csv_number(r.stress_ratio) << ',' << csv_number(r.granular_temperature) << ','
        << csv_number(r.inertial_number) << '\n';
}

}  // namespace bagnold::models
