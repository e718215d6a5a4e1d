// Series combination of a wall slip law with the half cell next to the wall. See the header.
#include "models/wall/wall_coefficient.hpp"

#include <cmath>
#include <stdexcept>

namespace bagnold::models::wall {

double wall_coefficient(double slip_coefficient, double viscosity, double wall_distance) {
  if (!(wall_distance > 0.0))
    throw std::invalid_argument("wall_coefficient: wall distance must be > 0 m");
  if (!(viscosity >= 0.0))
    throw std::invalid_argument("wall_coefficient: solids viscosity must be >= 0 Pa s");
  if (!(slip_coefficient >= 0.0))
    throw std::invalid_argument("wall_coefficient: slip coefficient must be >= 0 Pa s/m");
  const double bulk = viscosity / wall_distance;  // the no-slip coefficient μ_s/δ
  if (std::isinf(slip_coefficient)) return bulk;
  if (bulk == 0.0 || slip_coefficient == 0.0) return 0.0;
  return bulk * slip_coefficient / (bulk + slip_coefficient);
}

}  // namespace bagnold::models::wall
