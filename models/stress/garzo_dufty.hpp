#pragma once
// The dimensionless functions of Garzó–Dufty kinetic theory as the report writes them
// (App. B Sec. II, Eqs. 1–10), shared by SKT and MKT. With ρ_s, d and the granular
// temperature T [m²/s²]:
//   pressure        p = ρ_s H T                   (Eq. 1)
//   shear stress    τ = ρ_s d γ̇ J √T              (Eq. 2)  → shear viscosity ρ_s d J √T
//   dissipation     Γ = (ρ_s/d) K T^{3/2}          (Eq. 3)
// Terms in GD's c*(e) are neglected, as in the report (after Jenkins & Berzi).
// Templates over the scalar type (double or Dual); g0 is passed in so any g0 can be used.

namespace bagnold::models::garzo_dufty {

// H(φ, e) = φ[1 + 2(1 + e)φ g0], Eq. 4.
template <class Real>
Real pressure_factor(Real phi, Real g0, double restitution);

// η* = η_k* + η_c* + η_b*, Eqs. 7–10 (kinetic, collisional and bulk parts of the viscosity).
template <class Real>
Real scaled_viscosity(Real phi, Real g0, double restitution);

// J(φ, e) = (5√π/96) η*, Eq. 5.
template <class Real>
Real shear_factor(Real phi, Real g0, double restitution);

// K(φ, e) = (12/√π) φ² g0 (1 − e²), Eq. 6. With e_eff in place of e this is K′ (Eq. 25).
template <class Real>
Real dissipation_factor(Real phi, Real g0, double restitution);

// Bulk viscosity λ = ρ_s d J_b √T. GD's bulk viscosity κ* enters η* as η_b* = (3/5)κ*
// (Eq. 10), so J_b = (5√π/96)(5/3)η_b* = (4/(3√π))(1 + e)φ² g0 — Lun et al.'s bulk viscosity.
template <class Real>
Real bulk_factor(Real phi, Real g0, double restitution);

// Conductivity κ = ρ_s d J_κ √T of the granular energy flux q = −κ ∇T. Garzó & Dufty (1999,
// Phys. Rev. E 59, 5895, Eqs. for κ*, as MFIX's GT_PDE_GD writes them) with c* = 0 as
// everywhere here: with ζ0* = (5/12) g0 (1 − e²), ν_κ* = (g0/3)(1 + e)(1 + (33/16)(1 − e)),
//   κ_k* = (2/3)(1 + (3/5) φ g0 (1 + e)² (2e − 1)) / (ν_κ* − 2 ζ0*),
//   κ*   = κ_k* (1 + (6/5) φ g0 (1 + e)) + (256/25)(φ²/π) g0 (1 + e),
// and the dilute κ0 = (15/4) η0 = (15/4)(5√π/96) ρ_s d √T: J_κ = (15/4)(5√π/96) κ*. The report
// leaves the conductivity open (App. B Sec. V: δ_λ = 1, Jenkins & Berzi's choice, is GD's).
template <class Real>
Real conductivity_factor(Real phi, Real g0, double restitution);

}  // namespace bagnold::models::garzo_dufty
