#pragma once
// The incompressible gas solver on the staggered grid: SIMPLE outer iterations within an
// implicit-Euler time step (DESIGN.md, "Equations and algorithm", steps 2, 3 and 5). The gas
// occupies the fraction ε_g of each cell and feels the solids through drag (as MFIX's gas phase):
//   ∂(ε_g ρ_g u)/∂t + ∇·(ε_g ρ_g u u) = −ε_g ∇P + ∇·(ε_g μ_g ∇u) + ε_g ρ_g g − β (u − u_s),
//   ∇·(ε_g ρ_g u) = 0  (ε_g frozen: solids.momentum = false, or no solids: ε_g = 1, β = 0).
// The two-fluid solver (issue 4) adds the solids momentum and the volume-fraction correction.
//
// One time step (advance.cpp):
//   repeat until every normalized residual < numerics.tolerance:
//     1. momentum predictor for U, V, W (momentum_predictor.cpp): upwind implicit, TVD by
//        deferred correction, central diffusion, under-relaxed; gives u* and d = A / a_P;
//     2. pressure correction (pressure_correction.cpp): Σ_faces ρ A d (p'_P − p'_nb) = −Σ ρ A u*,
//        solved with CG + algebraic multigrid; P += α_p p', u = u* + d (p'_P − p'_N).

#include <array>
#include <memory>
#include <vector>

#include "solver/convection_limiter.hpp"
#include "solver/petsc/linear_system.hpp"
#include "solver/unknown_numbering.hpp"
#include "models/drag/drag_law.hpp"
#include "solver/velocity_faces.hpp"
#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

struct Residuals {
  std::array<double, 3> momentum{0, 0, 0};  // normalized, per direction
  double continuity = 0.0;                  // normalized mass imbalance
  double largest() const;
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

class GasSolver {
 public:
  GasSolver(const deck::Deck& deck, const parallel::Domain& domain);

  // Sets the boundary values every stencil reads: given face velocities, boundary pressures.
  void apply_boundary_values(run::FlowState& state) const;
  // Advances `state` (holding the last iterate, initially `old`) by one time step dt.
  StepResult advance(run::FlowState& state, const run::FlowState& old, double dt);

  // An extra momentum source [N/m³] at each face velocity of direction d (local_count()
  // entries, indexed by the owning cell), e.g. a manufactured solution's forcing. Empty: none.
  void set_momentum_source(int d, std::vector<double> source) {
    m_source[static_cast<std::size_t>(d)] = std::move(source);
  }

  // Collective: the cell with the largest residual of equation e (0–2 momentum x–z, 3
  // continuity) in the last outer iteration.
  CellLocation worst_cell(int equation) const;

  // Net mass flux [kg/s] out through each boundary region (monitor).
  std::vector<double> boundary_mass_flux(const run::FlowState& state) const;

 private:
  // Step 1: assembles and solves one momentum component; returns its normalized residual.
  double predict_momentum(int d, run::FlowState& state, const run::FlowState& old, double dt);
  // Step 2: solves the pressure correction, corrects P and u; returns the continuity residual.
  double correct_pressure(run::FlowState& state);

  // The velocity residuals are measured against: the largest face velocity in the domain, but at
  // least 1e-3 of the problem's reference speed (the fastest wall or inflow, or sqrt(|g| L)), so
  // that a fluid at rest is judged against a meaningful scale rather than round-off.
  double residual_velocity_scale(const run::FlowState& state) const;

  // ε_g on the face of `local` in the + direction d (linear between the two cell centres).
  double face_fraction(const run::FlowState& state, int local, int d) const;
  // Step 0 of an outer iteration: the drag coefficient β at cell centres from the current
  // velocities (nothing without solids).
  void evaluate_drag(const run::FlowState& state);

  double width(int local, int d) const { return m_width[static_cast<std::size_t>(local) * 3 + static_cast<std::size_t>(d)]; }
  double face_area(int local, int d) const;  // area of the cell's face normal to d

  const deck::Deck& m_deck;
  const parallel::Domain& m_domain;
  VelocityFaces m_faces;
  Limiter m_limiter;
  bool m_simplec;
  std::vector<double> m_width;  // 3 per local cell
  std::array<std::unique_ptr<UnknownNumbering>, 3> m_velocity_numbering;
  std::unique_ptr<UnknownNumbering> m_pressure_numbering;
  std::array<std::unique_ptr<LinearSystem>, 3> m_momentum_system;
  std::unique_ptr<LinearSystem> m_pressure_system;
  std::array<std::vector<double>, 3> m_d;  // d = A / a_P (relaxed) of each unknown face velocity
  std::array<std::vector<double>, 3> m_source;  // optional momentum sources [N/m³]
  std::array<double, 4> m_worst_value{0, 0, 0, 0};  // largest row residual per equation
  std::array<int, 4> m_worst_local{-1, -1, -1, -1};  // and its local cell
  std::unique_ptr<models::DragLaw> m_drag;  // null without solids
  std::vector<double> m_beta;                // β [kg/(m³ s)] per local cell
  double m_reference_speed = 1.0;  // [m/s]
  double m_velocity_scale = 1.0;   // residual_velocity_scale of the current outer iteration
  double m_reference_flux = 0.0;   // [kg/(s (m/s))]: ρ Σ_cells ½ Σ_faces A, per unit speed
};

}  // namespace bagnold::solver
