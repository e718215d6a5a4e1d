#pragma once
// The strain-rate invariants the solids-stress closures need, at cell centres, from staggered
// face velocities (issue 4, step 1 of the outer iteration):
//   cell-centred velocity  u_c = ½ (U_east + U_west) (likewise v, w; centre_velocity in
//   discretization.hpp), exact for linear fields;
//   ∇u by central differences of the cell-centred velocities between the two face neighbours,
//   one-sided where a neighbour is not fluid, zero where neither is; where it is a boundary cell
//   flagged in wall_shear_cells (per local cell; empty: none: wall_shear_cells below), the
//   tangential components take the ghost value −u_c there, so the wall shear enters γ̇;
//   D = ½ (∇u + ∇uᵀ),  γ̇ = sqrt(2 D:D) (model-notes.md: simple shear u_x = γ̇ z gives γ̇),
//   tr D = ∂u/∂x + ∂v/∂y + ∂w/∂z (from the face velocities directly: exact discrete divergence).
// Computed for owned fluid cells; the halo is exchanged; other cells get zero.
// With `tensor`, also D's six components per local cell (symmetric_component orders them).

#include <array>
#include <vector>

#include "solver/discretization.hpp"

namespace bagnold::solver {

// D_ab per local cell, six components: xx, yy, zz, xy, xz, yz.
using StrainTensor = std::array<std::vector<double>, 6>;
inline constexpr int symmetric_component(int a, int b) {
  return a == b ? a : a + b + 2;  // (0,1) → 3, (0,2) → 4, (1,2) → 5
}

void compute_strain_rate(const Discretization& discretization,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& strain_rate, std::vector<double>& divergence,
                         const std::vector<bool>& wall_shear_cells = {},
                         StrainTensor* tensor = nullptr);

// Per local cell: whether it is a boundary cell whose shear enters γ̇: a cell of a region flagged
// in wall_shear_regions (per boundary region: a stationary wall that does not let the solids
// slip), unless beside_openings is false and one of its six face neighbours (in the whole grid,
// stored on this rank or not) is a boundary cell of an opening: pressure outflow or inflow, or
// mass inflow (numerics.wall_shear_beside_openings; MFIX's SET_FLAGS). Empty when no region is
// flagged.
std::vector<bool> wall_shear_cells(const parallel::Domain& domain,
                                   const std::vector<bool>& wall_shear_regions, bool beside_openings);

}  // namespace bagnold::solver
