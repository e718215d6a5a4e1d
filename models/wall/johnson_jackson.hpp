#pragma once
// Johnson–Jackson partial slip for the solids (Johnson & Jackson 1987, J. Fluid Mech. 176:67,
// the report's App. C ref. [12]; the report itself prints no formula, so the form is the one
// MFIX and OpenFOAM's JohnsonJacksonParticleSlip use, with Θ = ⅓⟨C²⟩):
//   wall shear stress   τ_w = −c_JJ u_slip,
//                       c_JJ = (π√3/6) φ' ρ_s (φ/φ_max) g0 √Θ                     [Pa s/m]
//   energy flux into the flow from the wall (generation by slip − collisional loss at the wall)
//                       q_w = c_JJ |u_slip|² − (√3π/4)(1 − e_w²) ρ_s (φ/φ_max) g0 Θ^{3/2}   [W/m²]
// φ' specularity coefficient (0 free slip … 1 full momentum transfer), e_w particle–wall
// restitution, u_slip the solids velocity at the wall minus the wall's.
//
// Which Θ. A closure with an algebraic temperature (skt, mkt) has no conduction term, so the
// energy condition q_w cannot be imposed; use the first interior cell's Θ. A closure without a
// temperature (steady-shear) gets the temperature at which the wall neither feeds nor drains
// fluctuation energy, q_w = 0:  Θ_w = (2/3) φ' |u_slip|² / (1 − e_w²)  (wall_temperature below).
// Then c_JJ ∝ |u_slip|, a stress quadratic in the slip; lagged from the previous iterate it
// stays implicit. Pass c_JJ to wall_coefficient() for the coefficient of the momentum row.

#include "models/material.hpp"

namespace bagnold::models::wall {

struct JohnsonJacksonWall {
  double specularity;       // φ' [-], in [0, 1]
  double wall_restitution;  // e_w [-], in [0, 1]
  double max_packing;       // φ_max [-], in (0, 1]: the closure's packing limit
};

// Throws std::invalid_argument when a property is outside the ranges above.
void require_valid(const JohnsonJacksonWall& wall);

// c_JJ [Pa s/m] for solids fraction φ [-], radial distribution g0 [-] and granular
// temperature Θ [m²/s²] of the first interior cell (all ≥ 0).
double johnson_jackson_slip_coefficient(const JohnsonJacksonWall& wall, const Material& material,
                                        double solids_fraction, double radial_distribution,
                                        double granular_temperature);

// q_w [W/m²], positive into the flow, for the slip speed |u_slip| [m/s].
double johnson_jackson_energy_flux(const JohnsonJacksonWall& wall, const Material& material,
                                   double solids_fraction, double radial_distribution,
                                   double granular_temperature, double slip_speed);

// Θ_w [m²/s²] at which q_w = 0 (for closures without a temperature). Needs e_w < 1.
double johnson_jackson_wall_temperature(const JohnsonJacksonWall& wall, double slip_speed);

}  // namespace bagnold::models::wall
