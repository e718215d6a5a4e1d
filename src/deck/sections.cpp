#include "src/deck/sections.hpp"

#include "models/wall/wall_law.hpp"
#include "src/deck/choices.hpp"

namespace bagnold::deck {

namespace {
const std::vector<std::string> boundary_types = {"no_slip_wall",     "free_slip_wall",
                                                 "moving_wall",      "pressure_outflow",
                                                 "pressure_inflow",  "mass_inflow"};
const std::vector<std::string> wall_types = {"no_slip_wall", "free_slip_wall"};
}  // namespace

bool Grid::is_periodic(int direction) const {
  static const char* names[] = {"x", "y", "z"};
  for (const auto& p : periodic)
    if (p == names[direction]) return true;
  return false;
}

int Physics::gravity_axis() const {
  int axis = -1;
  for (int d = 0; d < 3; ++d)
    if (gravity[static_cast<std::size_t>(d)] != 0.0) {
      if (axis >= 0) return -1;
      axis = d;
    }
  return axis;
}

const Section<RunControl>& run_section() {
  static const Section<RunControl> s{"run", "Run control", {
      key(&RunControl::title, "title").init().doc("Free text shown in logs and snapshots."),
      key(&RunControl::end_time, "end_time").unit("s").required().at_least(0.0)
          .doc("Simulated time at which the run stops."),
      key(&RunControl::dt_initial, "dt_initial").unit("s").init().above(0.0)
          .doc("First time step; later steps adapt between dt_min and dt_max."),
      key(&RunControl::dt_min, "dt_min").unit("s").init().above(0.0)
          .doc("Smallest time step; a step that fails at dt_min stops the run."),
      key(&RunControl::dt_max, "dt_max").unit("s").init().above(0.0)
          .doc("Largest time step."),
  }};
  return s;
}

const Section<Physics>& physics_section() {
  static const Section<Physics> s{"physics", "Body forces", {
      key(&Physics::gravity, "gravity").unit("m/s^2").init()
          .doc("Gravitational acceleration vector (tilt it for an inclined chute)."),
  }};
  return s;
}

const Section<Grid>& grid_section() {
  static const Section<Grid> s{"grid", "Cartesian grid", {
      key(&Grid::periodic, "periodic").init().one_of({"x", "y", "z"})
          .doc("Directions whose opposite faces are a periodic pair."),
  }, {"x", "y", "z"}};
  return s;
}

const Section<Axis>& axis_section() {
  static const Section<Axis> s{"grid.x", "One grid direction ([grid.x], [grid.y], [grid.z])", {
      key(&Axis::min, "min").unit("m").init().doc("Lower end of the domain."),
      key(&Axis::max, "max").unit("m").required().doc("Upper end of the domain (> min)."),
      key(&Axis::cells, "cells").required().within(1, 1 << 20).doc("Number of cells."),
      key(&Axis::ratio, "ratio").unit("-").init().within(0.01, 100.0)
          .doc("Width of the last cell over the first: 1 is uniform, otherwise geometric."),
  }};
  return s;
}

const Section<Geometry>& geometry_section() {
  static const Section<Geometry> s{"geometry", "Geometry", {
      key(&Geometry::default_wall, "default_wall").init().one_of(wall_types)
          .doc("Wall type of every boundary cell no [[boundary]] region claims."),
  }, {"block"}};
  return s;
}

const Section<Block>& block_section() {
  static const Section<Block> s{"geometry.block", "Blocking primitives ([[geometry.block]])", {
      key(&Block::shape, "shape").required()
          .one_of({"box", "half_space", "cylinder", "cone", "quadric"})
          .doc("Primitive; a cell is blocked when its centre is inside (or outside) it."),
      key(&Block::blocks, "blocks").init().one_of({"inside", "outside"})
          .doc("Which side is solid; for cylinder/cone, outside means around it between its ends; "
               "for quadric, f ≥ 0 within its range."),
      key(&Block::min, "min").unit("m").doc("box: lower corner."),
      key(&Block::max, "max").unit("m").doc("box: upper corner."),
      key(&Block::point, "point").unit("m").doc("half_space: a point on the plane."),
      key(&Block::normal, "normal").unit("-")
          .doc("half_space: normal pointing into the blocked side (need not be unit length)."),
      key(&Block::base, "base").unit("m").doc("cylinder, cone: centre of the base disc."),
      key(&Block::axis, "axis").unit("-").doc("cylinder, cone: axis direction from the base."),
      key(&Block::length, "length").unit("m").above(0.0).doc("cylinder, cone: length along axis."),
      key(&Block::radius, "radius").unit("m").above(0.0).doc("cylinder, cone: radius at the base."),
      key(&Block::top_radius, "top_radius").unit("m").at_least(0.0)
          .doc("cone: radius at base + length along the axis."),
      key(&Block::centre, "centre").unit("m")
          .doc("quadric: the point c of f = (x−c)ᵀA(x−c) + bᵀ(x−c) + f0 (optional, default 0)."),
      key(&Block::matrix, "matrix").unit("1/m^2")
          .doc("quadric: A, 3 entries (its diagonal) or 9 (row by row)."),
      key(&Block::linear, "linear").unit("1/m").doc("quadric: b (optional, default 0)."),
      key(&Block::constant, "constant").unit("-").doc("quadric: f0; inside is where f < 0."),
      key(&Block::along, "along").one_of({"x", "y", "z"})
          .doc("quadric: the coordinate its range limits (one piece of a piecewise wall)."),
      key(&Block::range, "range").unit("m")
          .doc("quadric: [lower, upper] of that coordinate; the block acts only there."),
  }};
  return s;
}

std::vector<std::string> block_shape_keys(const std::string& shape) {
  if (shape == "box") return {"min", "max"};
  if (shape == "half_space") return {"point", "normal"};
  if (shape == "cylinder") return {"base", "axis", "length", "radius"};
  if (shape == "cone") return {"base", "axis", "length", "radius", "top_radius"};
  if (shape == "quadric") return {"centre", "matrix", "linear", "constant", "along", "range"};
  return {};
}

std::vector<std::string> block_shape_optional_keys(const std::string& shape) {
  if (shape == "quadric") return {"centre", "linear"};
  return {};
}

const Section<BoundaryRegion>& boundary_section() {
  static const Section<BoundaryRegion> s{"boundary", "Boundary regions ([[boundary]], first wins)", {
      key(&BoundaryRegion::name, "name").required()
          .doc("Name used in the monitor columns (mass flux through the region)."),
      key(&BoundaryRegion::type, "type").required().one_of(boundary_types)
          .doc("Condition on the faces between the region's cells and the fluid."),
      key(&BoundaryRegion::face, "face").init()
          .one_of({"x-", "x+", "y-", "y+", "z-", "z+", "internal", "any"})
          .doc("Domain face the region lies on, or internal (blocked cells inside the domain)."),
      key(&BoundaryRegion::min, "min").unit("m").init()
          .doc("Lower corner of the box that selects boundary cells by their centres, which on a "
               "domain face lie half a cell beyond it (see \"How regions select cells\")."),
      key(&BoundaryRegion::max, "max").unit("m").init()
          .doc("Upper corner of the selecting box."),
      key(&BoundaryRegion::pressure, "pressure").unit("Pa").init().above(0.0)
          .doc("pressure_inflow / pressure_outflow: gas pressure outside."),
      key(&BoundaryRegion::solids_pressure, "solids_pressure").init()
          .one_of({"zero", "zero-gradient"})
          .doc("pressure_outflow: the solids pressure P_s in the outflow cells: zero (the outlet "
               "is stress-free for the solids, as for material falling free below an orifice: "
               "P_s falls to 0 across its face) or zero-gradient (the adjacent fluid cell's, as "
               "MFIX's set_outflow copies P_s and P* into the outflow cell; with it the 5 mm bin "
               "jams with the steady-shear rheology, cases/bin/README.md)."),
      key(&BoundaryRegion::wall_velocity, "wall_velocity").unit("m/s").init()
          .doc("moving_wall: velocity of the wall (its tangential part is used)."),
      key(&BoundaryRegion::gas_velocity, "gas_velocity").unit("m/s").init()
          .doc("mass_inflow: gas velocity."),
      key(&BoundaryRegion::solids_velocity, "solids_velocity").unit("m/s").init()
          .doc("mass_inflow: solids velocity."),
      key(&BoundaryRegion::solids_fraction, "solids_fraction").unit("-").init().within(0.0, 1.0)
          .doc("mass_inflow: solids volume fraction ε_s."),
      key(&BoundaryRegion::solids_wall, "solids_wall").init()
          .one_of(models::wall::wall_law_registry().names())
          .doc("no_slip_wall / moving_wall: the solids' tangential wall condition (the gas keeps "
               "`type`): no-slip, free-slip, johnson-jackson (specularity, wall_restitution) or "
               "dense-slip (wall_friction; the report's App. C slip). free_slip_wall is free slip "
               "for both phases."),
      key(&BoundaryRegion::specularity, "specularity").unit("-").within(0.0, 1.0)
          .doc("solids_wall = johnson-jackson: specularity coefficient φ' (0 free slip, 1 full "
               "momentum transfer); required there."),
      key(&BoundaryRegion::wall_restitution, "wall_restitution").unit("-").within(0.0, 1.0)
          .doc("solids_wall = johnson-jackson: particle-wall restitution e_w; required there "
               "(< 1 with a closure that has no granular temperature)."),
      key(&BoundaryRegion::wall_friction, "wall_friction").unit("-").within(0.0, 10.0)
          .doc("solids_wall = dense-slip: particle-wall friction coefficient μ_w, at least "
               "μ_w* = 0.33 (the report's data); required there."),
  }};
  return s;
}

const Section<Gas>& gas_section() {
  static const Section<Gas> s{"gas", "Gas phase", {
      key(&Gas::enabled, "enabled").init()
          .doc("false: granular flow in vacuum, no gas equations are solved."),
      key(&Gas::density, "density").unit("kg/m^3").init().above(0.0).doc("ρ_g."),
      key(&Gas::viscosity, "viscosity").unit("Pa s").init().above(0.0).doc("μ_g."),
      key(&Gas::reference_pressure, "reference_pressure").unit("Pa").init().above(0.0)
          .doc("Initial gas pressure at the top of the domain."),
      key(&Gas::initial_pressure, "initial_pressure").init().one_of({"gas-weight", "bed-weight"})
          .doc("Initial gas pressure below the top: gas-weight = reference_pressure + ρ_g g h "
               "(the gas at rest); bed-weight = reference_pressure + the weight per area of the "
               "gas and solids above (each layer of cells across gravity averaged over its "
               "fluid cells, as MFIX's set_fluidbed_p when no initial pressure is given), the "
               "gas carrying the bed as in a fluidized bed. bed-weight needs gravity along one "
               "axis, not a periodic one."),
  }};
  return s;
}

const Section<models::Material>& solids_section() {
  using models::Material;
  static const Section<Material> s{"solids", "Granular phase", {
      key(&Material::diameter, "diameter").unit("m").init().above(0.0).doc("d_p."),
      key(&Material::density, "density").unit("kg/m^3").init().above(0.0).doc("ρ_s."),
      key(&Material::restitution, "restitution").unit("-").init().within(0.0, 1.0)
          .doc("e, normal coefficient of restitution."),
      key(&Material::friction, "friction").unit("-").init().within(0.0, 1.0)
          .doc("μ, interparticle friction coefficient (the report's tables cover [0, 1])."),
      key(&Material::stiffness, "stiffness").unit("N/m").init().above(0.0)
          .doc("k, normal contact stiffness (rheology models: quasi-static pressure)."),
      key(&Material::bond_number, "bond_number").unit("-").init().at_least(0.0)
          .doc("Bo*, modified Bond number (steady-shear-cohesive)."),
  }, {"enabled", "momentum"}};
  return s;
}

const Section<Solids>& solids_switch_section() {
  static const Section<Solids> s{"solids", "Granular phase", {
      key(&Solids::enabled, "enabled").init().doc("false: a single-phase (gas) run."),
      key(&Solids::momentum, "momentum").init()
          .doc("false: the solids stay as initialized (a fixed bed); the gas flows through them "
               "with ε_g and drag."),
  }};
  return s;
}

const Section<ModelChoice>& solids_stress_section() {
  static const Section<ModelChoice> s{"models.solids_stress", "Solids-stress closure", {
      key(&ModelChoice::name, "model").init_from(Models{}.solids_stress)
          .doc("Closure name; its constants go in [models.solids_stress.<model>]."),
  }};
  return s;
}

const Section<ModelChoice>& drag_section() {
  static const Section<ModelChoice> s{"models.drag", "Gas-solids drag", {
      key(&ModelChoice::name, "model").init_from(Models{}.drag)
          .doc("Drag law β; its constants go in [models.drag.<model>]."),
  }};
  return s;
}

const Section<InitialRegion>& initial_section() {
  static const Section<InitialRegion> s{"initial", "Initial state ([[initial]], later wins)", {
      key(&InitialRegion::min, "min").unit("m").init()
          .doc("Lower corner of the box (the fluid cells whose centres it contains are set; see "
               "\"How regions select cells\")."),
      key(&InitialRegion::max, "max").unit("m").init()
          .doc("Upper corner of the box."),
      key(&InitialRegion::solids_fraction, "solids_fraction").unit("-").init()
          .within(0.0, 1.0)
          .doc("ε_s; at most the selected closure's packing limit where the solids move."),
      key(&InitialRegion::gas_velocity, "gas_velocity").unit("m/s").init()
          .doc("Gas velocity."),
      key(&InitialRegion::solids_velocity, "solids_velocity").unit("m/s").init()
          .doc("Solids velocity."),
      key(&InitialRegion::granular_temperature, "granular_temperature").unit("m^2/s^2").init()
          .within(0.0, 1e6)
          .doc("Θ, the start of the granular energy equation where the closure transports Θ "
               "(granular_energy = \"transport\"; MFIX's IC_THETA_M). Ignored by an algebraic "
               "Θ. A bed with Θ = 0 and no slip stays at Θ = 0: every production term is "
               "proportional to √Θ."),
  }};
  return s;
}

const Section<PressureProbe>& pressure_probe_section() {
  static const Section<PressureProbe> s{"pressure_probe",
                                        "Pressure probes ([[pressure_probe]], monitor columns)", {
      key(&PressureProbe::name, "name").required()
          .doc("The monitor column dp_<name> [Pa] = p_g(lower) − p_g(upper), every step."),
      key(&PressureProbe::lower, "lower").unit("m").required()
          .doc("A point inside the domain: the probe's first end."),
      key(&PressureProbe::upper, "upper").unit("m").required()
          .doc("A point inside the domain: the probe's second end."),
      key(&PressureProbe::average, "average").init().one_of({"layer", "cell"})
          .doc("What each end measures: layer = the mean p_g over the fluid cells of the layer "
               "of cells across gravity that holds the point, weighted by their area across "
               "gravity (needs gravity along one axis); cell = p_g of the fluid cell that "
               "holds the point."),
  }};
  return s;
}

const Section<Numerics>& numerics_section() {
  static const Section<Numerics> s{"numerics", "Discretization and solver controls", {
      key(&Numerics::algorithm, "algorithm").init().one_of(choice_names(coupling_choices))
          .doc("Pressure-velocity coupling: SIMPLEC (d = A/(a_P − Σa_nb)) or SIMPLE (use relax_pressure ~0.3)."),
      key(&Numerics::convection, "convection").init()
          .one_of(choice_names(limiter_choices))
          .doc("Convection scheme: first-order upwind, or a TVD limiter by deferred correction."),
      key(&Numerics::tolerance, "tolerance").unit("-").init().within(1e-12, 1.0)
          .doc("A step has converged when every normalized residual is below this."),
      key(&Numerics::residual_normalization, "residual_normalization").init()
          .one_of(choice_names(residual_normalization_choices))
          .doc("What each momentum residual Σ|s − L u| is measured against. force: the forces "
               "that act on each control volume (weight, pressure, P_s, drag, wall stress), so a "
               "step passes only when the momentum equations hold to the tolerance times those "
               "forces and no viscosity or short step can hide an unbalanced one; the solids "
               "continuity too, as the force its fraction error makes through dP_s/dε_s and the "
               "weight (docs/solver.md, \"Convergence and time step\"). velocity-scale: "
               "Σ a_P U (U the largest velocity), which a large μ_s inflates. deviation: "
               "Σ(|Lu − L1 ū| + |s − L1 ū|) (OpenFOAM's), which a short step inflates. mfix: "
               "MFIX 21.3's test, to compare with MFIX at its tol_resid: Σ|A| |u| (MFIX's "
               "CALC_RESID_U), the continuity residuals against the step's first outer "
               "iteration, and their sum with the momentum residuals' against the tolerance "
               "(CHECK_CONVERGENCE)."),
      key(&Numerics::net_force_residual, "net_force_residual").init()
          .doc("Whether each momentum residual must also have a small net: |Σ (s − L u)| over the "
               "phase's rows, against the phase's weight Σ ε ρ V |g|, below the tolerance. The "
               "row residuals' sum is the force the iterate leaves unbalanced on the whole phase; "
               "a sum of magnitudes can hide it (the free-slip chute at small dt, "
               "cases/chute/README.md). No effect without gravity."),
      key(&Numerics::max_outer_iterations, "max_outer_iterations").init().within(1, 1000)
          .doc("SIMPLE outer iterations before the step is redone with dt / 2."),
      key(&Numerics::detect_stall, "detect_stall").init()
          .doc("Whether a step whose outer iteration has stopped converging is redone with dt / 2 "
               "at once instead of after max_outer_iterations (MFIX's DETECT_STALL): every 5 "
               "outer iterations, from the 15th, the largest residual must have fallen below "
               "its value 5 iterations before. It changes which dt a step is taken with, not "
               "the equations a converged step satisfies. bagnold import-mfix sets it as the "
               "MFIX deck does (MFIX's default: on)."),
      key(&Numerics::anderson_depth, "anderson_depth").init().within(0, 20)
          .doc("0: each outer iteration starts from the last one's result (Picard). m > 0: from "
               "Anderson's mixture of the last m + 1 results, the affine combination whose "
               "residuals (result minus start) are least in a norm that weighs each field by its "
               "scale (Walker & Ni 2011). It changes how a step converges, not the equations a "
               "converged step satisfies. Where a mixture would take ε_s below 0 or above the "
               "largest ε_s of the latest result, ε_s is clipped into that range (monitor column "
               "limit_anderson_clipped)."),
      key(&Numerics::easy_outer_iterations, "easy_outer_iterations").init().within(1, 1000)
          .doc("A step converged in at most this many iterations lets dt grow."),
      key(&Numerics::hard_outer_iterations, "hard_outer_iterations").init().within(0, 1000)
          .doc("A step converged in more than this many iterations makes the next dt smaller by "
               "dt_growth (not below run.dt_max / 4), so dt settles where a step takes "
               "easy_outer_iterations to hard_outer_iterations; 0: dt shrinks only when a step "
               "fails (the default: where the iterations per step hardly depend on dt, as with a tight "
               "tolerance, shrinking only adds steps). Must exceed easy_outer_iterations."),
      key(&Numerics::dt_growth, "dt_growth").unit("-").init().within(1.0, 2.0)
          .doc("Factor by which dt grows after an easy step (up to run.dt_max)."),
      key(&Numerics::max_courant, "max_courant").unit("-").init().within(1e-3, 100.0)
          .doc("Largest Courant number |u| dt/δ of either phase's face velocities (δ the distance "
               "between the cell centres the face lies between): the next dt is cut to keep it. "
               "The implicit scheme stays stable above 1; the limit keeps a step from carrying "
               "material across more than half a cell, which the outer iteration then "
               "converges at a cost of accuracy. Monitor column `courant`."),
      key(&Numerics::vacant_fraction, "vacant_fraction").unit("-").init().within(1e-14, 1e-4)
          .doc("A regularization of the granular energy equation (a closure with granular_energy "
               "= \"transport\"): a cell whose ε_s is at or below it holds no solids to carry "
               "fluctuation energy, and its Θ is set to 0 (MFIX's ZERO_EP_S). It changes Θ only in "
               "cells with less solids than this, whose stresses are negligible at any Θ; the "
               "bubbling bed's averages move with it 10x smaller no more than with a 1 % "
               "change of the first dt (cases/fluidized-bed/README.md)."),
      key(&Numerics::relax_velocity, "relax_velocity").unit("-").init().within(0.05, 1.0)
          .doc("Under-relaxation of the momentum equations, α_u."),
      key(&Numerics::wall_shear_in_strain_rate, "wall_shear_in_strain_rate").init()
          .doc("Whether a stationary no-slip solids wall's shear enters the closure's strain rate "
               "in the cells beside it (ghost value −u_c, as MFIX's ghost cells and the report's "
               "OpenFOAM code do), instead of one-sided interior differences (false)."),
      key(&Numerics::wall_shear_beside_openings, "wall_shear_beside_openings").init()
          .doc("With wall_shear_in_strain_rate, whether a no-slip wall cell that has an opening "
               "(pressure outflow or inflow, mass inflow) as a face neighbour puts its shear into "
               "the strain rate too. false: in the strain rate only, such a wall cell holds a "
               "free-slip ghost (+u_c a width away; the momentum equations keep the no-slip "
               "wall), as MFIX's SET_FLAGS makes every wall cell beside a flow boundary "
               "free-slip; it lowers the strain rate, and raises the frictional viscosity, in "
               "the cells beside an orifice's rim. import-mfix sets false (docs/import-mfix.md)."),
      key(&Numerics::copy_velocity_into_openings, "copy_velocity_into_openings").init()
          .doc("In the strain rate only: whether the outside cell of a pressure outflow or "
               "inflow holds its fluid neighbour's tangential velocity (a zero-gradient ghost a "
               "width away, as MFIX's SET_OUTFLOW copies the velocities into its outflow "
               "cells: half the one-sided difference) instead of adding nothing (false: a "
               "one-sided difference at the fluid cell). It lowers the strain rate, and raises "
               "the frictional viscosity, in the cells of an orifice. import-mfix sets true "
               "(docs/import-mfix.md)."),
      key(&Numerics::copy_fluxes_into_openings, "copy_fluxes_into_openings").init()
          .doc("In the momentum equations' convection only: whether the outside cell of a "
               "pressure outflow or inflow carries, on the three faces it stores (its +x, +y and "
               "+z faces), the mass fluxes of the fluid cell beside it, as MFIX's "
               "SET_OUTFLOW_FLUXES copies Flux_E, Flux_N and Flux_T into its outflow cells, "
               "instead of its own (false: the opening's face flux, and none across the outside "
               "cell's other faces). true: an opening's velocity face takes in, over its "
               "control volume's whole height, the momentum the material beside the opening "
               "brings sideways (at the rim, a wall's zero), so material leaves an orifice "
               "slower: MFIX's bin decks drain 10.6 % (10 mm) and 10.9 % (5 mm) slower "
               "(cases/bin/mfix/README.md). "
               "import-mfix sets true (docs/import-mfix.md)."),
      key(&Numerics::shear_on_opening_faces, "shear_on_opening_faces").init()
          .doc("Whether the velocity faces of an opening (pressure outflow or inflow, mass "
               "inflow), whose control volumes lie half in the opening's outside cell and half "
               "in the fluid cell beside it, feel the shear of the walls and faces beside them. "
               "true: with the mean viscosity of those two cells (the solids' is 0 in the "
               "outside cell, so with arithmetic means the half of the control volume inside "
               "the domain is sheared, as under a stress-free exit). false: no shear on any "
               "edge with an opening's outside cell among its four cells, for both phases, as "
               "in MFIX, whose flow-boundary cells have zero viscosity (SET_EPMUS_VALUES, "
               "SET_EPMUG_VALUES) that its harmonic edge means (GET_VCELL_SDIFF_TERMS) carry to "
               "those edges: material in an orifice's face slides along its rim. import-mfix "
               "sets false (docs/import-mfix.md)."),
      key(&Numerics::viscosity_average, "viscosity_average").init()
          .one_of(choice_names(viscosity_average_choices))
          .doc("How the viscosity on a control-volume edge is made from the four cells around it: "
               "arithmetic (their mean; exact where μ varies linearly, as it falls to zero at a "
               "free surface), harmonic (2ab/(a + b), nested as MFIX's AVG_H; exact for "
               "piecewise-constant layers) or yield-bounded (for the solids, the mean of the "
               "cells' viscosities each taken at the edge's strain rate γ̇_e, the mean of the "
               "fluid cells' γ̇ around it, as a plastic stress is: a cell that shears slower than "
               "the edge gives its stress over the edge's rate, μ_c γ̇_c/γ̇_e, so an edge between "
               "a rigid cell and a flowing one carries no more stress than its cells do; the "
               "gas's arithmetic). docs/solver.md gives the measurements behind the default."),
      key(&Numerics::viscosity_linearization, "viscosity_linearization").init()
          .one_of(choice_names(viscosity_linearization_choices))
          .doc("How the solids momentum rows of an outer iteration take the closure's μ_s(γ̇). "
               "picard: the viscous terms implicit with μ_s of the current iterate (the secant "
               "viscosity); where the stress barely depends on the rate (a jammed, frictional "
               "bed) or grows as its square (Bagnold scaling), the outer iteration then contracts "
               "by about |n − 1| per pass, n = dln τ/dln γ̇. newton: the implicit viscosity is "
               "the tangent's part along the current strain direction, μ_s (1 + (n − 1) N_de²) "
               "per face (N = √2 D/γ̇), and the rest of μ_s acts on the current iterate, so the "
               "converged step is the same; n comes from a second closure evaluation at 1.0001 γ̇. "
               "Does not change the model, only how the iteration reaches it (docs/solver.md)."),
      key(&Numerics::solids_momentum, "solids_momentum").init()
          .one_of(choice_names(solids_momentum_choices))
          .doc("How the three solids momentum components are solved in each outer iteration. "
               "segregated: one component after the other, the transpose's cross part "
               "∂_e(μ_s ∂_d u_e), e ≠ d, on the right-hand side at the current iterate (as MFIX). "
               "coupled: the three in one linear system with the cross part in the matrix, for "
               "where a large μ_s (a stagnant zone's) couples the components strongly. The same "
               "equations either way: it changes how a step converges, not what it converges to "
               "(docs/solver.md)."),
      key(&Numerics::step_solver, "step_solver").init()
          .one_of(choice_names(step_solver_choices))
          .doc("How a time step's discrete equations are solved. outer-iteration: MFIX's "
               "segregated SIMPLE iteration (momentum predictors with partial elimination of drag, "
               "pressure correction, solids fraction correction) repeated until the residuals are "
               "below numerics.tolerance. newton: all of the step's unknowns (both phases' "
               "velocities, the gas pressure, the solids fraction) in one nonlinear system, solved "
               "by Newton iterations with a line search on PETSc's SNES, each a direct solve of "
               "the coupled linearization (PETSc options with the prefix newton_); "
               "numerics.max_outer_iterations bounds the Newton iterations. The same equations "
               "and the same convergence test either way (docs/solver.md, \"Newton on the whole step\"). "
               "Not with a transported granular energy."),
      key(&Numerics::newton_linearization, "newton_linearization").init()
          .one_of(choice_names(newton_linearization_choices))
          .doc("The Jacobian of numerics.step_solver = \"newton\". exact: the derivative of the "
               "step's equations (applied matrix-free). stress-velocity: the same, except that the "
               "solids' rate-independent (frictional, plastic) stress is linearized with a stress "
               "direction of its own instead of the strain direction (Rudi, Shih & Stadler 2020), "
               "which keeps the stiffness of a zone that stands rigid; the exact derivative has none "
               "there, and Newton stalls in a bin's stagnant corners. Only the path to the solution "
               "differs: the converged step is the same."),
      key(&Numerics::solids_bulk_viscosity_ratio, "solids_bulk_viscosity_ratio").unit("-").init()
          .within(0.0, 100.0)
          .doc("r: a bulk viscosity r μ_s added to the closure's own λ_s (σ = −P_s I + 2 μ_s D + "
               "(λ_s − ⅔ μ_s) ∇·u I), which dissipates the work a rate-dependent P_s does on "
               "expansion. 0: the closure's λ_s alone."),
      key(&Numerics::solids_bulk_viscosity_until, "solids_bulk_viscosity_until").unit("s").init()
          .within(0.0, std::numeric_limits<double>::infinity())
          .doc("The bulk viscosity r μ_s acts in the steps that start before this time and not "
               "after it, so that a run can use it to get through a start-up and then run the "
               "closure's own equations. inf: the whole run. Where it ends, the run carries on "
               "from the state it reached; whether that state is one the closure alone holds is "
               "shown by running on (cases/chute/README.md, \"The stabilizer\")."),
      key(&Numerics::pressure_shear_rate_relaxation_time, "pressure_shear_rate_relaxation_time")
          .unit("s").init().within(0.0, 1e3)
          .doc("τ_P: the closure's P_s and dP_s/dε_s are evaluated at a shear rate γ̇_P that "
               "relaxes towards the current one over τ_P in each cell (dγ̇_P/dt = (γ̇ − γ̇_P)/τ_P, "
               "implicit Euler, not advected; μ_s and Θ keep the current rate). The steady-state "
               "equations are unchanged (γ̇_P = γ̇); which steady state a run reaches, and whether "
               "it holds, can depend on τ_P. It stops a rate-dependent P_s from following creep and "
               "bursts instantly in jammed zones (cases/chute/README.md). 0: P_s at the current "
               "rate."),
      key(&Numerics::relax_pressure, "relax_pressure").unit("-").init().within(0.01, 1.0)
          .doc("Under-relaxation of the pressure correction, α_p."),
      key(&Numerics::pressure_preconditioner, "pressure_preconditioner").init()
          .one_of({"hypre", "gamg"})
          .doc("Algebraic multigrid for the pressure correction: hypre BoomerAMG (HMIS "
               "coarsening, extended+i interpolation with at most 4 entries per row, one level of "
               "aggressive coarsening; -pressure_pc_hypre_boomeramg_* options override each) or PETSc GAMG, "
               "built afresh in a new solver object at the steps pressure_preconditioner_steps "
               "says (so either restarts bit-exactly) and kept over the outer iterations between. "
               "Either converges to the same answer; which costs less depends on the case "
               "(docs/benchmarks.md, \"The pressure preconditioner\")."),
      key(&Numerics::pressure_preconditioner_steps, "pressure_preconditioner_steps").init()
          .within(1, 1000)
          .doc("How many time steps one build of the pressure preconditioner serves: it is "
               "built afresh at the first step, every this many steps, after every snapshot and "
               "for a redone step, and its later solves take it with their own matrix. A restart "
               "from a snapshot builds where the run continued past it did, and stays bit-exact. "
               "It changes how many iterations a pressure solve takes to pressure_tolerance, and "
               "so the outer iterations' path within the outer tolerance (the 5 mm bin drained "
               "0.07 % slower over another dt path); above 1 the steps on which it is built depend on "
               "when snapshots are written, so two runs with different snapshot schedules (or one "
               "stopped by a signal and restarted) agree to the outer tolerance, not to the bit. "
               "20 saves 14 % of the CPU time of MFIX's 5 mm bin deck (docs/benchmarks.md, \"The "
               "pressure preconditioner\")."),
      key(&Numerics::pressure_tolerance, "pressure_tolerance").unit("-").init()
          .within(1e-14, 0.5).doc("Relative tolerance of the pressure-correction solve: each "
               "outer iteration reduces the linear residual by this factor from its value at the "
               "current iterate. The next outer iteration assembles the system anew, so a tighter "
               "solve changes how many outer iterations a step takes, not what it converges to "
               "(numerics.tolerance decides that; docs/benchmarks.md, \"Linear tolerances\")."),
      key(&Numerics::momentum_tolerance, "momentum_tolerance").unit("-").init()
          .within(1e-14, 0.5).doc("Relative tolerance of the momentum solves, as "
               "pressure_tolerance for the pressure correction."),
      key(&Numerics::momentum_preconditioner, "momentum_preconditioner").init()
          .one_of({"jacobi", "bjacobi"})
          .doc("Preconditioner of the momentum solves (BiCGStab): point Jacobi (the same on any "
               "number of ranks, and no factorization per solve) or block Jacobi with ILU(0) on "
               "each rank's block. Either changes how a solve reaches momentum_tolerance, not "
               "what it converges to."),
      key(&Numerics::partition_weights, "partition_weights").init()
          .one_of({"cells", "work", "phases", "layers"})
          .doc("What the partition over ranks balances: fluid cells; work (a fluid cell "
               "holding solids weighs as much as it costs against a gas-only one); phases "
               "(each rank its share of the fluid cells and of the cells holding solids, so that "
               "the gas steps and the solids steps of the outer iteration are each balanced); "
               "or layers (each layer of cells across gravity split evenly over the ranks, cut "
               "along gravity: a bed that fills the domain from the bottom gives every rank its "
               "share of the bed and of the gas above at any fill level; needs gravity along one "
               "axis). Work and phases are weighed from the initial state or the restart "
               "snapshot's, so a restart on more than one rank agrees with the run it continues "
               "to the solver tolerance; cells and layers come from the geometry alone, and a "
               "restart on as many ranks is bit-identical."),
      key(&Numerics::repartition_imbalance, "repartition_imbalance").unit("-").init()
          .within(0.0, 10.0)
          .doc("On more than one rank, 0: the partition stays as the run started. x > 0: at each "
               "snapshot, when the largest rank's work above the ranks' mean (its fluid cells weighed "
               "as partition_weights = \"work\" weighs them, from the current state) has grown "
               "by more than the fraction x since the partition was made, the ranks partition "
               "the domain anew from the current state (by phases under partition_weights = "
               "\"phases\", else by work) and continue from the snapshot just written, which carries the state "
               "to its new owners. It moves cells between ranks, not the equations: the "
               "continuation agrees with one on the old partition to the solver tolerance. Not "
               "with partition_weights = \"layers\", which does not depend on the state."),
  }};
  return s;
}

const Section<Output>& output_section() {
  static const Section<Output> s{"output", "Output", {
      key(&Output::directory, "directory").required()
          .doc("Where snapshots, the XDMF index, the monitor, run.toml and provenance.toml go "
               "(created if missing); a fresh run refuses one that holds a run unless --overwrite. "
               "A restart writes into its snapshot's directory unless --set gives this key."),
      key(&Output::snapshot_interval, "snapshot_interval").unit("s").init().above(0.0)
          .doc("Simulated time between HDF5 snapshots. Each is written at the end of the first step that "
               "reaches its scheduled time, at that step's time: steps are not shortened for "
               "output, so the schedule does not change the answer (the final step lands on "
               "run.end_time); with numerics.pressure_preconditioner_steps above 1 it moves the "
               "answer within the outer tolerance."),
      key(&Output::progress, "progress").init().one_of({"auto", "always", "never"})
          .doc("The progress line (simulated time, dt, outer iterations, time left). auto: "
               "redrawn in place on stderr when stderr is a terminal, else a plain line on "
               "stdout every output.progress_interval; always: redrawn in place on stderr even "
               "when it is not a terminal; never: none. Log lines clear it first either way."),
      key(&Output::progress_interval, "progress_interval").unit("s").init().within(0.0, 86400.0)
          .doc("Wall time between plain progress lines (output.progress = auto without a "
               "terminal); 0 writes one after every step."),
  }};
  return s;
}

}  // namespace bagnold::deck
