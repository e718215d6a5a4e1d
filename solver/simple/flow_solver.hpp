#pragma once
// The two-fluid (Euler–Euler) solver on the staggered grid, as MFIX solves it: gas and one
// solids phase share the gas pressure P, are coupled by drag β, and the solids carry a pressure
// P_s and viscosity μ_s from the solids-stress closure (DESIGN.md, "Equations and algorithm"):
//   ∂(ε_g ρ_g u_g)/∂t + ∇·(ε_g ρ_g u_g u_g) = −ε_g ∇P + ∇·(ε_g μ_g ∇u_g) + ε_g ρ_g g + β (u_s − u_g)
//   ∂(ε_s ρ_s u_s)/∂t + ∇·(ε_s ρ_s u_s u_s) = −ε_s ∇P − ∇P_s + ∇·(μ_s ∇u_s) + ε_s ρ_s g + β (u_g − u_s)
//   ∂ε_s/∂t + ∇·(ε_s u_s) = 0,   ε_g = 1 − ε_s,   ∇·(ε_g u_g + ε_s u_s) = 0 (both incompressible).
// Either phase may be absent: gas alone (solids.enabled = false: ε_g = 1, β = 0, the single-phase
// solver), frozen solids (solids.momentum = false: a fixed bed), or solids in vacuum
// (gas.enabled = false: no gas momentum, no pressure correction).
//
// One time step (advance.cpp), outer iterations until every normalized residual is below
// numerics.tolerance:
//   0. closures on the current iterate (solids_closure.cpp): β, P_s, dP_s/dε_s, μ_s, Θ;
//   1. momentum predictors of both phases per direction (momentum_assembly.cpp,
//      momentum_predictor.cpp) with partial elimination of the drag coupling;
//   2. pressure correction from the mixture volume continuity (pressure_correction.cpp); both
//      phases' velocities respond to p' through their d coefficients;
//   3. solids volume fraction correction (volume_fraction_correction.cpp): solids continuity
//      with the solids-pressure gradient linearized through dP_s/dε_s; ε_s then follows from
//      the corrected fluxes in conservative form (solids mass conserved to round-off);
//      ε_g = 1 − ε_s.

#include <array>
#include <memory>
#include <vector>

#include "models/drag/drag_law.hpp"
#include "models/stress/solids_stress.hpp"
#include "solver/convection_limiter.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/simple/momentum_residual.hpp"
#include "solver/simple/solids_wall.hpp"
#include "solver/unknown_numbering.hpp"
#include "solver/velocity_faces.hpp"
#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// The equations whose residuals a step watches, in this order.
enum Equation : int {
  gas_momentum_x, gas_momentum_y, gas_momentum_z,
  solids_momentum_x, solids_momentum_y, solids_momentum_z,
  mixture_continuity, solids_continuity,
  equation_count
};
const char* equation_name(int equation);

struct Residuals {
  std::array<double, equation_count> value{};  // normalized, per Equation
  double largest() const;
  int worst() const;  // the Equation with the largest (NaN counts as largest)
};

// Where an equation's residual is largest: for the message when a run cannot continue.
struct CellLocation {
  grid::Index3 cell{0, 0, 0};
  std::array<double, 3> position{0, 0, 0};  // cell centre [m]
};

struct StepResult {
  bool converged = false;
  int iterations = 0;
  Residuals residuals;
};

enum Phase : int { gas = 0, solids = 1 };

// One assembled momentum row of one phase, before drag, relaxation and partial elimination.
struct MomentumRow {
  double a = 0.0;              // diagonal: convection, diffusion, transient
  double b = 0.0;              // sources: pressure, gravity, transient, TVD correction
  double neighbours_a = 0.0;   // Σ a_nb
  double neighbours_u = 0.0;   // Σ a_nb u_nb at the current iterate
  double transient = 0.0;      // ε ρ V/dt, the part of a from the time derivative
  double fraction = 0.0;       // ε of the phase at the face velocity
  double area = 0.0;           // face area normal to the velocity
  double volume = 0.0;         // control volume of the face velocity
  bool active = true;          // false: a solids row below the threshold, u_s = 0
  int count = 0;               // off-diagonal entries
  std::int64_t columns[6];
  double values[6];            // −a_nb
};

class FlowSolver {
 public:
  FlowSolver(const deck::Deck& deck, const parallel::Domain& domain);

  // Sets the boundary values every stencil reads: given face velocities, boundary pressures,
  // the solids fraction of boundary cells.
  void apply_boundary_values(run::FlowState& state) const;
  // Advances `state` (holding the last iterate, initially `old`) by one time step dt.
  StepResult advance(run::FlowState& state, const run::FlowState& old, double dt);

  // An extra gas momentum source [N/m³] at each face velocity of direction d (local_count()
  // entries, indexed by the owning cell), e.g. a manufactured solution's forcing. Empty: none.
  void set_momentum_source(int d, std::vector<double> source) {
    m_source[static_cast<std::size_t>(d)] = std::move(source);
  }

  // Collective: the cell with the largest residual of `equation` in the last outer iteration.
  CellLocation worst_cell(int equation) const;

  // Net mass flux [kg/s] of a phase out through each boundary region (monitor).
  std::vector<double> boundary_mass_flux(const run::FlowState& state, Phase phase) const;
  // The solids mass flux per region [kg/s] through which the last converged step changed the
  // inventory: the fluxes conserve_solids used (before it updated ε_s, which changes the upwind
  // ε_s at an outlet), so the monitor's outflow balances the inventory to round-off. Falls back
  // to boundary_mass_flux(state, solids) where the solids do not move.
  std::vector<double> stepped_solids_flux(const run::FlowState& state) const;

  bool moves(Phase phase) const { return m_moves[phase]; }

 private:
  // Step 0: β at cell centres; P_s, dP_s/dε_s, μ_s, Θ from the closure; the gas's ε_g μ_g.
  // P_s is evaluated at γ̇_P (state.pressure_shear_rate), relaxed from old's over dt.
  void evaluate_drag(const run::FlowState& state);
  void evaluate_solids_stress(run::FlowState& state, const run::FlowState& old, double dt);
  // Step 1: assembles one phase's momentum rows for direction d (owned unknown faces, in row order).
  void assemble_momentum(Phase phase, int d, const run::FlowState& state,
                         const run::FlowState& old, double dt, std::vector<MomentumRow>& rows);
  // Step 1: both phases for direction d: partial elimination, relaxation, solve, d and e.
  void predict_momentum(int d, run::FlowState& state, const run::FlowState& old, double dt,
                        Residuals& residuals);
  // Step 2: mixture volume continuity; corrects P and both velocities; returns its residual.
  double correct_pressure(run::FlowState& state);
  // Step 3: solids continuity with dP_s/dε_s implicit; returns its residual.
  double correct_volume_fraction(run::FlowState& state, const run::FlowState& old, double dt);
  // Damps a compressing correction ε' where the closure's P_s departs from its linearization.
  void limit_compression(const run::FlowState& state, std::vector<double>& correction);
  // After convergence: ε_s from the converged fluxes in conservative form; ε_g = 1 − ε_s.
  void conserve_solids(run::FlowState& state, const run::FlowState& old, double dt);
  void update_gas_fraction(run::FlowState& state) const;

  // The velocity residuals are measured against: the largest face velocity in the domain, but at
  // least 1e-3 of the problem's reference speed (the fastest wall or inflow, or sqrt(|g| L)), so
  // that a fluid at rest is judged against a meaningful scale rather than round-off.
  double residual_velocity_scale(const run::FlowState& state) const;

  // ε of a phase on the face of `local` in the + direction d, linear between the two centres.
  double face_fraction(const run::FlowState& state, Phase phase, int local, int d) const;
  // ε of a phase carried through that face: the gas's linear value; the solids' upwind value.
  double flux_fraction(const run::FlowState& state, Phase phase, int local, int d) const;
  // Whether the solids momentum at this face is solved (ε_s above the threshold beside it).
  bool solids_present(const run::FlowState& state, int local, int d) const;
  void record_worst(int equation, double row_residual, int local);
  // c_w [Pa s/m] of a partial-slip solids wall across `link` from the tangential velocity d of
  // cell l; e the wall-normal direction, δ the wall distance (solids_wall.cpp).
  double solids_wall_coefficient(const run::FlowState& state, const Link& link, int l, int d,
                                 int e, double wall_distance) const;

  double width(int local, int d) const { return m_width[static_cast<std::size_t>(local) * 3 + static_cast<std::size_t>(d)]; }
  double face_area(int local, int d) const;  // area of the cell's face normal to d
  double density(Phase phase) const;
  const VelocityFaces& faces(Phase phase) const { return *m_faces[phase]; }

  const deck::Deck& m_deck;
  const parallel::Domain& m_domain;
  std::array<std::unique_ptr<VelocityFaces>, 2> m_faces;  // gas, solids (inflow values differ)
  std::array<bool, 2> m_moves{false, false};  // whether each phase's momentum is solved
  Limiter m_limiter;
  bool m_simplec;
  ResidualNormalization m_residual_normalization;
  double m_bulk_viscosity_ratio;  // numerics.solids_bulk_viscosity_ratio: λ_s = r μ_s
  std::vector<double> m_width;  // 3 per local cell
  std::array<std::unique_ptr<UnknownNumbering>, 3> m_velocity_numbering;
  std::array<std::array<std::unique_ptr<LinearSystem>, 3>, 2> m_momentum_system;  // [phase][d]
  std::unique_ptr<UnknownNumbering> m_pressure_numbering;
  std::unique_ptr<LinearSystem> m_pressure_system;
  std::unique_ptr<LinearSystem> m_fraction_system;
  // Velocity responses of each unknown face: u_m += d_m (p'_c − p'_n), u_s += e (ε'_c − ε'_n).
  std::array<std::array<std::vector<double>, 3>, 2> m_d;  // [phase][d]
  std::array<std::vector<double>, 3> m_e;
  std::array<std::vector<double>, 3> m_source;  // optional gas momentum sources [N/m³]
  std::array<double, equation_count> m_worst_value{};  // largest row residual per equation
  std::array<int, equation_count> m_worst_local{};     // and its local cell
  std::unique_ptr<models::DragLaw> m_drag;                  // null without moving phases to couple
  std::unique_ptr<models::SolidsStressModel> m_stress;      // null unless the solids move
  std::unique_ptr<SolidsWalls> m_solids_walls;              // null unless the solids move
  // Partial-slip wall coefficients c_w per (component d, 6 × local + face), evaluated on the
  // first outer iteration of a step and held for the rest of it: the slip laws switch steeply
  // near yield (η ≈ η_s), and re-evaluating them every iteration made the iterations cycle.
  std::array<std::vector<double>, 3> m_wall_coefficients;
  int m_outer_iteration = 0;
  std::vector<double> m_stepped_solids_flux;  // set by conserve_solids
  std::vector<double> m_beta;                      // β [kg/(m³ s)] per local cell
  std::array<std::vector<double>, 2> m_viscosity;  // ε_g μ_g and μ_s [Pa s] per local cell
  std::vector<double> m_pressure_derivative;       // dP_s/dε_s [Pa] per local cell
  std::vector<double> m_strain_rate, m_divergence; // scratch for the closure
  std::vector<bool> m_no_slip_strain_regions;      // per region: its wall shear enters γ̇
  double m_reference_speed = 1.0;  // [m/s]
  double m_gravity = 0.0;          // |g| [m/s²]
  double m_velocity_scale = 1.0;   // residual_velocity_scale of the iterate, at most 10× the step start's
  double m_reference_area = 0.0;   // Σ_cells ½ Σ_faces A [m²]
};

// Below this ε_s on both sides of a face the solids momentum there is not solved (u_s = 0).
inline constexpr double solids_threshold = 1e-6;

}  // namespace bagnold::solver
