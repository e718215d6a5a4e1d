#pragma once
// Test helpers for models/drag/: build a law by name and evaluate it at one state. Header-only,
// shared by the drag tests.

#include <memory>
#include <string>
#include <vector>

#include "models/drag/drag_law.hpp"

namespace bagnold::tests {

using models::DragProperties;

// Air at 20 °C and 1 atm with 1 mm glass beads, the states the issue names.
inline DragProperties air_and_glass_beads() {
  return {.gas_density = 1.2, .gas_viscosity = 1.8e-5, .particle_diameter = 1e-3,
          .particle_density = 2500.0};
}

inline std::unique_ptr<models::DragLaw> make_law(const std::string& name,
                                                 const models::Coefficients& given = {}) {
  return models::drag_registry().create(name, given);
}

inline double beta_at(const models::DragLaw& law, const DragProperties& properties,
                      double gas_fraction, double slip_speed) {
  const std::vector<double> eps{gas_fraction}, slip{slip_speed};
  std::vector<double> beta(1);
  law.evaluate(properties, {eps, slip}, beta);
  return beta[0];
}

}  // namespace bagnold::tests
