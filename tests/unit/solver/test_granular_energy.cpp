// The granular energy equation (granular_energy_equation.hpp) against analytic solutions, with
// mfix-default's transported Θ (MFIX's LUN_1984, lun_granular_energy.hpp), on 1 and 2 ranks:
//  - homogeneous cooling: a periodic box at rest cools as Haff's law Θ = Θ₀/(1 + t/t₀)²,
//    t₀ = 3 ρ_s φ/(c √Θ₀) from (3/2) ρ_s φ dΘ/dt = −c Θ^{3/2}; implicit Euler's error falls as dt;
//  - simple shear at steady state: production μ_s γ̇² = dissipation c Θ^{3/2} (no gas: μ_s ∝ √Θ)
//    gives Θ = (μ_s/√Θ) γ̇²/c, recovered to round-off at every φ below packing;
//  - Θ ≥ 0 without a clamp under a compressing, shearing random flow;
//  - Johnson–Jackson walls: a plug sliding between two of them settles where the walls'
//    generation A√Θ − loss BΘ^{3/2} on both faces balances the bulk dissipation c Θ^{3/2} V.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "models/stress/lun_granular_energy.hpp"
#include "models/wall/johnson_jackson.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/flow_solver.hpp"
#include "solver/simple/granular_energy_equation.hpp"
#include "src/run/initial_state.hpp"
#include "tests/support/petsc_environment.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

// The closures with a transported Θ: mfix-default (Lun et al., MFIX's LUN_1984) and skt
// (Garzó–Dufty).
const std::vector<std::string> closures_with_transport = {"mfix-default", "skt"};
std::string transport_section(const std::string& closure) {
  return closure == "mfix-default"
             ? "[models.solids_stress.mfix-default]\npacked_gas_fraction = 0.42\n"
               "kinetic_theory = \"lun\"\ngranular_energy = \"transport\"\n"
             : "[models.solids_stress." + closure + "]\ngranular_energy = \"transport\"\n"
               "dilute_stress = \"kinetic\"\n";  // the algebraic form as printed (SteadySimpleShear…)
}

// The closure with its Θ transported, solids in vacuum, a periodic box at rest.
std::string transported(double fraction, double temperature, const std::string& closure = "mfix-default") {
  return unit_deck(3, 3, 3, "\"x\", \"y\", \"z\"", 0.0,
                   two_fluid(closure, false) + transport_section(closure) + tight_linear_solves +
                       "tolerance = 1e-10\nmax_outer_iterations = 50\n"
                       "[[initial]]\nsolids_fraction = " + std::to_string(fraction) +
                       "\ngranular_temperature = " + std::to_string(temperature) + "\n");
}

double owned_mean_temperature(const Case& c, const run::FlowState& s) {
  double total = 0.0;
  for (int l = 0; l < c.owned_fluid(); ++l) total += s.granular_temperature[static_cast<std::size_t>(l)];
  return c.sum(total) / c.sum(static_cast<double>(c.owned_fluid()));
}

// The theory's terms at one point without gas: {μ_s/√Θ, c} (Γ = c Θ^{3/2}).
std::array<double, 2> unit_terms(const models::GranularEnergyTheory& theory, const models::Material& m,
                                 double phi) {
  std::vector<double> fraction{phi}, temperature{1.0}, zero{0.0};
  std::vector<double> p(1), mu(1), lambda(1), kappa(1), c(1), slip(1), held(1);
  models::KineticTerms out{p, mu, lambda, kappa, c, slip, held};
  theory.evaluate(m, {fraction, temperature, zero, zero, 0.0}, out);
  return {mu[0], c[0]};
}

// `steps` pseudo-time steps of 1 s of the equation alone, each from the last: its steady state.
bool settle(Case& c, solver::GranularEnergyEquation& equation, const solver::ClosureFields& fields,
            const solver::CarriedFractions& carried, int steps) {
  for (int k = 0; k < steps; ++k) {
    c.old = c.state;
    solver::IterationSums sums;
    solver::WorstCells worst;
    solver::StepResult record;
    if (!equation.solve(c.old, 1.0, fields, carried, c.state, sums, worst, record)) {
      ADD_FAILURE() << record.failure;
      return false;
    }
  }
  return true;
}

// Θ(2 t₀)/Θ_Haff − 1 after steps of t₀/steps_per_t0.
double haff_error(int steps_per_t0, const std::string& closure) {
  const double phi = 0.3, theta0 = 1e-2;
  Case c(transported(phi, theta0, closure));
  solver::FlowSolver flow(c.deck, c.domain);
  run::set_initial_state(c.deck, c.domain, c.state);
  flow.apply_boundary_values(c.state);
  const solver::Closures closures(c.deck, c.disc);
  const double dissipation = unit_terms(*closures.stress()->granular_energy(), c.deck.solids.material, phi)[1];
  const double t0 = 3.0 * c.deck.solids.material.density * phi / (dissipation * std::sqrt(theta0));
  const double dt = t0 / steps_per_t0;
  for (int step = 0; step < 2 * steps_per_t0; ++step) {
    c.old = c.state;
    const auto result = flow.advance(c.state, c.old, dt);
    EXPECT_TRUE(result.converged) << result.failure;
    if (!result.converged) return INFINITY;
  }
  const double haff = theta0 / 9.0;  // Θ₀/(1 + 2)²
  return owned_mean_temperature(c, c.state) / haff - 1.0;
}

TEST(GranularEnergy, HomogeneousCoolingFollowsHaffsLaw) {
  for (const auto& closure : closures_with_transport) {
    const double coarse = haff_error(50, closure), fine = haff_error(100, closure);
    // Implicit Euler cools too slowly, by O(dt): 2.2 % at dt = t₀/50, and first order.
    std::printf("%s: Θ(2 t0)/Haff - 1: %.6g at dt = t0/50, %.6g at t0/100\n", closure.c_str(), coarse, fine);
    EXPECT_GT(fine, 0.0) << closure;
    EXPECT_LT(fine, 0.012) << closure;
    EXPECT_NEAR(coarse / fine, 2.0, 0.1) << closure;
  }
}

TEST(GranularEnergy, SteadySimpleShearBalancesProductionAndDissipation) {
  const double rate = 50.0;  // γ̇ [1/s]
  for (const auto& closure : closures_with_transport)
  for (const double phi : {0.02, 0.1, 0.25, 0.4, 0.5, 0.57}) {
    Case c(transported(phi, 1e-3, closure));
    run::set_initial_state(c.deck, c.domain, c.state);
    solver::Closures closures(c.deck, c.disc);
    solver::GranularEnergyEquation equation(c.disc, solver::SolverSettings(c.deck, c.domain), closures);
    solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
    std::fill(fields.strain_rate.begin(), fields.strain_rate.end(), rate);
    solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
    // Pseudo-time steps from the last iterate: the steady state is the local balance.
    ASSERT_TRUE(settle(c, equation, fields, carried, 80));
    const auto& material = c.deck.solids.material;
    const auto [shear, dissipation] = unit_terms(*closures.stress()->granular_energy(), material, phi);
    const double expected = shear * rate * rate / dissipation;
    // SKT's algebraic T (Eq. 15, its dilute limit off) is this balance: the same Θ from the
    // closure evaluated without Θ.
    if (closure == "skt") {
      std::vector<double> fraction{phi}, rates{rate}, divergence{0.0}, out(5);
      models::SolidsStress stress{{&out[0], 1}, {&out[1], 1}, {&out[2], 1}, {&out[3], 1}, {&out[4], 1}};
      closures.stress()->evaluate(material, {fraction, rates, divergence}, stress);
      EXPECT_NEAR(out[4], expected, 1e-12 * expected) << "φ = " << phi;
    }
    for (int l = 0; l < c.owned_fluid(); ++l)
      EXPECT_NEAR(c.state.granular_temperature[static_cast<std::size_t>(l)], expected, 1e-12 * expected)
          << closure << " φ = " << phi;
  }
}

TEST(GranularEnergy, StaysNonNegativeUnderACompressingShearingFlow) {
  // A random solids velocity field (strong local compression and expansion, |u| ~ 1 m/s) and
  // random fractions: every Θ ≥ 0, none clamped beyond round-off.
  Case c(transported(0.3, 1e-4));
  run::set_initial_state(c.deck, c.domain, c.state);
  for (int l = 0; l < c.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const auto x = c.centre(l);
    c.state.solids_fraction[i] = 0.3 + 0.25 * wiggle(x, 1.0);
    c.state.granular_temperature[i] = 1e-4 * (1.0 + wiggle(x, 2.0));
    for (int d = 0; d < 3; ++d) c.state.solids_velocity[static_cast<std::size_t>(d)][i] = wiggle(x, 3.0 + d);
  }
  c.old = c.state;
  solver::Closures closures(c.deck, c.disc);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
  closures.evaluate(c.disc, c.state, c.old, 1e-3, fields);
  solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
  solver::carry_all_fractions(c.disc, c.state, carried);
  solver::GranularEnergyEquation equation(c.disc, solver::SolverSettings(c.deck, c.domain), closures);
  solver::IterationSums sums;
  solver::WorstCells worst;
  solver::StepResult record;
  ASSERT_TRUE(equation.solve(c.old, 1e-3, fields, carried, c.state, sums, worst, record)) << record.failure;
  double lowest = INFINITY, highest = 0.0;
  for (int l = 0; l < c.owned_fluid(); ++l) {
    lowest = std::min(lowest, c.state.granular_temperature[static_cast<std::size_t>(l)]);
    highest = std::max(highest, c.state.granular_temperature[static_cast<std::size_t>(l)]);
  }
  EXPECT_LE(c.max(-lowest), 0.0);  // the lowest Θ on any rank is ≥ 0
  EXPECT_GT(c.max(highest), 1e-4);  // the shear heated it
  EXPECT_EQ(c.sum(sums.interventions[solver::temperature_clamped_at_zero]), 0.0);
}

TEST(GranularEnergy, JohnsonJacksonWallsHeatASlidingPlug) {
  // Two cells, periodic in x and y, Johnson–Jackson walls at z = 0 and z = 2 cm; the solids
  // slide along x at 0.2 m/s with no shear inside. By symmetry nothing is conducted between
  // the two: in each, V c Θ^{3/2} = A (gain √Θ − loss Θ^{3/2}).
  const std::string walls =
      "[[boundary]]\nname = \"floor\"\ntype = \"no_slip_wall\"\nface = \"z-\"\n"
      "solids_wall = \"johnson-jackson\"\nspecularity = 0.5\nwall_restitution = 0.9\n"
      "[[boundary]]\nname = \"roof\"\ntype = \"no_slip_wall\"\nface = \"z+\"\n"
      "solids_wall = \"johnson-jackson\"\nspecularity = 0.5\nwall_restitution = 0.9\n";
  const double phi = 0.3, speed = 0.2;
  Case c(unit_deck(1, 1, 2, "\"x\", \"y\"", 0.0,
                   walls + two_fluid("mfix-default", false) +
                       "[models.solids_stress.mfix-default]\npacked_gas_fraction = 0.42\n"
                       "kinetic_theory = \"lun\"\ngranular_energy = \"transport\"\n" +
                       tight_linear_solves + "[[initial]]\nsolids_fraction = 0.3\n"
                       "granular_temperature = 1e-4\nsolids_velocity = [0.2, 0.0, 0.0]\n"));
  run::set_initial_state(c.deck, c.domain, c.state);
  solver::Closures closures(c.deck, c.disc);
  solver::GranularEnergyEquation equation(c.disc, solver::SolverSettings(c.deck, c.domain), closures);
  solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));  // no shear
  solver::CarriedFractions carried(static_cast<std::size_t>(c.local_count()));
  ASSERT_TRUE(settle(c, equation, fields, carried, 100));
  const auto& m = c.deck.solids.material;
  const auto* closure = closures.stress();
  const models::wall::JohnsonJacksonWall wall{0.5, 0.9, closure->packing_limit(m)};
  const double g0 = closure->wall_radial_distribution(m, phi);
  const double loss = -models::wall::johnson_jackson_energy_flux(wall, m, phi, g0, 1.0, 0.0);
  const double gain = models::wall::johnson_jackson_energy_flux(wall, m, phi, g0, 1.0, speed) + loss;
  const double dissipation = unit_terms(*closure->granular_energy(), m, phi)[1];
  const double area = 1e-4, volume = 1e-6;  // the 1 cm cell
  // Divided by √Θ:
  const double expected = area * gain / (volume * dissipation + area * loss);
  ASSERT_GT(gain, 0.0);
  for (int l = 0; l < c.owned_fluid(); ++l)
    EXPECT_NEAR(c.state.granular_temperature[static_cast<std::size_t>(l)], expected, 1e-12 * expected);
}

// numerics.vacant_fraction: a cell with ε_s at or below it holds no solids and its Θ is 0;
// above it the same cell keeps its fluctuation energy and cools.
TEST(GranularEnergy, CellsAtOrBelowTheVacantFractionHoldNoTemperature) {
  auto mean_temperature_after_a_step = [](const std::string& vacant) {
    Case c(unit_deck(3, 3, 3, "\"x\", \"y\", \"z\"", 0.0,
                     two_fluid("mfix-default", false) + transport_section("mfix-default") +
                         tight_linear_solves + "tolerance = 1e-10\nmax_outer_iterations = 50\n" +
                         vacant + "[[initial]]\nsolids_fraction = 5e-9\ngranular_temperature = 0.01\n"));
    solver::FlowSolver flow(c.deck, c.domain);
    run::set_initial_state(c.deck, c.domain, c.state);
    flow.apply_boundary_values(c.state);
    c.old = c.state;
    const auto result = flow.advance(c.state, c.old, 1e-4);
    EXPECT_TRUE(result.converged) << result.failure;
    return owned_mean_temperature(c, c.state);
  };
  EXPECT_EQ(mean_temperature_after_a_step(""), 0.0);  // the default, 1e-8
  const double kept = mean_temperature_after_a_step("vacant_fraction = 1e-9\n");
  EXPECT_GT(kept, 0.0099);
  EXPECT_LE(kept, 0.01);
}

}  // namespace
}  // namespace bagnold::tests
