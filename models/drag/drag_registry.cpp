// The drag registry and the coefficient every drag law shares.
#include "models/drag/drag_law.hpp"
#include "models/drag/pointwise.hpp"

namespace bagnold::models {

Registry<DragLaw>& drag_registry() {
  static Registry<DragLaw> registry;
  return registry;
}

namespace drag {

CoefficientSpec min_gas_fraction_spec() {
  return real_spec("min_gas_fraction", "-", 0.2, 0.01, 0.5,
                   "ε_g,min [-]: gas fractions below it are evaluated at it, so β stays finite "
                   "for an iterate past the packing limit (never acts in a converged state).");
}

double read_min_gas_fraction(const Coefficients& c) {
  return real_coefficient(c, "min_gas_fraction");
}

}  // namespace drag
}  // namespace bagnold::models
