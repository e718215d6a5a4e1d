#pragma once
// TVD limiters ψ(r) for the deferred-correction convection scheme: the face value is
// φ_f = φ_U + ½ ψ(r) (φ_D − φ_U), r = (φ_U − φ_UU)/(φ_D − φ_U) (U upwind, D downwind,
// UU upwind of U). ψ = 0 is first-order upwind.

#include <algorithm>
#include <cmath>
#include <string>

#include "src/deck/choices.hpp"

namespace bagnold::solver {

using Limiter = deck::Limiter;  // named in deck::limiter_choices

inline Limiter limiter_from_name(const std::string& name) {
  return deck::choice_value(deck::limiter_choices, name, "convection scheme");
}

// Inline: called for every convective face of every momentum row.
inline double limiter(Limiter kind, double r) {
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

// The higher-order face value minus the upwind value, ½ ψ(r) (φ_D − φ_U).
inline double tvd_correction(Limiter kind, double upwind_upwind, double upwind, double downwind) {
  const double jump = downwind - upwind;
  if (kind == Limiter::upwind || std::abs(jump) < 1e-300) return 0.0;
  // r ≤ 0 (ψ = 0, a local extremum or a flat upwind side) is read from the signs, without the
  // division.
  const double slope = upwind - upwind_upwind;
  if (slope == 0.0 || (slope > 0.0) != (jump > 0.0)) return 0.0;
  return 0.5 * limiter(kind, slope / jump) * jump;
}

}  // namespace bagnold::solver
