// FlowSolver::advance, the driver of one time step (flow_solver.hpp, advance.cpp): a fluid at
// rest stays at rest and converges at once; a moving two-phase flow keeps its solids inventory
// to round-off; a linear solve that fails makes the step fail with the reason. On 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>

#include "solver/simple/flow_solver.hpp"
#include "solver/simple/row_location.hpp"
#include "solver/simple/row_trace.hpp"
#include "src/run/initial_state.hpp"
#include "tests/support/petsc_environment.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::petsc_check;

const std::string& tight = tight_linear_solves;

// The deck's initial state with its boundary values, as `bagnold run` starts.
struct Stepper {
  explicit Stepper(const std::string& text, const std::vector<std::string>& overrides = {})
      : c(text, overrides), flow(c.deck, c.domain) {
    run::set_initial_state(c.deck, c.domain, c.state);
    flow.apply_boundary_values(c.state);
    c.old = c.state;
  }
  double largest_speed() const {
    double largest = 0.0;
    for (const auto* v : {&c.state.gas_velocity, &c.state.solids_velocity})
      for (const auto& component : *v)
        for (int l = 0; l < c.layout().owned_count(); ++l) largest = std::max(largest, std::abs(component[static_cast<std::size_t>(l)]));
    return c.max(largest);
  }
  Case c;
  solver::FlowSolver flow;
};

TEST(FlowSolver, HydrostaticGasAtRestStaysAtRestInOneIteration) {
  Stepper r(unit_deck(3, 4, 5, "", -9.81, gas_only() + tight), {"grid.z.ratio=2.0"});
  const auto result = r.flow.advance(r.c.state, r.c.old, 1e-3);
  EXPECT_TRUE(result.converged);
  EXPECT_TRUE(result.failure.empty());
  EXPECT_LE(result.iterations, 2);
  // The hydrostatic rows balance to round-off (test_momentum): velocities of ~1e-11 m/s.
  EXPECT_LT(r.largest_speed(), 1e-9);
  for (int l = 0; l < r.c.owned_fluid(); ++l)
    EXPECT_NEAR(r.c.state.gas_pressure[static_cast<std::size_t>(l)], r.c.old.gas_pressure[static_cast<std::size_t>(l)], 1e-6);
}

TEST(FlowSolver, TwoPhaseMixtureAtRestStaysAtRest) {
  // No gravity, ε_s = 0.3 below and 0.1 above: nothing drives a flow.
  Stepper r(unit_deck(3, 3, 4, "\"x\"", 0.0,
                  two_fluid() + tight + "[[initial]]\nsolids_fraction = 0.1\n"
                                        "[[initial]]\nmax = [1.0, 1.0, 0.02]\nsolids_fraction = 0.3\n"));
  const auto result = r.flow.advance(r.c.state, r.c.old, 1e-3);
  EXPECT_TRUE(result.converged) << result.failure;
  EXPECT_LE(result.iterations, 2);
  EXPECT_LT(r.largest_speed(), 1e-12);
  for (int l = 0; l < r.c.owned_fluid(); ++l)
    EXPECT_EQ(r.c.state.solids_fraction[static_cast<std::size_t>(l)], r.c.old.solids_fraction[static_cast<std::size_t>(l)]);
}

TEST(FlowSolver, AMovingTwoPhaseStepKeepsTheSolidsInventory) {
  // A closed box (no gravity), the solids moving up at 2 cm/s in the lower half at t = 0: the
  // step converges and conserve_solids keeps Σ ε_s V to round-off.
  Stepper r(unit_deck(3, 3, 6, "\"x\", \"y\"", 0.0,
                  two_fluid() + tight + "tolerance = 1e-6\nmax_outer_iterations = 100\n"
                                        "[[initial]]\nsolids_fraction = 0.2\n"
                                        "[[initial]]\nmax = [1.0, 1.0, 0.03]\nsolids_fraction = 0.3\n"
                                        "solids_velocity = [0.0, 0.0, 0.02]\n"));
  const double before = r.c.solids_volume(r.c.state);
  const auto result = r.flow.advance(r.c.state, r.c.old, 1e-3);
  ASSERT_TRUE(result.converged) << result.failure << " after " << result.iterations;
  EXPECT_GT(r.largest_speed(), 1e-4);  // it moved
  // Each face's flux enters its two cells with opposite signs: round-off of a sum of 54 cells.
  EXPECT_NEAR(r.c.solids_volume(r.c.state), before, 1e-13 * before);
  EXPECT_GT(result.linear_iterations[solver::momentum_systems], 0.0);
  EXPECT_GT(result.linear_iterations[solver::pressure_system], 0.0);
  EXPECT_GT(result.linear_iterations[solver::fraction_system], 0.0);
  EXPECT_LT(result.residuals.largest(), 1e-6);
  // Closed: nothing crosses a boundary.
  for (const double f : r.flow.stepped_solids_flux(r.c.state)) EXPECT_EQ(f, 0.0);
}

TEST(FlowSolver, TheMfixTestJudgesTheSumWithContinuityAgainstTheFirstIteration) {
  // numerics.residual_normalization = "mfix" (MFIX's CHECK_CONVERGENCE): the first outer
  // iteration's continuity imbalance is the reference, so that iteration cannot end the step,
  // and the step ends when the sum of all residuals is within the tolerance.
  Stepper r(unit_deck(3, 3, 6, "\"x\", \"y\"", 0.0,
                  two_fluid() + tight + "tolerance = 1e-3\nresidual_normalization = \"mfix\"\n"
                                        "[[initial]]\nsolids_fraction = 0.2\n"
                                        "[[initial]]\nmax = [1.0, 1.0, 0.03]\nsolids_fraction = 0.3\n"
                                        "solids_velocity = [0.0, 0.0, 0.02]\n"));
  const auto result = r.flow.advance(r.c.state, r.c.old, 1e-3);
  ASSERT_TRUE(result.converged) << result.failure << " after " << result.iterations;
  EXPECT_GE(result.iterations, 2);
  double sum = 0.0;
  for (int e = 0; e <= solver::solids_continuity; ++e) sum += result.residuals.value[static_cast<std::size_t>(e)];
  EXPECT_LE(sum, 1e-3);
  EXPECT_DOUBLE_EQ(result.judged, sum);  // what the step was judged by, for the run log
  EXPECT_GT(result.residuals.value[solver::mixture_continuity] + result.residuals.value[solver::solids_continuity], 0.0);
}

TEST(FlowSolver, TheSteppedSolidsFluxBalancesTheInventoryOfAnOpenColumn) {
  // A fed column (ε_s = 0.3 coming in at 5 cm/s into 0.1, a pressure outlet at the top), a loose
  // outer tolerance so that the converged iterate still carries a visible continuity residual:
  // conserve_solids makes Σ ε_s V change by exactly −dt Σ (the fluxes it stepped with)/ρ_s.
  const std::string feed =
      "[[boundary]]\nname = \"feed\"\ntype = \"mass_inflow\"\nface = \"z-\"\n"
      "gas_velocity = [0.0, 0.0, 0.1]\nsolids_velocity = [0.0, 0.0, 0.05]\nsolids_fraction = 0.3\n"
      "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n";
  Stepper r(unit_deck(2, 2, 6, "\"x\", \"y\"", -9.81,
                      two_fluid() + feed + tight + "tolerance = 1e-2\n[[initial]]\nsolids_fraction = 0.1\n"));
  const double dt = 1e-2;
  const double before = r.c.solids_volume(r.c.state);
  const auto result = r.flow.advance(r.c.state, r.c.old, dt);
  ASSERT_TRUE(result.converged) << result.failure;
  double net = 0.0;
  for (const double f : r.flow.stepped_solids_flux(r.c.state)) net += f;
  EXPECT_LT(net, 0.0);  // the feed brings solids in [kg/s]
  // Round-off of sums over 24 cells of ~1e-7 m³.
  EXPECT_NEAR(r.c.solids_volume(r.c.state), before - dt * net / 2500.0, 1e-13 * before);
}

TEST(FlowSolver, AFailedLinearSolveFailsTheStepWithItsReason) {
  // A lid-driven cavity from rest needs a real pressure correction; one CG iteration at a
  // relative tolerance of 1e-14 cannot give it.
  const std::string lid = "[[boundary]]\nname = \"lid\"\ntype = \"moving_wall\"\nface = \"z+\"\n"
                          "wall_velocity = [1.0, 0.0, 0.0]\n";
  // Each step's pressure KSP reads the options when the step starts: the cap holds for this
  // step and is cleared when it ends, however it ends.
  struct CappedPressureSolve {
    CappedPressureSolve() { petsc_check(PetscOptionsSetValue(nullptr, "-pressure_ksp_max_it", "1"), "PetscOptionsSetValue"); }
    ~CappedPressureSolve() { PetscOptionsClearValue(nullptr, "-pressure_ksp_max_it"); }
  };
  solver::StepResult result;
  {
    const CappedPressureSolve cap;
    Stepper r(unit_deck(4, 1, 4, "\"y\"", 0.0, gas_only() + lid + "[numerics]\npressure_tolerance = 1e-14\n"));
    result = r.flow.advance(r.c.state, r.c.old, 1e-2);
  }
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.failure.empty());
  EXPECT_NE(result.failure.find("pressure"), std::string::npos) << result.failure;
  // It stopped at the failed solve (the first whose system needs more than one CG iteration,
  // the 2nd outer iteration here), not at max_outer_iterations = 40.
  EXPECT_LE(result.iterations, 3);
  // The same deck without the cap converges.
  Stepper ok(unit_deck(4, 1, 4, "\"y\"", 0.0, gas_only() + lid + "[numerics]\npressure_tolerance = 1e-14\n"
                                                             "max_outer_iterations = 200\n"));
  const auto fine = ok.flow.advance(ok.c.state, ok.c.old, 1e-2);
  EXPECT_TRUE(fine.converged) << fine.failure;
  EXPECT_TRUE(fine.failure.empty());
}

TEST(FlowSolver, DetectStallEndsAStepWhoseResidualStopsFalling) {
  // The lid-driven cavity with an outer tolerance no iterate reaches (1e-12, below what the
  // linear solves' 1e-4 leave): the residual falls, then levels off. With numerics.detect_stall
  // the step stops there, at a multiple of 5 from 15 on (StallWatch); without it, it runs on to
  // max_outer_iterations.
  const std::string deck =
      unit_deck(4, 1, 4, "\"y\"", 0.0,
                gas_only() + "[[boundary]]\nname = \"lid\"\ntype = \"moving_wall\"\nface = \"z+\"\n"
                             "wall_velocity = [1.0, 0.0, 0.0]\n"
                             "[numerics]\ntolerance = 1e-12\nmax_outer_iterations = 400\n");
  Stepper watched(deck, {"numerics.detect_stall=true"});
  const auto stalled = watched.flow.advance(watched.c.state, watched.c.old, 1e-2);
  EXPECT_FALSE(stalled.converged);
  EXPECT_TRUE(stalled.stalled);
  EXPECT_TRUE(stalled.failure.empty());
  EXPECT_GE(stalled.iterations, 15);
  EXPECT_LT(stalled.iterations, 400);
  EXPECT_EQ(stalled.iterations % 5, 0);
  Stepper plain(deck);
  const auto ran_on = plain.flow.advance(plain.c.state, plain.c.old, 1e-2);
  EXPECT_FALSE(ran_on.converged);
  EXPECT_FALSE(ran_on.stalled);
  EXPECT_EQ(ran_on.iterations, 400);
}

TEST(FlowSolver, AFailedRowIsLocatedInAFluidCellAndItsOpeningByName) {
  // An outlet on the bottom face: its z-faces are owned by the boundary cells below the fluid.
  const std::string outlet =
      "[[boundary]]\nname = \"orifice\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n";
  const Case c(unit_deck(2, 2, 3, "", 0.0, gas_only() + outlet));
  const auto& grid = c.domain.grid;
  auto natural = [&](int i, int j, int k) { return grid.natural(grid::Index3{i, j, k}); };
  // The face below cell (1, 0, 0), owned by (1, 0, -1): the fluid cell above, its -z face.
  auto where = solver::locate_row(c.domain, solver::gas_momentum_z, natural(1, 0, -1), natural(1, 0, 0));
  EXPECT_EQ(where.cell, (grid::Index3{1, 0, 0}));
  EXPECT_EQ(where.face, "-z");
  EXPECT_EQ(where.region, "orifice");
  EXPECT_NEAR(where.position[2], 0.005, 1e-12);
  // An interior face: the owner and its + face, no region.
  where = solver::locate_row(c.domain, solver::solids_momentum_x, natural(0, 1, 2), natural(1, 1, 2));
  EXPECT_EQ(where.cell, (grid::Index3{0, 1, 2}));
  EXPECT_EQ(where.face, "+x");
  EXPECT_EQ(where.region, "");
  // The top face of the top cell: a wall beyond (the default region), named as such.
  where = solver::locate_row(c.domain, solver::gas_momentum_z, natural(0, 0, 2), natural(0, 0, 3));
  EXPECT_EQ(where.cell, (grid::Index3{0, 0, 2}));
  EXPECT_EQ(where.face, "+z");
  EXPECT_FALSE(where.region.empty());
  EXPECT_NE(where.region, "orifice");
  // A continuity row is its cell.
  where = solver::locate_row(c.domain, solver::solids_continuity, natural(1, 1, 1), -1);
  EXPECT_EQ(where.cell, (grid::Index3{1, 1, 1}));
  EXPECT_EQ(where.face, "");
  EXPECT_EQ(where.text(), "cell (1, 1, 1) at (0.015, 0.015, 0.015) m");
}

TEST(FlowSolver, RowTraceSelectsRowsAgainstTheirWeightAndNamesTheirCell) {
  const Case c(unit_deck(2, 2, 3, "", 0.0, gas_only()));
  const auto& grid = c.domain.grid;
  auto natural = [&](int i, int j, int k) { return grid.natural(grid::Index3{i, j, k}); };
  const solver::RowTrace trace(0.5);
  ASSERT_TRUE(trace.on());
  solver::RowTrace::Row row{.phase = 1, .component = 0, .owner = natural(0, 1, 2), .plus = natural(1, 1, 2),
                            .residual = -0.6, .weight = 1.0, .force = 3.0, .diagonal = 2e5,
                            .velocity = -1e-7, .sources = 80.0, .neighbours = -80.0, .viscous = 0.05};
  EXPECT_TRUE(trace.selects(row));  // |r| = 0.6 of its weight
  row.residual = 0.4;
  EXPECT_FALSE(trace.selects(row));
  row.weight = 0.0;  // no weight (no gravity): judged against its force F = 3
  row.residual = 1.6;
  EXPECT_TRUE(trace.selects(row));
  row.residual = 1.4;
  EXPECT_FALSE(trace.selects(row));
  row.weight = 1.0;
  row.residual = -0.6;
  const std::string text = trace.line(c.domain, row);
  EXPECT_EQ(text.rfind("row solids x (0, 1, 2) +x: r/w = -0.6, r = -0.6 N", 0), 0u) << text;
  EXPECT_NE(text.find("b = 80 N, sum a_nb u_nb = -80 N"), std::string::npos) << text;
  EXPECT_FALSE(solver::RowTrace(0.0).on());
  EXPECT_FALSE(solver::RowTrace(-1.0).on());
  // From the environment: a positive number, anything else off.
  ::setenv("BAGNOLD_TRACE_ROWS", "0.25", 1);
  EXPECT_TRUE(solver::RowTrace().on());
  for (const char* bad : {"", "abc", "0", "-1", "1x"}) {
    ::setenv("BAGNOLD_TRACE_ROWS", bad, 1);
    EXPECT_FALSE(solver::RowTrace().on()) << bad;
  }
  ::unsetenv("BAGNOLD_TRACE_ROWS");
  EXPECT_FALSE(solver::RowTrace().on());
}

}  // namespace
}  // namespace bagnold::tests
