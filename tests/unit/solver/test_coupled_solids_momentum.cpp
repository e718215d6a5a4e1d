// numerics.solids_momentum = "coupled" (coupled_solids_momentum.hpp): the three solids momentum
// components in one system, the transpose's cross part in the matrix. The equations are the
// segregated predictor's, so a step converged tightly both ways ends in the same state; and the
// coupled step is converged under the same residuals. On 1 and 2 ranks (the coupled numbering
// spans ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#include "solver/simple/closures.hpp"
#include "solver/simple/coupled_solids_momentum.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/flow_solver.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "src/run/initial_state.hpp"
#include "tests/support/petsc_environment.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

// A dense MKT bed (ε_s = 0.55) in a box with no-slip walls across y and z, periodic along x,
// sliding along x at 5 cm/s under gravity tilted along x: the walls shear it, and the cross part
// couples u_x with u_y and u_z near them.
std::string sheared_bed(const std::string& solids_momentum) {
  return unit_deck(4, 4, 6, "\"x\"", -9.81,
                   two_fluid("mkt") + tight_linear_solves +
                       "tolerance = 1e-9\nmax_outer_iterations = 400\n"
                       "solids_momentum = \"" + solids_momentum + "\"\n"
                       "[[initial]]\nsolids_fraction = 0.55\nsolids_velocity = [0.05, 0.0, 0.0]\n");
}

struct Step {
  explicit Step(const std::string& solids_momentum)
      : c(sheared_bed(solids_momentum), {"physics.gravity=[4.0, 0.0, -9.0]"}), flow(c.deck, c.domain) {
    run::set_initial_state(c.deck, c.domain, c.state);
    flow.apply_boundary_values(c.state);
    c.old = c.state;
    result = flow.advance(c.state, c.old, 2e-4);
  }
  Case c;
  solver::FlowSolver flow;
  solver::StepResult result;
};

// The solids momentum rows of a case for any velocity field, at the closures of its state
// (evaluated once): what the assembly puts in each row at fixed μ_s.
struct FixedClosures {
  explicit FixedClosures(Case& of)
      : c(of), fields(static_cast<std::size_t>(of.local_count())), carried(static_cast<std::size_t>(of.local_count())) {
    solver::Closures closures(c.deck, c.disc);
    closures.evaluate(c.disc, c.state, c.old, dt, fields);
    solver::carry_all_fractions(c.disc, c.state, carried);
  }
  std::vector<solver::MomentumRow> rows(int d, const run::FlowState& state) const {
    const solver::MomentumAssemblyInputs in{c.disc, c.settings, c.old, dt, fields, carried, no_source};
    std::vector<solver::MomentumRow> out;
    solver::MomentumAssemblyScratch scratch;
    solver::assemble_momentum_rows(in, solver::solids, d, state, nullptr, true, out, scratch);
    return out;
  }
  static constexpr double dt = 1e-3;  // [s]
  Case& c;
  solver::ClosureFields fields;
  solver::CarriedFractions carried;
  std::array<std::vector<double>, 3> no_source;
};

// The cross entries a row records are its cross part: with u_x = 0 everywhere (no convection of
// x momentum) and u_y, u_z linear in x, the x rows' b changes by exactly Σ c u_e when u_y and
// u_z are switched off at fixed closures.
TEST(CoupledSolidsMomentum, CrossEntriesAreTheRowsCrossPart) {
  Case c(unit_deck(5, 5, 5, "", 0.0, two_fluid("mkt", false)));
  const double G[3][3] = {{0.0, 0.0, 0.0}, {3.0, 0.0, 0.0}, {5.0, 0.0, 0.0}};
  set_linear_solids(c, 0.55, G);
  const FixedClosures fixed(c);
  run::FlowState still = c.state;
  for (const int e : {1, 2}) std::fill(still.solids_velocity[static_cast<std::size_t>(e)].begin(),
                                       still.solids_velocity[static_cast<std::size_t>(e)].end(), 0.0);
  const auto moving = fixed.rows(0, c.state), resting = fixed.rows(0, still);
  double worst = 0.0, size = 0.0;
  for (std::size_t r = 0; r < moving.size(); ++r) {
    double cross = 0.0;
    for (int k = 0; k < moving[r].cross_count; ++k)
      cross += moving[r].cross_coefficient[k] *
               c.state.solids_velocity[static_cast<std::size_t>(moving[r].cross_component[k])]
                                      [static_cast<std::size_t>(moving[r].cross_cell[k])];
    worst = std::max(worst, std::abs((moving[r].b - resting[r].b) - cross));
    size = std::max(size, std::abs(cross));
  }
  EXPECT_GT(c.max(size), 0.0);  // the walls make the cross part nonzero next to them
  EXPECT_LT(c.max(worst), 1e-12 * c.max(size));
}

// One solve of the coupled system satisfies every solids row with its cross part taken at the
// solution, not at the iterate: the cross entries are in the matrix, at the right columns (on
// 2 ranks, across the partition). A packed MKT bed (μ_s large) in a closed box under a velocity
// field with all nine gradients, so that the cross part is large.
TEST(CoupledSolidsMomentum, OneSolveHoldsTheRowsWithTheCrossPartAtTheSolution) {
  Case c(unit_deck(5, 4, 6, "", 0.0, two_fluid("mkt", false)));
  const double G[3][3] = {{1.0, 2.0, -3.0}, {4.0, -1.5, 2.5}, {-2.0, 3.0, 0.5}};
  set_linear_solids(c, 0.6, G);
  const FixedClosures fixed(c);
  std::array<std::vector<solver::MomentumRow>, 3> rows;
  for (int d = 0; d < 3; ++d) rows[static_cast<std::size_t>(d)] = fixed.rows(d, c.state);
  solver::KrylovSettings krylov;
  krylov.pc_type = "jacobi";
  krylov.relative_tolerance = 1e-13;
  krylov.absolute_tolerance = 1e-30;
  krylov.max_iterations = 5000;
  solver::CoupledSolidsMomentum coupled(c.disc, krylov);
  const auto iterate = c.state.solids_velocity;
  for (int d = 0; d < 3; ++d)
    for (std::size_t r = 0; r < rows[static_cast<std::size_t>(d)].size(); ++r) {
      const auto& row = rows[static_cast<std::size_t>(d)][r];
      coupled.set_row(d, r, row, row.a, row.b, iterate);
    }
  auto solution = iterate;
  ASSERT_TRUE(coupled.solve(solution).converged);
  double at_solution = 0.0, at_iterate = 0.0, scale = 0.0;
  for (int d = 0; d < 3; ++d) {
    const auto& numbering = c.disc.velocity_numbering(d);
    std::map<std::int64_t, std::size_t> local_of;
    for (int l = 0; l < c.local_count(); ++l)
      if (numbering.global[static_cast<std::size_t>(l)] >= 0) local_of[numbering.global[static_cast<std::size_t>(l)]] = static_cast<std::size_t>(l);
    const auto& u = solution[static_cast<std::size_t>(d)];
    for (std::size_t r = 0; r < rows[static_cast<std::size_t>(d)].size(); ++r) {
      const auto& row = rows[static_cast<std::size_t>(d)][r];
      double residual = row.a * u[static_cast<std::size_t>(numbering.owned_locals[r])] - row.b;
      for (int k = 0; k < row.count; ++k) residual += row.values[k] * u[local_of.at(row.columns[k])];
      double cross_change = 0.0;
      for (int k = 0; k < row.cross_count; ++k) {
        const auto e = static_cast<std::size_t>(row.cross_component[k]);
        const auto cell = static_cast<std::size_t>(row.cross_cell[k]);
        cross_change += row.cross_coefficient[k] * (solution[e][cell] - iterate[e][cell]);
      }
      at_iterate = std::max(at_iterate, std::abs(residual));
      at_solution = std::max(at_solution, std::abs(residual - cross_change));
      scale = std::max(scale, std::abs(row.b));
    }
  }
  EXPECT_LT(c.max(at_solution), 1e-9 * c.max(scale));
  EXPECT_GT(c.max(at_iterate), 1e3 * c.max(at_solution));  // the cross part matters here
}

TEST(CoupledSolidsMomentum, ConvergesToTheSegregatedStep) {
  const Step segregated("segregated"), coupled("coupled");
  ASSERT_TRUE(segregated.result.converged) << segregated.result.failure;
  ASSERT_TRUE(coupled.result.converged) << coupled.result.failure;
  double largest = 0.0, difference = 0.0, fraction = 0.0;
  for (int d = 0; d < 3; ++d)
    for (int l = 0; l < segregated.c.layout().owned_count(); ++l) {
      const auto i = static_cast<std::size_t>(l);
      const double a = segregated.c.state.solids_velocity[static_cast<std::size_t>(d)][i];
      const double b = coupled.c.state.solids_velocity[static_cast<std::size_t>(d)][i];
      largest = std::max(largest, std::abs(a));
      difference = std::max(difference, std::abs(a - b));
      fraction = std::max(fraction, std::abs(segregated.c.state.solids_fraction[i] - coupled.c.state.solids_fraction[i]));
    }
  largest = segregated.c.max(largest);
  EXPECT_GT(largest, 0.01);  // it moves
  // The same discrete equations, each converged to 1e-9: the same state to well within the
  // velocities' own size.
  EXPECT_LT(segregated.c.max(difference), 1e-6 * largest);
  EXPECT_LT(segregated.c.max(fraction), 1e-9);
  // Both made the shear and the cross coupling work: more than one outer iteration.
  EXPECT_GT(segregated.result.iterations, 1);
  EXPECT_GT(coupled.result.iterations, 1);
}

}  // namespace
}  // namespace bagnold::tests
