#pragma once
// The resolved deck: every value a run uses, in SI units, after defaults, overrides and checks.
// A key's default is the initializer of its member here (or in models/material.hpp), written
// nowhere else; its unit, range and doc are declared once, in src/deck/sections.cpp, whose
// `.init()` says the key takes that default. The key reference (docs/deck.md) is generated from
// both by `bagnold keys`.

#include <array>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "models/coefficients.hpp"
#include "models/material.hpp"

namespace bagnold::deck {

struct RunControl {
  std::string title;
  double end_time = 0.0;     // [s]
  double dt_initial = 1e-4;  // [s]
  double dt_min = 1e-7;      // [s]
  double dt_max = 1e-2;      // [s]
};

struct Physics {
  std::array<double, 3> gravity{0.0, 0.0, -9.81};  // [m/s²]
  // The axis gravity acts along, or -1 when it has more than one non-zero component (or none).
  int gravity_axis() const;
};

struct Axis {
  double min = 0.0;    // [m]
  double max = 0.0;    // [m]
  int cells = 1;
  double ratio = 1.0;  // width of the last cell / width of the first (geometric stretching)
};

struct Grid {
  Axis x, y, z;
  std::vector<std::string> periodic;  // subset of {"x", "y", "z"}
  bool is_periodic(int direction) const;
};

// A primitive that blocks cells (their centres) inside or outside of it.
struct Block {
  std::string shape;  // box | half_space | cylinder | cone | quadric
  std::string blocks = "inside";  // inside | outside
  std::array<double, 3> min{0, 0, 0}, max{0, 0, 0};       // box [m]
  std::array<double, 3> point{0, 0, 0}, normal{0, 0, 1};  // half_space: blocks where (x−p)·n > 0
  std::array<double, 3> base{0, 0, 0}, axis{0, 0, 1};     // cylinder / cone: base centre, axis
  double length = 0.0;      // [m] along the axis from the base
  double radius = 0.0;      // [m] at the base
  double top_radius = 0.0;  // [m] at base + length (cone only)
  // quadric: f(x) = (x−c)ᵀA(x−c) + bᵀ(x−c) + f0, inside where f < 0, over range[0] ≤ x_along ≤
  // range[1] only (one piece of a piecewise wall; src/grid/shapes.hpp).
  std::array<double, 3> centre{0, 0, 0};  // c [m]
  std::vector<double> matrix;             // A [1/m²]: 3 entries (diagonal) or 9 (row by row)
  std::array<double, 3> linear{0, 0, 0};  // b [1/m]
  double constant = 0.0;                  // f0 [-]
  std::string along = "z";                // x | y | z: the coordinate `range` limits
  std::vector<double> range;              // [m] [lower, upper]
};

struct Geometry {
  std::string default_wall = "no_slip_wall";
  std::vector<Block> blocks;
};

// A boundary region: the boundary cells (outside the domain or blocked, next to fluid) whose
// centres fall in [min, max], restricted to one face of the domain or to internal walls.
struct BoundaryRegion {
  std::string name;
  std::string type;           // no_slip_wall | free_slip_wall | moving_wall | pressure_outflow |
                              // pressure_inflow | mass_inflow
  std::string face = "any";   // x- | x+ | y- | y+ | z- | z+ | internal | any
  std::array<double, 3> min{-1e30, -1e30, -1e30}, max{1e30, 1e30, 1e30};
  double pressure = 101325.0;                 // [Pa] pressure inflow/outflow
  // pressure_outflow: P_s beyond the outlet, "zero" (stress-free) or "zero-gradient" (MFIX).
  std::string solids_pressure = "zero";
  std::array<double, 3> wall_velocity{0, 0, 0};    // [m/s] moving wall
  std::array<double, 3> gas_velocity{0, 0, 0};     // [m/s] mass inflow
  std::array<double, 3> solids_velocity{0, 0, 0};  // [m/s] mass inflow
  double solids_fraction = 0.0;               // ε_s of the inflow [-]
  // Walls (no_slip_wall, moving_wall): the solids' tangential condition; the gas keeps `type`.
  std::string solids_wall = "no-slip";  // no-slip | free-slip | johnson-jackson | dense-slip
  double specularity = 0.0;        // φ' [-], johnson-jackson
  double wall_restitution = 0.0;   // e_w [-], johnson-jackson
  double wall_friction = 0.0;      // μ_w [-], dense-slip
};

struct Gas {
  bool enabled = true;
  double density = 1.2;        // ρ_g [kg/m³]
  double viscosity = 1.8e-5;   // μ_g [Pa s]
  double reference_pressure = 101325.0;  // [Pa]
  // The initial gas pressure below the top: gas-weight (ρ_g g h) or bed-weight (the weight of
  // gas and solids above, per area of each layer: MFIX's set_fluidbed_p).
  std::string initial_pressure = "gas-weight";
};

struct Solids {
  bool enabled = true;
  bool momentum = true;  // false: solids frozen as initialized (a fixed bed), as MFIX's MOMENTUM_EQ
  models::Material material;
};

struct ModelChoice {
  std::string name;
  models::Coefficients coefficients;  // resolved: every declared coefficient present
};

struct Models {
  ModelChoice solids_stress{.name = "mkt", .coefficients = {}};
  ModelChoice drag{.name = "gidaspow", .coefficients = {}};
};

struct InitialRegion {
  std::array<double, 3> min{-1e30, -1e30, -1e30}, max{1e30, 1e30, 1e30};
  double solids_fraction = 0.0;
  std::array<double, 3> gas_velocity{0, 0, 0};
  std::array<double, 3> solids_velocity{0, 0, 0};
  double granular_temperature = 0.0;  // Θ [m²/s²], where the closure transports it
};

// A pressure probe: the monitor column dp_<name> = p_g(lower) − p_g(upper) [Pa], each end the
// gas pressure of the fluid cell containing the point (average = cell) or the area-weighted mean
// over the fluid cells of the layer across gravity that contains it (average = layer).
struct PressureProbe {
  std::string name;
  std::array<double, 3> lower{0, 0, 0}, upper{0, 0, 0};  // [m]
  std::string average = "layer";  // layer | cell
};

struct Numerics {
  std::string algorithm = "simplec";     // simplec | simple
  std::string convection = "superbee";   // upwind | superbee | muscl | van_leer | minmod
  double tolerance = 1e-4;               // normalized residual for convergence of a step
  std::string residual_normalization = "velocity-scale";  // velocity-scale | force | deviation | mfix
  bool net_force_residual = false;  // also |Σ row residuals| / the phase's weight
  int max_outer_iterations = 40;         // before the step is redone with dt / 2
  bool detect_stall = false;             // redo a step whose largest residual stops falling
  int anderson_depth = 0;                // 0: Picard; m: Anderson mixing over the last m iterates
  int easy_outer_iterations = 8;         // at or below: the next step grows
  int hard_outer_iterations = 0;         // above (if > 0): the next step shrinks
  double dt_growth = 1.2;                // factor after an easy step
  double max_courant = 0.5;              // largest |u| dt/δ of either phase
  double vacant_fraction = 1e-8;         // ε_s at or below which Θ = 0 (granular energy equation)
  double relax_velocity = 0.7;           // α_u
  bool wall_shear_in_strain_rate = true;  // no-slip walls' shear in the wall cells' γ̇
  bool wall_shear_beside_openings = true;  // false: wall cells beside an opening free-slip in γ̇ (MFIX)
  bool copy_velocity_into_openings = false;  // true: openings hold the fluid's velocity in γ̇ (MFIX)
  std::string viscosity_average = "arithmetic";  // arithmetic | harmonic | yield-bounded
  bool copy_fluxes_into_openings = false;  // true: openings carry the fluid's mass fluxes in convection (MFIX)
  bool shear_on_opening_faces = true;  // false: an opening's velocity faces feel no wall or edge shear (MFIX)
  std::string viscosity_linearization = "picard";  // picard | newton
  std::string solids_momentum = "segregated";  // segregated | coupled
  std::string step_solver = "outer-iteration";  // outer-iteration | newton
  std::string newton_linearization = "stress-velocity";  // stress-velocity | exact
  double solids_bulk_viscosity_ratio = 0.0;  // r μ_s added to the closure's λ_s
  double solids_bulk_viscosity_until = std::numeric_limits<double>::infinity();  // [s]: in steps starting before
  double pressure_shear_rate_relaxation_time = 0.0;  // τ_P [s]: P_s at γ̇ relaxed over τ_P
  double relax_pressure = 1.0;           // α_p (SIMPLE needs about 0.3)
  std::string pressure_preconditioner = "hypre";  // hypre | gamg
  int pressure_preconditioner_steps = 1;  // time steps one multigrid hierarchy serves
  double pressure_tolerance = 1e-2;      // relative, per outer iteration
  double momentum_tolerance = 1e-2;      // relative, per outer iteration
  std::string momentum_preconditioner = "jacobi";  // jacobi | bjacobi
  std::string partition_weights = "cells";  // cells | work | phases | layers
  double repartition_imbalance = 0.0;  // 0: off; else repartition by work above this imbalance
};

struct Output {
  std::string directory;
  double snapshot_interval = 0.1;  // [s]
  std::string progress = "auto";   // auto | always | never
  double progress_interval = 30.0; // [s] of wall time between plain progress lines
};

// Where a value of the deck was written: the file, line and column, or the --set argument that
// gave it (line 0). Checks made after loading (a region that selects no cell, a grid too large
// for the machine) point at it as the loader's own errors do.
struct Origin {
  std::string file;
  int line = 0;
  int column = 0;
};

struct Deck {
  std::string source;  // path of the deck file
  RunControl run;
  Physics physics;
  Grid grid;
  Geometry geometry;
  std::vector<BoundaryRegion> boundaries;
  Gas gas;
  Solids solids;
  Models models;
  std::vector<InitialRegion> initial;
  std::vector<PressureProbe> pressure_probes;  // [[pressure_probe]]
  Numerics numerics;
  Output output;
  // Every table, array element and key of the deck by its dotted path as messages name it
  // ("boundary[1]", "grid.z.cells"); origin_of falls back to the deck file without a line.
  std::map<std::string, Origin> origins;
  Origin origin_of(const std::string& path) const;
};

}  // namespace bagnold::deck
