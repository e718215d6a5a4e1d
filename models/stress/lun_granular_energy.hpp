#pragma once
// Lun et al. (1984)'s kinetic theory in the transport form MFIX solves with KT_TYPE =
// 'LUN_1984' (MFIX routines GT_PDE_LUN in calc_mu_s.f and SOURCE_GRANULAR_ENERGY in
// source_granular_energy.f): Lun, Savage, Jeffrey & Chepurniy, J. Fluid Mech. 140 (1984)
// 223–256, with MFIX's two gas–solids modifications (its SWITCH = 1) and its factor (2 + α)/3.
// With η = (1 + e)/2, g0 Carnahan–Starling (App. B Eq. 11) and Θ the granular temperature:
//   P_s  = ρ_s φ Θ (1 + 4 η φ g0)
//   μ_d  = 5 ρ_s d √(πΘ)/96,  μ_b = 256 μ_d φ² g0/(5π)
//   μ*   = ρ_s φ g0 Θ μ_d / (ρ_s φ g0 Θ + 2 β μ_d/(ρ_s φ))             (μ_d without gas)
//   μ_s  = (2 + α)/3 [μ*/(η(2 − η) g0) (1 + 8/5 η φ g0)(1 + 8/5 η(3η − 2) φ g0) + 3/5 η μ_b],
//          α = 1.6 (MFIX's constant ALPHA; 1 recovers Lun et al.'s own coefficient)
//   λ_s  = η μ_b  (the bulk viscosity; MFIX's second viscosity is η μ_b − ⅔ μ_s)
//   κ_d  = 75 ρ_s d √(πΘ)/(48 η (41 − 33η))
//   κ*   = ρ_s φ g0 Θ κ_d / (ρ_s φ g0 Θ + 6/5 β κ_d/(ρ_s φ))
//   κ_s  = κ*/g0 [(1 + 12/5 η φ g0)(1 + 12/5 η²(4η − 3) φ g0) + 64/(25π)(41 − 33η)(η φ g0)²]
//   Γ    = 48/√π η(1 − η) ρ_s φ² g0 Θ^{3/2}/d = 12(1 − e²) ρ_s φ² g0 Θ^{3/2}/(√π d)
//   S_slip = 81 φ (μ_g |u_g − u_s|)²/(g0 d³ ρ_s √π √Θ)   (Koch & Sangani, J. Fluid Mech. 400
//          (1999) 229–263, as MFIX adds it; √Θ is MFIX's √(Θ + 10⁻¹⁵))
// and the gas–solids exchange −3βΘ, which the equation takes from β itself.
// Valid: slightly inelastic, frictionless spheres, 0 < φ below packing.

#include <string>

#include "models/dual.hpp"
#include "models/stress/granular_energy.hpp"

namespace bagnold::models::lun1984 {

inline constexpr double mfix_alpha = 1.6;  // α of MFIX's (2 + α)/3
// The default of mfix-default's slip_temperature_floor [m²/s²]: MFIX's SMALL_NUMBER, added to Θ
// under the square root of Koch & Sangani's slip production so that it is finite where Θ = 0.
inline constexpr double default_slip_temperature_floor = 1e-15;

// The terms at one point; pressure_per_temperature carries d/dφ (at fixed Θ) in its slope.
struct PointTerms {
  Dual pressure_per_temperature;
  double shear_viscosity = 0.0, bulk_viscosity = 0.0, conductivity = 0.0;
  double dissipation_coefficient = 0.0, slip_production = 0.0;
};
// φ ≤ 0 or Θ ≤ 0 give zero viscosities and conductivity (MFIX: μ* = κ* = 0 at Θ → 0).
// slip_temperature_floor: Θ_floor in the slip production's √(Θ + Θ_floor).
PointTerms point_terms(double phi, double temperature, double drag, double slip_speed,
                       double gas_viscosity, const Material& material,
                       double slip_temperature_floor = default_slip_temperature_floor);

// The theory as the granular energy equation takes it. held_above: Θ is held at 0 where
// φ > held_above (mfix-default: the plastic regime ε_g < ε_g*, as MFIX's
// SOLVE_GRANULAR_ENERGY does with Schaeffer's friction); above 1 it never is.
class GranularEnergy final : public GranularEnergyTheory {
 public:
  GranularEnergy(double held_above, double slip_temperature_floor)
      : m_held_above(held_above), m_slip_temperature_floor(slip_temperature_floor) {}
  std::string name() const override { return "lun-1984"; }
  void evaluate(const Material& material, const KineticInput& in, KineticTerms& out) const override;

 private:
  double m_held_above;
  double m_slip_temperature_floor;
};

}  // namespace bagnold::models::lun1984
