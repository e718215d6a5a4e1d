#pragma once
// The array loop every drag law shares: it checks the spans and the properties, clips ε_g into
// [min_gas_fraction, 1] and |slip| to ≥ 0, and hands one cell at a time to the law's point
// function (a non-virtual, inlinable callable), so the interface stays one virtual call per
// array.

#include <cmath>
#include <span>
#include <stdexcept>
#include <string>

#include "models/coefficients.hpp"
#include "models/drag/drag_law.hpp"

namespace bagnold::models::drag {

// min_gas_fraction [-], shared by every drag law: ε_g below it is evaluated at it. The solids
// closures stop packing near ε_g ≈ 0.36, so in a converged solution it does not act; it keeps β
// finite for a solver iterate that overshoots (at ε_g → 0 Ergun's 1/ε_g, Wen–Yu's ε_g^−2.65 and
// Syamlal–O'Brien's 1/V_r all diverge).
CoefficientSpec min_gas_fraction_spec();
double read_min_gas_fraction(const Coefficients& c);

// Rejects properties no drag law can use (the deck range-checks them too; this guards direct
// callers). ρ_g = 0 is allowed: every law then reduces to its viscous (Stokes/Darcy) part.
inline void require_valid_properties(const DragProperties& p, const std::string& law) {
  if (!(p.gas_density >= 0.0 && p.gas_viscosity > 0.0 && p.particle_diameter > 0.0 &&
        p.particle_density >= 0.0))
    throw std::invalid_argument(law + ": drag needs ρ_g ≥ 0, μ_g > 0, d_p > 0 and ρ_s ≥ 0");
}

// point(ε_g, |slip|) -> β for one cell.
template <class PointFunction>
void evaluate_cells(const DragState& in, std::span<double> beta, double min_gas_fraction,
                    PointFunction&& point) {
  const std::size_t n = in.gas_fraction.size();
  if (in.slip_speed.size() != n || beta.size() != n)
    throw std::invalid_argument("drag: input and output arrays differ in length");
  for (std::size_t i = 0; i < n; ++i) {
    const double raw = in.gas_fraction[i];
    const double gas_fraction = raw > 1.0 ? 1.0 : (raw > min_gas_fraction ? raw : min_gas_fraction);
    beta[i] = point(gas_fraction, std::abs(in.slip_speed[i]));
  }
}

}  // namespace bagnold::models::drag
