#pragma once
// Component d of a staggered velocity at a cell centre: the mean of the cell's two faces along d,
//   u_c = ½ (U_east + U_west)   (likewise v from the north and south faces, w from top and bottom),
// where the field holds, at each local cell, the velocity on its + face (docs/output.md).
// Convention at walls and openings: the face between a fluid cell and a boundary cell is stored
// (fixed or solved), so the mean is always of two faces there; a − face that is not stored on
// this rank (only beyond the halo, where no result is used) counts as the cell's own + face.
// The one face-to-centre average: the solver's closures and the snapshots' cell-centred
// velocity vectors both use it.

#include <vector>

#include "src/parallel/layout.hpp"

namespace bagnold::parallel {

inline double centre_velocity(const Layout& layout, const std::vector<double>& u, int l, int d) {
  const int minus = layout.neighbour(l, 2 * d);
  const double own = u[static_cast<std::size_t>(l)];
  return 0.5 * (own + (minus >= 0 ? u[static_cast<std::size_t>(minus)] : own));
}

}  // namespace bagnold::parallel
