#pragma once
// The drag interface (DESIGN.md, "Equations and algorithm", step 1): one call evaluates the
// interphase momentum exchange coefficient β over whole arrays of cells, never a virtual call
// per cell.
//
// Convention (as MFIX's F_gs, "model A"): the drag force per unit volume of mixture on the gas
// is −β (u_g − u_s) and on the solids +β (u_g − u_s); β [kg/(m³ s)] ≥ 0. So that a solver
// can treat drag implicitly and by partial elimination, every law here
//   - is finite for ε_g ∈ [0.3, 1] and slip speeds 0…100 m/s, including slip exactly 0, where
//     it returns its Stokes-limit value (not zero: β is a coefficient, the force β·0 vanishes);
//   - vanishes linearly and smoothly as ε_s = 1 − ε_g → 0 (β ∝ ε_s there).
// Gas fractions outside the range are clipped (drag/pointwise.hpp): above 1 to 1 (β = 0), below
// to the law's min_gas_fraction (default 0.2), where β is still finite.

#include <span>
#include <string>

#include "models/registry.hpp"

namespace bagnold::models {

struct DragProperties {
  double gas_density;             // ρ_g [kg/m³]
  double gas_viscosity;           // μ_g [Pa s]
  double particle_diameter;       // d_p [m]
  double particle_density = 0.0;  // ρ_s [kg/m³]; none of the laws shipped here needs it
};

struct DragState {
  std::span<const double> gas_fraction;  // ε_g [-]
  std::span<const double> slip_speed;    // |u_g − u_s| [m/s], at the cell centre
};

class DragLaw {
 public:
  virtual ~DragLaw() = default;
  virtual std::string name() const = 0;
  // Fills beta[i] = β(ε_g[i], |u_g − u_s|[i]) [kg/(m³ s)]; all spans of equal length.
  virtual void evaluate(const DragProperties& properties, const DragState& in,
                        std::span<double> beta) const = 0;
};

Registry<DragLaw>& drag_registry();

}  // namespace bagnold::models
