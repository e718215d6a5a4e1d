#include "solver/convection_limiter.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bagnold::solver {

Limiter limiter_from_name(const std::string& name) {
  if (name == "upwind") return Limiter::upwind;
  if (name == "superbee") return Limiter::superbee;
  if (name == "muscl") return Limiter::muscl;
  if (name == "van_leer") return Limiter::van_leer;
  if (name == "minmod") return Limiter::minmod;
  throw std::invalid_argument("unknown convection scheme '" + name + "'");
}

double limiter(Limiter kind, double r) {
  if (r <= 0.0) return 0.0;
  switch (kind) {
    case Limiter::upwind: return 0.0;
    case Limiter::superbee: return std::max(std::min(2.0 * r, 1.0), std::min(r, 2.0));
    case Limiter::muscl: return std::min({2.0 * r, 0.5 * (1.0 + r), 2.0});
    case Limiter::van_leer: return 2.0 * r / (1.0 + r);
    case Limiter::minmod: return std::min(r, 1.0);
  }
  return 0.0;
}

double tvd_correction(Limiter kind, double upwind_upwind, double upwind, double downwind) {
  const double jump = downwind - upwind;
  if (kind == Limiter::upwind || std::abs(jump) < 1e-300) return 0.0;
  const double r = (upwind - upwind_upwind) / jump;
  return 0.5 * limiter(kind, r) * jump;
}

}  // namespace bagnold::solver
