#pragma once
// After a step has converged: ε_s from the converged fluxes in conservative form,
//     ε_P = ε_P^old − dt/V Σ_faces A ε_up u_out,
// each face's flux computed once for both sides, so the solids mass changes only through
// boundaries, to round-off (the change to ε_s is of the size of the converged continuity
// residual); then ε_g = 1 − ε_s. And the boundary mass fluxes the monitor reports.

#include <vector>

#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "solver/simple/solver_settings.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// Net mass flux [kg/s] of a phase out through each boundary region of the domain, with
// `density` its ρ (collective).
std::vector<double> boundary_mass_flux(const Discretization& discretization,
                                       const run::FlowState& state, Phase phase, double density);

// The conservative update of ε_s and ε_g in `state` from `old` over dt, with the solids' carried
// fractions of `state`. Returns the solids mass flux per region [kg/s] through which it changed
// the inventory (collective).
std::vector<double> conserve_solids(const Discretization& discretization, const CarriedFractions& carried,
                                    double density, const run::FlowState& old, double dt,
                                    run::FlowState& state);

}  // namespace bagnold::solver
