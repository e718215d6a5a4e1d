#pragma once
// The strain-rate invariants the solids-stress closures need, at cell centres, from staggered
// face velocities (issue 4, step 1 of the outer iteration):
//   cell-centred velocity  u_c = ½ (U_east + U_west) (likewise v, w; centre_velocity in
//   discretization.hpp), exact for linear fields;
//   ∇u by central differences of the cell-centred velocities between the two face neighbours,
//   one-sided where a neighbour is not fluid, zero where neither is; where it is a boundary cell
//   with a ghost in wall_ghosts (per local cell; empty: none: strain_rate_ghosts below), the
//   tangential components take the ghost value there: −u_c (a no-slip wall, whose shear then
//   enters γ̇) or +u_c (a free-slip ghost), a width away;
//   D = ½ (∇u + ∇uᵀ),  γ̇ = sqrt(2 D:D) (model-notes.md: simple shear u_x = γ̇ z gives γ̇),
//   tr D = ∂u/∂x + ∂v/∂y + ∂w/∂z (from the face velocities directly: exact discrete divergence).
// Computed for owned fluid cells; the halo is exchanged; other cells get zero.
// With `tensor`, also D's six components per local cell (symmetric_component orders them).

#include <array>
#include <cstdint>
#include <vector>

#include "solver/discretization.hpp"

namespace bagnold::solver {

// D_ab per local cell, six components: xx, yy, zz, xy, xz, yz.
using StrainTensor = std::array<std::vector<double>, 6>;
inline constexpr int symmetric_component(int a, int b) {
  return a == b ? a : a + b + 2;  // (0,1) → 3, (0,2) → 4, (1,2) → 5
}

// What a boundary cell beside a fluid cell gives γ̇'s stencil there: nothing (a one-sided
// difference), a no-slip ghost (−u_c a width away: the wall's shear) or a free-slip ghost
// (+u_c a width away: half the one-sided difference), as MFIX's ghost cells.
enum class WallGhost : std::uint8_t { none, no_slip, mirror };

void compute_strain_rate(const Discretization& discretization,
                         const std::array<std::vector<double>, 3>& velocity,
                         std::vector<double>& strain_rate, std::vector<double>& divergence,
                         const std::vector<WallGhost>& wall_ghosts = {},
                         StrainTensor* tensor = nullptr);

// Per local cell, the ghost it is in γ̇: no_slip for a boundary cell of a region flagged in
// wall_shear_regions (per boundary region: a stationary wall that does not let the solids slip),
// mirror instead when beside_openings is false and one of its six face neighbours (in the whole
// grid, stored on this rank or not) is a boundary cell of an opening: pressure outflow or
// inflow, or mass inflow (numerics.wall_shear_beside_openings; MFIX's SET_FLAGS makes those
// wall cells free-slip for γ̇); mirror for a pressure outflow or inflow cell when
// copy_into_openings (numerics.copy_velocity_into_openings; MFIX's SET_OUTFLOW); none elsewhere.
// Empty when no cell has a ghost.
std::vector<WallGhost> strain_rate_ghosts(const parallel::Domain& domain,
                                        const std::vector<bool>& wall_shear_regions, bool beside_openings,
                                        bool copy_into_openings = false);

}  // namespace bagnold::solver
