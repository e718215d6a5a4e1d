// Syamlal–O'Brien drag (Syamlal & O'Brien 1989; Garside & Al-Dibouni 1977). See the header.
#include "models/drag/syamlal_obrien.hpp"

#include <cmath>
#include <memory>

#include "models/drag/pointwise.hpp"

namespace bagnold::models::drag {

double dalla_valle_drag_times_reynolds(double reynolds) {
  const double root = 0.63 * std::sqrt(reynolds) + 4.8;
  return root * root;
}

double terminal_velocity_ratio(double gas_fraction, double reynolds, const GarsideAlDibouni& c) {
  const double a = std::pow(gas_fraction, 4.14);
  const double b =
      gas_fraction <= 0.85 ? c.c1 * std::pow(gas_fraction, 1.28) : std::pow(gas_fraction, c.d1);
  // V_r = ½ (a − x + s), x = 0.06 Re, s = sqrt((x − a)² + 4 x b) — the radicand rewritten from
  // the header's form; it is a sum of non-negative terms.
  const double x = 0.06 * reynolds;
  const double s = std::sqrt((x - a) * (x - a) + 4.0 * x * b);
  if (a >= x) return 0.5 * (a - x + s);
  // For x > a, a − x + s cancels; multiplying by (s − (a − x))/(s − (a − x)) gives 2 x b/(s + x − a).
  return 2.0 * x * b / (s + x - a);
}

double syamlal_obrien_coefficient(const DragProperties& p, double gas_fraction,
                                  double slip_speed, const GarsideAlDibouni& c) {
  const double d = p.particle_diameter;
  const double reynolds = p.gas_density * slip_speed * d / p.gas_viscosity;
  const double velocity_ratio = terminal_velocity_ratio(gas_fraction, reynolds, c);
  return 0.75 * (1.0 - gas_fraction) * gas_fraction * p.gas_viscosity *
         dalla_valle_drag_times_reynolds(reynolds / velocity_ratio) / (velocity_ratio * d * d);
}

void SyamlalObrien::evaluate(const DragProperties& properties, const DragState& in,
                             std::span<double> beta) const {
  require_valid_properties(properties, name());
  evaluate_cells(in, beta, m_min_gas_fraction, [&](double gas_fraction, double slip) {
    return syamlal_obrien_coefficient(properties, gas_fraction, slip, m_constants);
  });
}

namespace {
[[maybe_unused]] const bool registered = drag_registry().add(
    {.name = "syamlal-obrien",
     .summary = "Syamlal & O'Brien (1989): Dalla Valle C_D at the Garside–Al-Dibouni V_r",
     .coefficients = {real_spec("c1", "-", 0.8, 0.05, 1.0,
                                "c1 [-]: B = c1 ε_g^1.28 for ε_g ≤ 0.85 in V_r (MFIX drag_c1)."),
                      real_spec("d1", "-", 2.65, 0.5, 30.0,
                                "d1 [-]: B = ε_g^d1 for ε_g > 0.85 in V_r (MFIX drag_d1); "
                                "1.28 + log c1/log 0.85 keeps B continuous."),
                      min_gas_fraction_spec()},
     .make = [](const Coefficients& c) -> std::unique_ptr<DragLaw> {
       return std::make_unique<SyamlalObrien>(
           GarsideAlDibouni{.c1 = real_coefficient(c, "c1"), .d1 = real_coefficient(c, "d1")},
           read_min_gas_fraction(c));
     }});
}  // namespace

}  // namespace bagnold::models::drag
