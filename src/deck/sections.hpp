#pragma once
// The declarations of every deck section (one table each; see schema.hpp).

#include "src/deck/deck.hpp"
#include "src/deck/schema.hpp"

namespace bagnold::deck {

const Section<RunControl>& run_section();
const Section<Physics>& physics_section();
const Section<Grid>& grid_section();
const Section<Axis>& axis_section();  // [grid.x], [grid.y], [grid.z]
const Section<Geometry>& geometry_section();
const Section<Block>& block_section();  // [[geometry.block]]
const Section<BoundaryRegion>& boundary_section();  // [[boundary]]
const Section<Gas>& gas_section();
const Section<models::Material>& solids_section();
const Section<Solids>& solids_switch_section();  // solids.enabled, read with [solids]
const Section<ModelChoice>& solids_stress_section();  // [models.solids_stress]
const Section<ModelChoice>& drag_section();           // [models.drag]
const Section<InitialRegion>& initial_section();  // [[initial]]
const Section<PressureProbe>& pressure_probe_section();  // [[pressure_probe]]
const Section<Numerics>& numerics_section();
const Section<Output>& output_section();

// Keys of each block shape, beyond `shape` and `blocks`.
std::vector<std::string> block_shape_keys(const std::string& shape);
// Those of block_shape_keys(shape) a deck may leave out (the member's initializer applies).
std::vector<std::string> block_shape_optional_keys(const std::string& shape);

}  // namespace bagnold::deck
