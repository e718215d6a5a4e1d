#pragma once
// The part of the deck the outer iteration reads, resolved once: which phases move, their
// densities, gravity, the iteration's controls and the reference speed residuals are judged
// against. Each step takes what it needs from here, not from the deck.

#include <array>

#include "solver/convection_limiter.hpp"
#include "solver/simple/momentum_residual.hpp"
#include "src/deck/deck.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::solver {

struct SolverSettings {
  SolverSettings(const deck::Deck& deck, const parallel::Domain& domain);

  std::array<bool, 2> moves{false, false};  // whether each phase's momentum is solved
  bool drag = false;                        // both phases present: β couples them
  std::array<double, 2> density{0.0, 0.0};  // ρ_g, ρ_s [kg/m³]
  std::array<double, 3> gravity{0, 0, 0};   // g [m/s²]
  double gravity_magnitude = 0.0;           // |g| [m/s²]
  // The fastest boundary velocity, or the free-fall speed sqrt(|g| L) over the domain [m/s].
  double reference_speed = 1.0;
  double extent = 1.0;  // the domain's largest extent [m]
  // The least velocity residuals are judged against [m/s], 1e-3 of the reference speed: a fluid
  // at rest is then measured against a small velocity change, not against round-off.
  double least_speed = 1e-3;
  // The least acceleration a "force" momentum residual is judged against [m/s²]: 1e-3 of
  // U²/L (U the reference speed, L the domain's largest extent), which is 1e-3 |g| when gravity
  // sets U. A row on which nothing acts is then measured against ε ρ V times it.
  double least_acceleration = 1e-3;

  double tolerance = 1e-4;  // numerics.tolerance
  int max_outer_iterations = 40;
  bool detect_stall = false;  // numerics.detect_stall: StallWatch (step_record.hpp)
  int anderson_depth = 0;  // numerics.anderson_depth: 0 Picard
  double relax_velocity = 0.7;  // α_u
  double relax_pressure = 1.0;  // α_p
  bool simplec = true;
  Limiter limiter = Limiter::superbee;
  ResidualNormalization residual_normalization = ResidualNormalization::velocity_scale;
  bool net_force_residual = false;
  deck::ViscosityAverage viscosity_average = deck::ViscosityAverage::arithmetic;
  bool shear_on_opening_faces = true;  // numerics.shear_on_opening_faces
  bool copy_fluxes_into_openings = false;  // numerics.copy_fluxes_into_openings
  deck::ViscosityLinearization viscosity_linearization = deck::ViscosityLinearization::picard;
  bool coupled_solids_momentum = false;  // numerics.solids_momentum = "coupled"
  deck::StepSolver step_solver = deck::StepSolver::outer_iteration;  // numerics.step_solver
  bool stress_velocity = true;  // numerics.newton_linearization = "stress-velocity"
  double vacant_fraction = 1e-8;  // numerics.vacant_fraction: Θ = 0 at or below this ε_s
};

}  // namespace bagnold::solver
