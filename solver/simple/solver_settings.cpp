// The outer iteration's settings, resolved from the deck once (solver_settings.hpp).
#include "solver/simple/solver_settings.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

SolverSettings::SolverSettings(const deck::Deck& deck, const parallel::Domain& domain)
    : moves{deck.gas.enabled, deck.solids.enabled && deck.solids.momentum},
      drag(deck.solids.enabled && deck.gas.enabled),
      density{deck.gas.density, deck.solids.material.density},
      gravity(deck.physics.gravity),
      tolerance(deck.numerics.tolerance),
      max_outer_iterations(deck.numerics.max_outer_iterations),
      detect_stall(deck.numerics.detect_stall),
      anderson_depth(deck.numerics.anderson_depth),
      relax_velocity(deck.numerics.relax_velocity),
      relax_pressure(deck.numerics.relax_pressure),
      simplec(deck::choice_value(deck::coupling_choices, deck.numerics.algorithm, "algorithm") ==
              deck::Coupling::simplec),
      limiter(limiter_from_name(deck.numerics.convection)),
      residual_normalization(residual_normalization_from_name(deck.numerics.residual_normalization)),
      net_force_residual(deck.numerics.net_force_residual),
      viscosity_average(deck::choice_value(deck::viscosity_average_choices,
                                           deck.numerics.viscosity_average, "viscosity average")),
      shear_on_opening_faces(deck.numerics.shear_on_opening_faces),
      copy_fluxes_into_openings(deck.numerics.copy_fluxes_into_openings),
      viscosity_linearization(deck::choice_value(deck::viscosity_linearization_choices,
                                                 deck.numerics.viscosity_linearization,
                                                 "viscosity linearization")),
      coupled_solids_momentum(deck::choice_value(deck::solids_momentum_choices, deck.numerics.solids_momentum,
                                                 "solids momentum") == deck::SolidsMomentum::coupled),
      step_solver(deck::choice_value(deck::step_solver_choices, deck.numerics.step_solver, "step solver")),
      stress_velocity(deck::choice_value(deck::newton_linearization_choices, deck.numerics.newton_linearization,
                                         "Newton linearization") == deck::NewtonLinearization::stress_velocity),
      vacant_fraction(deck.numerics.vacant_fraction) {
  double largest = 0.0, g2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    largest = std::max(largest, domain.grid.axis(d).faces().back() - domain.grid.axis(d).faces().front());
    g2 += gravity[static_cast<std::size_t>(d)] * gravity[static_cast<std::size_t>(d)];
  }
  gravity_magnitude = std::sqrt(g2);
  extent = largest;
  reference_speed = std::sqrt(gravity_magnitude * extent);
  for (const auto& region : domain.regions.regions)
    for (int d = 0; d < 3; ++d)
      reference_speed = std::max({reference_speed, std::abs(region.wall_velocity[static_cast<std::size_t>(d)]),
                                  std::abs(region.gas_velocity[static_cast<std::size_t>(d)]),
                                  std::abs(region.solids_velocity[static_cast<std::size_t>(d)])});
  if (reference_speed <= 0.0) reference_speed = 1.0;
  least_speed = 1e-3 * reference_speed;
  least_acceleration = 1e-3 * reference_speed * reference_speed / extent;
}

}  // namespace bagnold::solver
