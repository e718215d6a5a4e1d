#pragma once
// What each cell of the extended box is: fluid (an active cell, solved for), boundary (a
// blocked or out-of-domain cell next to fluid, stored to carry boundary values), or excluded
// (blocked and away from fluid: never stored). Boundary cells belong to a boundary region.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/grid/structured_grid.hpp"

namespace bagnold::grid {

// A deck whose geometry cannot be run (e.g. every cell blocked): bad input, with the reason.
class GeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class CellKind : std::uint8_t { excluded = 0, fluid = 1, boundary = 2 };

enum class BoundaryType : std::uint8_t {
  no_slip_wall, free_slip_wall, moving_wall, pressure_outflow, pressure_inflow, mass_inflow
};
BoundaryType boundary_type_from_name(const std::string& name);
const char* boundary_type_name(BoundaryType type);

// The deck's [[boundary]] regions, followed by one implicit region "walls" of
// geometry.default_wall that takes every boundary cell no region claims.
struct BoundaryRegions {
  std::vector<deck::BoundaryRegion> regions;
  std::vector<BoundaryType> types;
  int default_region() const { return static_cast<int>(regions.size()) - 1; }
};
BoundaryRegions make_boundary_regions(const deck::Deck& deck);

struct CellFlags {
  std::vector<CellKind> kind;        // per natural index of the extended box
  std::vector<std::int16_t> region;  // boundary region of boundary cells, -1 otherwise
  std::int64_t fluid_count = 0;
  std::int64_t boundary_count = 0;
  // Per [[geometry.block]]: the domain cells whose centre it blocks (also those another block
  // blocks too). The same on every rank: each builds the flags of the whole box.
  std::vector<std::int64_t> block_cells;
};

// Whether a [[boundary]] region selects the boundary cell at `ijk`: the cell lies on the
// region's face (the ring cell outside it, for x- ... z+; inside the domain, for internal) and
// its centre is in [min, max]. A ring cell's centre lies half a cell outside the domain face,
// so a box that selects one on a domain face reaches past that face.
bool region_selects(const StructuredGrid& grid, const Index3& ijk, const deck::BoundaryRegion& region);

// Marks blocked cells from the deck's primitives, then the boundary skin: every non-fluid cell
// with a fluid cell among its 26 neighbours (periodic directions wrap). A boundary cell belongs
// to the first [[boundary]] region that selects it, else to the implicit "walls".
CellFlags classify_cells(const StructuredGrid& grid, const deck::Geometry& geometry,
                         const BoundaryRegions& regions);

}  // namespace bagnold::grid
