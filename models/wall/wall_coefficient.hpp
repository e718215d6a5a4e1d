#pragma once
// The implicit form every solids wall law takes in Bagnold (docs/models.md, "Dense-flow wall
// slip"). A partial-slip law gives the wall shear stress as a Robin condition on the solids
// velocity *at the wall*,
//     τ_w = −c_slip (u_wall-side − U_wall)          c_slip [Pa s/m] ≥ 0,
// with c_slip = 0 free slip and c_slip = ∞ no slip. On a staggered grid the tangential velocity
// u_P nearest the wall sits a distance δ inside it (half a cell); between the two the bulk
// viscosity μ_s carries the same stress, τ_w = −μ_s (u_P − u_wall-side)/δ. Eliminating the
// unknown wall-side velocity puts the two resistances in series:
//     τ_w = −c_w (u_P − U_wall),     1/c_w = δ/μ_s + 1/c_slip.
// The momentum row of u_P then gets a_P += c_w A and b += c_w A U_wall (A the wall face area):
// the same place the no-slip term μ_s A/δ goes, so the wall stays implicit and c_w ≤ μ_s/δ
// never makes the row less diagonally dominant than a no-slip wall does.

namespace bagnold::models::wall {

// c_w [Pa s/m] from c_slip [Pa s/m] (may be +∞: no slip), the first interior cell's solids
// viscosity μ_s [Pa s] ≥ 0 and the wall distance δ [m] > 0 of its tangential velocity.
// No slip (c_slip = ∞) gives μ_s/δ; free slip (c_slip = 0) gives 0. Throws
// std::invalid_argument for δ ≤ 0, μ_s < 0 or c_slip < 0 (or NaN).
double wall_coefficient(double slip_coefficient, double viscosity, double wall_distance);

}  // namespace bagnold::models::wall
