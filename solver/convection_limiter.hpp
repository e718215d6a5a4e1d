#pragma once
// TVD limiters ψ(r) for the deferred-correction convection scheme: the face value is
// φ_f = φ_U + ½ ψ(r) (φ_D − φ_U), r = (φ_U − φ_UU)/(φ_D − φ_U) (U upwind, D downwind,
// UU upwind of U). ψ = 0 is first-order upwind.

#include <string>

namespace bagnold::solver {

enum class Limiter { upwind, superbee, muscl, van_leer, minmod };

Limiter limiter_from_name(const std::string& name);
double limiter(Limiter kind, double r);
// The higher-order face value minus the upwind value, ½ ψ(r) (φ_D − φ_U).
double tvd_correction(Limiter kind, double upwind_upwind, double upwind, double downwind);

}  // namespace bagnold::solver
