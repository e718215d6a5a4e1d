#include "src/grid/cell_flags.hpp"

#include <stdexcept>

#include "src/grid/shapes.hpp"

namespace bagnold::grid {

namespace {
const char* const type_names[] = {"no_slip_wall",    "free_slip_wall",  "moving_wall",
                                  "pressure_outflow", "pressure_inflow", "mass_inflow"};

// Whether a boundary cell at `ijk` lies on the given face ("x-", "internal", "any", ...).
bool on_face(const StructuredGrid& grid, const Index3& ijk, const std::string& face) {
  if (face == "any") return true;
  if (face == "internal") return grid.in_domain(ijk);
  const int d = face[0] - 'x';
  return face[1] == '-' ? ijk[d] == -1 : ijk[d] == grid.cells(d);
}
}  // namespace

bool region_selects(const StructuredGrid& grid, const Index3& ijk, const deck::BoundaryRegion& region) {
  return on_face(grid, ijk, region.face) && inside_box(grid.centre(ijk), region.min, region.max);
}

BoundaryType boundary_type_from_name(const std::string& name) {
  for (int t = 0; t < 6; ++t)
    if (name == type_names[t]) return static_cast<BoundaryType>(t);
  throw std::invalid_argument("unknown boundary type '" + name + "'");
}

const char* boundary_type_name(BoundaryType type) {
  return type_names[static_cast<int>(type)];
}

BoundaryRegions make_boundary_regions(const deck::Deck& deck) {
  BoundaryRegions out;
  out.regions = deck.boundaries;
  deck::BoundaryRegion walls;
  walls.name = "walls";
  walls.type = deck.geometry.default_wall;
  out.regions.push_back(walls);
  for (const auto& r : out.regions) out.types.push_back(boundary_type_from_name(r.type));
  return out;
}

CellFlags classify_cells(const StructuredGrid& grid, const deck::Geometry& geometry,
                         const BoundaryRegions& regions) {
  const std::int64_t n = grid.extended_cell_count();
  CellFlags flags;
  flags.kind.assign(static_cast<std::size_t>(n), CellKind::excluded);
  flags.region.assign(static_cast<std::size_t>(n), -1);
  flags.block_cells.assign(geometry.blocks.size(), 0);

  // 1. Fluid: domain cells whose centre no primitive blocks.
  for (std::int64_t c = 0; c < n; ++c) {
    const Index3 ijk = grid.index3(c);
    if (!grid.in_domain(ijk)) continue;
    const auto x = grid.centre(ijk);
    bool blocked = false;
    for (std::size_t b = 0; b < geometry.blocks.size(); ++b)
      if (blocks_point(geometry.blocks[b], x)) {
        blocked = true;
        ++flags.block_cells[b];
      }
    if (!blocked) {
      flags.kind[static_cast<std::size_t>(c)] = CellKind::fluid;
      ++flags.fluid_count;
    }
  }

  // 2. Boundary skin: non-fluid cells (blocked, or in the ring of a non-periodic direction)
  //    touching fluid, including across edges and corners.
  for (std::int64_t c = 0; c < n; ++c) {
    if (flags.kind[static_cast<std::size_t>(c)] == CellKind::fluid) continue;
    const Index3 ijk = grid.index3(c);
    bool ring_of_periodic = false;
    for (int d = 0; d < 3; ++d)
      ring_of_periodic = ring_of_periodic ||
                         (grid.periodic(d) && (ijk[d] == -1 || ijk[d] == grid.cells(d)));
    if (ring_of_periodic) continue;
    bool touches_fluid = false;
    for (int dk = -1; dk <= 1 && !touches_fluid; ++dk)
      for (int dj = -1; dj <= 1 && !touches_fluid; ++dj)
        for (int di = -1; di <= 1 && !touches_fluid; ++di) {
          Index3 other;
          if (grid.step(ijk, {di, dj, dk}, other) &&
              flags.kind[static_cast<std::size_t>(grid.natural(other))] == CellKind::fluid)
            touches_fluid = true;
        }
    if (!touches_fluid) continue;
    flags.kind[static_cast<std::size_t>(c)] = CellKind::boundary;
    ++flags.boundary_count;
    // 3. Region: the first [[boundary]] that selects the cell, else "walls".
    int region = regions.default_region();
    for (int r = 0; r < regions.default_region(); ++r)
      if (region_selects(grid, ijk, regions.regions[static_cast<std::size_t>(r)])) {
        region = r;
        break;
      }
    flags.region[static_cast<std::size_t>(c)] = static_cast<std::int16_t>(region);
  }
  return flags;
}

}  // namespace bagnold::grid
