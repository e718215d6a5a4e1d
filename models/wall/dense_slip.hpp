#pragma once
// Dense-flow wall slip of Chialvo et al. (report App. C) in its coarse-grained, translation-only
// form: the apparent slip velocity of the solids at a wall, from the stress ratio η and the
// viscosity ν of the flow next to it (Sec. III.D generalization, Eqs. 32–40, 47–48):
//   x        = (η − η_s)/(μ_w + μ_w* − η_s),   μ_w* = 0.33          Eqs. 13, 15
//   I_surf   = 1.55 x^{2/3}/(1 − x)^{5.25}                           Eq. 14 (x ≤ x_max, below)
//   e_eff    = e − (3/2) μ exp(−3μ)                                   Eq. 27
//   m'       = 23.4 (1 − e_eff²) arctan[6 (μ_w/η_s − 1)]            Eq. 26
//   I'       = m' (η − η_s)                                          Eq. 28
//   m        = 1/g(μ)²,  g(μ) = 1 − exp(−6μ)                        Eqs. 19, 22
//   I_rot    = m I'                                                  Eq. 20
//   I_slip   = I_surf + I_rot                                        Eq. 24
//   F(η)     = I_slip^app = I_slip + I' = I_surf + (1 + m) I'        Eqs. 31, 45
//   |v_slip^app| = ν/(ρ_s d) · F(η),  directed against the wall-tangential velocity
//                                                                    Eqs. 29, 38–39, 47–48
// η_s(μ) is the yield stress ratio of the bulk rheology's table (model-notes: the same table).
//
// Implicit form. Written as a slip coefficient c_slip = τ/|v_slip^app| [Pa s/m] with τ = η p the
// first interior cell's shear stress, τ_w = −c_slip v_slip is a Robin condition the momentum row
// takes on its diagonal (wall_coefficient.hpp), never a velocity imposed on the solver. At
// convergence it returns Eq. 48 with η, ν taken in the first interior cell (Eq. 40's coarse-grid
// choice; docs/models.md says why) and the wall stress in place of τ.
//
// Limits (docs/models.md, "Dense-flow wall slip"):
//   η ≤ η_s (x ≤ 0): no surface slip, F = 0, c_slip = +∞ (no slip); likewise F ≤ 0, p ≤ 0, τ ≤ 0.
//   x → 1: Eq. 14 diverges; x is capped at x_max (default 0.9, where I_surf ≈ 2.6e5: as good as
//          free slip) so F stays finite and c_slip > 0.
//   μ_w < μ_w* = 0.33: refused (std::invalid_argument). The report's data cover sustained shear
//          only (App. C Sec. III.A); below μ_w* the walls do not shear the material at all.
//   μ < 0.1: refused. m = 1/g(μ)² diverges as μ → 0, and the report tabulates no friction between
//          0 and 0.1.
//   0.33 ≤ μ_w < η_s(μ): m' < 0 as printed (Eq. 26); used as printed, F clipped at 0.

#include "models/material.hpp"

namespace bagnold::models::wall {

namespace chialvo_slip {  // App. C's constants; its symbols, not App. A's or B's
constexpr double critical_wall_friction = 0.33;  // μ_w* [-], Sec. III.A and Eq. 13
constexpr double min_particle_friction = 0.1;    // μ [-], smallest μ > 0 in the report's tables

double slip_abscissa(double stress_ratio, double yield_stress_ratio,
                     double wall_friction);                 // x, Eqs. 13, 15
double surface_slip(double abscissa);                       // I_surf(x), Eq. 14; 0 for x ≤ 0
double effective_restitution(double restitution, double friction);  // e_eff, Eq. 27
double rotation_ratio(double friction);                     // m = 1/g(μ)², Eqs. 19, 22
double boundary_layer_slope(double restitution, double friction, double wall_friction,
                            double yield_stress_ratio);     // m', Eq. 26
}  // namespace chialvo_slip

struct DenseSlipWall {
  double wall_friction;            // μ_w [-], particle–wall friction, ≥ 0.33
  double max_slip_abscissa = 0.9;  // x_max [-], in (0, 1): cap of x in Eq. 14
};

// The first interior cell's state, as the solver has it.
struct NearWallState {
  double pressure;     // P_s [Pa]
  double viscosity;    // μ_s = ν_core [Pa s]  (Eq. 40 at the first interior cell)
  double strain_rate;  // γ̇ [1/s]
  // η = τ/p with τ = μ_s γ̇; 0 (no slip) where p ≤ 0.
  double stress_ratio() const;
};

class DenseSlip {
 public:
  // Checks the limits above; throws std::invalid_argument with the range when outside.
  DenseSlip(const Material& material, const DenseSlipWall& wall, double yield_stress_ratio);

  // F(η) = I_slip^app [-], Eqs. 14, 20, 24, 28, 31; ≥ 0, and 0 for η ≤ η_s.
  double scaled_apparent_slip(double stress_ratio) const;
  // |v_slip^app| [m/s] = ν F(η)/(ρ_s d), Eq. 48.
  double apparent_slip_speed(double stress_ratio, double viscosity) const;
  // c_slip [Pa s/m] = τ/|v_slip^app| = ρ_s d γ̇ / F(η); +∞ (no slip) where F = 0 or τ = 0.
  double slip_coefficient(const NearWallState& state) const;
  // c_w [Pa s/m] for the momentum row of the tangential velocity δ [m] from the wall:
  // 1/c_w = δ/μ_s + 1/c_slip (wall_coefficient.hpp); no slip gives exactly μ_s/δ.
  double wall_coefficient(const NearWallState& state, double wall_distance) const;

  double yield_stress_ratio() const { return m_yield_stress_ratio; }

 private:
  double m_density;             // ρ_s [kg/m³]
  double m_diameter;            // d [m]
  double m_wall_friction;       // μ_w [-]
  double m_max_abscissa;        // x_max [-]
  double m_yield_stress_ratio;  // η_s [-]
  double m_rotation_ratio;      // m [-]
  double m_layer_slope;         // m' [-]
};

}  // namespace bagnold::models::wall
