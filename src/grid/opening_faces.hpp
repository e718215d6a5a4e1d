#pragma once
// The boundary openings as faces: every face between a fluid cell and a boundary cell of a
// pressure inflow, pressure outflow or mass inflow region (the bin's orifice, its open top),
// in a fixed global order, with its corners. Snapshots write the face velocities there so a
// viewer can show the flow through an opening (docs/output.md, "Openings"), which the cell data
// cannot: the velocity of a face on the domain's boundary is stored at the ring cell outside it.

#include <array>
#include <vector>

#include "src/grid/cell_flags.hpp"
#include "src/grid/structured_grid.hpp"

namespace bagnold::grid {

struct OpeningFace {
  Natural owner = 0;     // the cell on the face's − side along `direction`: it stores the velocity
  int direction = 0;     // d: the face is normal to axis d
  Natural fluid = 0;     // the fluid cell beside it
  int region = 0;        // the boundary region of the cell on the other side
  int outward_sign = 1;  // +1 when the fluid lies on the − side (flow out is along +d), else −1
  std::array<std::array<double, 3>, 4> corners{};  // [m], counter-clockwise about +d
};

// Whether a boundary type lets a phase through: pressure inflow and outflow, mass inflow.
bool is_opening(BoundaryType type);
// Whether a boundary type holds a given pressure: pressure inflow and outflow.
bool is_pressure_opening(BoundaryType type);
// Whether cell n (natural index) is a boundary cell of an opening's region.
bool is_opening_cell(const CellFlags& flags, const BoundaryRegions& regions, Natural n);

// Every opening face of the extended box, ordered by (owner, direction); the same on every rank
// (it reads the global flags).
std::vector<OpeningFace> opening_faces(const StructuredGrid& grid, const CellFlags& flags,
                                       const BoundaryRegions& regions);

}  // namespace bagnold::grid
