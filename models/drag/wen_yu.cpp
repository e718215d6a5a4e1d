// Wen–Yu drag with Schiller–Naumann C_D (Wen & Yu 1966; Schiller & Naumann 1933). See the header.
#include "models/drag/wen_yu.hpp"

#include <cmath>
#include <memory>

#include "models/drag/pointwise.hpp"

namespace bagnold::models::drag {

double schiller_naumann_drag_times_reynolds(double reynolds) {
  if (reynolds < 1000.0) return 24.0 * (1.0 + 0.15 * std::pow(reynolds, 0.687));
  return 0.44 * reynolds;
}

double wen_yu_coefficient(const DragProperties& p, double gas_fraction, double slip_speed) {
  const double solids_fraction = 1.0 - gas_fraction;
  const double d = p.particle_diameter;
  const double reynolds = gas_fraction * p.gas_density * slip_speed * d / p.gas_viscosity;
  return 0.75 * schiller_naumann_drag_times_reynolds(reynolds) * solids_fraction *
         p.gas_viscosity * std::pow(gas_fraction, -2.65) / (d * d);
}

void WenYu::evaluate(const DragProperties& properties, const DragState& in,
                     std::span<double> beta) const {
  require_valid_properties(properties, name());
  evaluate_cells(in, beta, m_min_gas_fraction, [&](double gas_fraction, double slip) {
    return wen_yu_coefficient(properties, gas_fraction, slip);
  });
}

namespace {
[[maybe_unused]] const bool registered = drag_registry().add(
    {.name = "wen-yu",
     .summary = "Wen & Yu (1966) with Schiller–Naumann C_D: dilute suspensions",
     .coefficients = {min_gas_fraction_spec()},
     .make = [](const Coefficients& c) -> std::unique_ptr<DragLaw> {
       return std::make_unique<WenYu>(read_min_gas_fraction(c));
     }});
}  // namespace

}  // namespace bagnold::models::drag
