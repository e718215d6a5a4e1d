// Gidaspow drag: Ergun (1952) below ε_g = 0.8, Wen–Yu (1966) above (Gidaspow 1994). See the header.
#include "models/drag/gidaspow.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "models/drag/pointwise.hpp"
#include "models/drag/wen_yu.hpp"

namespace bagnold::models::drag {

double ergun_coefficient(const DragProperties& p, double gas_fraction, double slip_speed) {
  const double solids_fraction = 1.0 - gas_fraction;
  const double d = p.particle_diameter;
  return 150.0 * solids_fraction * solids_fraction * p.gas_viscosity / (gas_fraction * d * d) +
         1.75 * solids_fraction * p.gas_density * slip_speed / d;
}

double gidaspow_blend_weight(double gas_fraction) {
  return std::atan(150.0 * 1.75 * (gas_fraction - gidaspow_switch_gas_fraction)) /
             std::numbers::pi +
         0.5;
}

void Gidaspow::evaluate(const DragProperties& properties, const DragState& in,
                        std::span<double> beta) const {
  require_valid_properties(properties, name());
  if (m_transition == GidaspowTransition::step) {
    evaluate_cells(in, beta, m_min_gas_fraction, [&](double gas_fraction, double slip) {
      return gas_fraction <= gidaspow_switch_gas_fraction
                 ? ergun_coefficient(properties, gas_fraction, slip)
                 : wen_yu_coefficient(properties, gas_fraction, slip);
    });
    return;
  }
  evaluate_cells(in, beta, m_min_gas_fraction, [&](double gas_fraction, double slip) {
    const double weight = gidaspow_blend_weight(gas_fraction);
    return (1.0 - weight) * ergun_coefficient(properties, gas_fraction, slip) +
           weight * wen_yu_coefficient(properties, gas_fraction, slip);
  });
}

namespace {
GidaspowTransition read_transition(const Coefficients& c) {
  return string_coefficient(c, "transition") == "arctan-blend" ? GidaspowTransition::arctan_blend
                                                               : GidaspowTransition::step;
}

[[maybe_unused]] const bool registered = drag_registry().add(
    {.name = "gidaspow",
     .summary = "Gidaspow (1994): Ergun for ε_g ≤ 0.8, Wen–Yu above",
     .coefficients = {choice_spec("transition", "step", {"step", "arctan-blend"},
                                  "Ergun/Wen–Yu switch at ε_g = 0.8 [-]: \"step\" (Gidaspow, "
                                  "MFIX GIDASPOW; discontinuous) or \"arctan-blend\" (MFIX "
                                  "GIDASPOW_BLEND; smooth)."),
                      min_gas_fraction_spec()},
     .make = [](const Coefficients& c) -> std::unique_ptr<DragLaw> {
       return std::make_unique<Gidaspow>(read_transition(c), read_min_gas_fraction(c));
     }});
}  // namespace

}  // namespace bagnold::models::drag
