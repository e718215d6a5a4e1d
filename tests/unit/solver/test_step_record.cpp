// The residual bookkeeping of an outer iteration (momentum_residual.hpp, step_record.hpp): the
// three normalizations and the net-force bound on hand-made rows, IterationSums::reduce over the
// ranks, and which equation counts as the worst. On 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "solver/simple/momentum_residual.hpp"
#include "solver/simple/step_record.hpp"
#include "src/parallel/communicator.hpp"

namespace bagnold::tests {
namespace {

using solver::MomentumResidual;
using solver::ResidualNormalization;

using Row = MomentumResidual::Row;  // diagonal, L u, L1, s, transient, weight, force

double value_of(const MomentumResidual& residual, const std::vector<Row>& rows, std::vector<double>* row_residuals = nullptr) {
  MomentumResidual::Sums sums;
  for (const Row& r : rows) {
    const double each = residual.add(sums, r);
    if (row_residuals) row_residuals->push_back(each);
  }
  return residual.value(sums);
}

const std::vector<Row> two_rows = {{4.0, 1.0, 1.0, 1.5, 10.0, 0.0}, {2.0, -0.5, 2.0, -0.2, 20.0, 0.0}};

TEST(MomentumResidual, VelocityScaleNormalizesBySumOfDiagonalsTimesU) {
  const MomentumResidual residual(ResidualNormalization::velocity_scale, 0.5, 2.0, 0.01);
  std::vector<double> rows;
  // Σ|s − Lu| = 0.5 + 0.3 over Σ A U = (4 + 2) · 2. Hand arithmetic: round-off only.
  EXPECT_NEAR(value_of(residual, two_rows, &rows), 0.8 / 12.0, 1e-15);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_NEAR(rows[0], 0.5, 1e-15);
  EXPECT_NEAR(rows[1], 0.3, 1e-15);
}

TEST(MomentumResidual, DeviationNormalizesByTheForcesAboutTheMean) {
  // ū = 0.5, U_min = 0.01: Σ (|Lu − L1 ū| + |s − L1 ū| + transient U_min)
  // = (0.5 + 1.0 + 0.1) + (1.5 + 1.2 + 0.2) = 4.5.
  const MomentumResidual residual(ResidualNormalization::deviation, 0.5, 2.0, 0.01);
  EXPECT_NEAR(value_of(residual, two_rows), 0.8 / 4.5, 1e-15);
  // A large viscosity adds to L u and L1 alike: a row of a uniform field (u = ū everywhere)
  // with an unbalanced force keeps its residual against that force, not against A U.
  const std::vector<Row> viscous = {{1e6, 1e6 * 0.5, 1e6, 1e6 * 0.5 + 1.0, 10.0, 0.0}};
  EXPECT_GT(value_of(residual, viscous), 0.5);  // 1 / (0 + 1 + 0.1)
  const MomentumResidual scale(ResidualNormalization::velocity_scale, 0.5, 2.0, 0.01);
  EXPECT_LT(value_of(scale, viscous), 1e-6);  // what the velocity scale hides
  // The triangle inequality bounds the deviation residual by 1 for any rows.
  std::vector<Row> any;
  for (int i = 0; i < 50; ++i) any.push_back({1.0 + i, std::sin(i), 0.5 + std::cos(i), std::sin(3.0 * i), 0.0, 0.0});
  const MomentumResidual bare(ResidualNormalization::deviation, 0.3, 1.0, 0.0);
  EXPECT_LE(value_of(bare, any), 1.0 + 1e-15);
}

TEST(MomentumResidual, ForceNormalizesByTheForcesThatAct) {
  // Σ F = 3 + 0.9, whatever the transient parts (a short step loosens nothing).
  const std::vector<Row> rows = {{4.0, 1.0, 1.0, 1.5, 10.0, 0.0, 3.0}, {2.0, -0.5, 2.0, -0.2, 20.0, 0.0, 0.9}};
  const MomentumResidual residual(ResidualNormalization::force, 0.5, 2.0, 0.01);
  EXPECT_NEAR(value_of(residual, rows), 0.8 / 3.9, 1e-15);
  // A row of a plug in a viscous layer (μ_s A/δ = 1e6 on each side, u = 1 everywhere) whose
  // iterate leaves 1 % of its weight W = 2 N unbalanced (a 1 % wrong acceleration): the
  // neighbours cancel, so the residual is 1e-2 against the weight, whatever the viscosity or dt
  // (transient 2e3 = W/(g dt) at dt = 1e-4 s). The velocity scale calls it 1e-8.
  const double a = 2e6 + 2e3, W = 2.0;
  const std::vector<Row> plug = {{a, a * 1.0 - 2e6, 2e3, 2e3 * 1.0 - 0.01 * W, 2e3, W, W}};
  EXPECT_NEAR(value_of(MomentumResidual(ResidualNormalization::force, 1.0, 1.0, 0.0), plug), 0.01, 1e-12);
  EXPECT_LT(value_of(MomentumResidual(ResidualNormalization::velocity_scale, 1.0, 1.0, 0.0), plug), 1e-7);
  // Nothing acts and nothing is left: zero, not 0/0.
  EXPECT_EQ(value_of(residual, {{1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0}}), 0.0);
}

TEST(MomentumResidual, ForceBalanceIsTheForceNormsResidualUnderEveryNorm) {
  // The plug row above: 1 % of its weight unbalanced. Every norm's sums give the force norm's
  // 1e-2 through force_balance, while their own value() differs (the velocity scale's 1e-8).
  const double a = 2e6 + 2e3, W = 2.0;
  Row plug{a, a * 1.0 - 2e6, 2e3, 2e3 * 1.0 - 0.01 * W, 2e3, W, W};
  for (const auto kind : {ResidualNormalization::velocity_scale, ResidualNormalization::deviation,
                          ResidualNormalization::force, ResidualNormalization::mfix}) {
    MomentumResidual::Sums sums;
    MomentumResidual(kind, 1.0, 1.0, 0.0).add(sums, plug);
    EXPECT_NEAR(MomentumResidual::force_balance(sums), 0.01, 1e-12);
  }
  // Rows "mfix" leaves out of its own sums still count: a row at rest carrying its whole weight
  // unbalanced doubles the residual over twice the force.
  Row at_rest{a, 0.0, 2e3, W, 2e3, W, W};
  at_rest.mfix_counted = false;
  MomentumResidual::Sums sums;
  const MomentumResidual mfix(ResidualNormalization::mfix, 1.0, 1.0, 0.0);
  mfix.add(sums, plug);
  mfix.add(sums, at_rest);
  EXPECT_NEAR(MomentumResidual::force_balance(sums), (0.01 * W + W) / (2.0 * W), 1e-12);
  EXPECT_EQ(MomentumResidual::force_balance(MomentumResidual::Sums{}), 0.0);  // nothing: 0, not 0/0
  // MFIX's residual carries the other phase's through the drag's elimination; the force balance
  // does not: a row balanced on its own with (βV/A_o) r_o = 0.5 W is unbalanced only for "mfix".
  Row coupled = plug;
  coupled.source += 0.01 * W;  // balanced: s = L u
  coupled.mfix_coupling = 0.5 * W;
  MomentumResidual::Sums mfix_sums;
  EXPECT_NEAR(mfix.add(mfix_sums, coupled), 0.5 * W, 1e-9);
  EXPECT_NEAR(MomentumResidual::force_balance(mfix_sums), 0.0, 1e-12);
}

TEST(MomentumResidual, MfixNormalizesByDiagonalTimesSpeedOverTheRowsItCounts) {
  // MFIX's CALC_RESID_U: Σ|s − Lu| over Σ |A_e| |u| of the counted rows; a row MFIX skips (at
  // rest, or dilute solids) is in neither sum, however large its residual.
  std::vector<Row> rows = two_rows;
  rows[0].mfix_scale = 3.0;
  rows[1].mfix_scale = 5.0;
  const MomentumResidual residual(ResidualNormalization::mfix, 0.5, 2.0, 0.01);
  EXPECT_NEAR(value_of(residual, rows), 0.8 / 8.0, 1e-15);
  Row skipped{1.0, 0.0, 1.0, 100.0, 0.0, 0.0};
  skipped.mfix_counted = false;
  rows.push_back(skipped);
  std::vector<double> each;
  EXPECT_NEAR(value_of(residual, rows, &each), 0.8 / 8.0, 1e-15);
  EXPECT_EQ(each.back(), 0.0);
}

TEST(MomentumResidual, NetForceMakesTheValueAtLeastTheNetOverTheWeight) {
  // Three rows each leaving +0.1 N, each weighing 0.2 N, against huge diagonals: the sum of
  // magnitudes is negligible against Σ A U, the net force is half the weight.
  const std::vector<Row> same_sign = {{1e6, 0.0, 1.0, 0.1, 0.0, 0.2}, {1e6, 0.0, 1.0, 0.1, 0.0, 0.2},
                                      {1e6, 0.0, 1.0, 0.1, 0.0, 0.2}};
  const MomentumResidual checked(ResidualNormalization::velocity_scale, 0.0, 1.0, 0.0, true);
  const MomentumResidual unchecked(ResidualNormalization::velocity_scale, 0.0, 1.0, 0.0, false);
  EXPECT_NEAR(value_of(checked, same_sign), 0.3 / 0.6, 1e-15);
  EXPECT_NEAR(value_of(unchecked, same_sign), 0.3 / 3e6, 1e-20);
  // Residuals that cancel leave no net force: the value is the normalized one.
  const std::vector<Row> cancelling = {{1e6, 0.0, 1.0, 0.1, 0.0, 0.2}, {1e6, 0.0, 1.0, -0.1, 0.0, 0.2}};
  EXPECT_NEAR(value_of(checked, cancelling), 0.2 / 2e6, 1e-20);
  // Without weight (no gravity) there is nothing to compare the net with.
  const std::vector<Row> weightless = {{1e6, 0.0, 1.0, 0.1, 0.0, 0.0}};
  EXPECT_NEAR(value_of(checked, weightless), 0.1 / 1e6, 1e-20);
}

TEST(MomentumResidual, ZeroResidualIsZeroAndNamesAreChecked) {
  const MomentumResidual residual(ResidualNormalization::deviation, 0.0, 1.0, 0.0, true);
  const std::vector<Row> exact = {{3.0, 1.0, 2.0, 1.0, 0.0, 1.0}};
  EXPECT_EQ(value_of(residual, exact), 0.0);
  EXPECT_EQ(value_of(residual, {}), 0.0);  // no rows at all (a phase without unknowns)
  EXPECT_EQ(solver::residual_normalization_from_name("force"), ResidualNormalization::force);
  EXPECT_EQ(solver::residual_normalization_from_name("deviation"), ResidualNormalization::deviation);
  EXPECT_EQ(solver::residual_normalization_from_name("velocity-scale"), ResidualNormalization::velocity_scale);
  EXPECT_THROW(solver::residual_normalization_from_name("deviations"), std::invalid_argument);
}

TEST(IterationSums, ReduceAddsEverySumOverTheRanks) {
  const parallel::Communicator comm;
  const double weight = comm.rank() + 1.0;            // this rank's factor
  const double total = comm.size() * (comm.size() + 1) / 2.0;  // Σ over ranks of (rank + 1)
  solver::IterationSums sums;
  for (std::size_t e = 0; e < sums.momentum.size(); ++e)
    for (std::size_t j = 0; j < MomentumResidual::Sums::size; ++j) sums.momentum[e].values[j] = weight * (10.0 * e + j + 1);
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t j = 0; j < 2; ++j) sums.continuity[c][j] = weight * (100.0 + 10.0 * c + j);
  for (std::size_t i = 0; i < sums.interventions.size(); ++i) sums.interventions[i] = weight * (1000.0 + i);
  sums.normalization[0] = MomentumResidual(ResidualNormalization::velocity_scale, 0.0, 2.0, 0.0);
  sums.reduce(comm);
  // Sums of small integers: exact.
  for (std::size_t e = 0; e < sums.momentum.size(); ++e)
    for (std::size_t j = 0; j < MomentumResidual::Sums::size; ++j)
      EXPECT_EQ(sums.momentum[e].values[j], total * (10.0 * e + j + 1)) << "momentum " << e << " sum " << j;
  for (std::size_t c = 0; c < 2; ++c)
    for (std::size_t j = 0; j < 2; ++j) EXPECT_EQ(sums.continuity[c][j], total * (100.0 + 10.0 * c + j));
  for (std::size_t i = 0; i < sums.interventions.size(); ++i) EXPECT_EQ(sums.interventions[i], total * (1000.0 + i));
  // How each sum turns into a residual is not reduced; value() is Σ|R| / norm of the reduced
  // sums (total · 1 over total · 2), whatever the ranks.
  EXPECT_DOUBLE_EQ(sums.normalization[0].value(sums.momentum[0]), 0.5);
}

TEST(StepRecord, TheWorstEquationIsTheLargest) {
  solver::Residuals residuals;
  residuals.value[solver::solids_continuity] = 3e-3;
  residuals.value[solver::gas_momentum_y] = 1e-3;
  EXPECT_EQ(residuals.worst(), solver::solids_continuity);
  EXPECT_EQ(residuals.largest(), 3e-3);
  // A NaN in the last equation is the worst.
  residuals.value[solver::solids_continuity] = std::nan("");
  EXPECT_EQ(residuals.worst(), solver::solids_continuity);
  EXPECT_TRUE(std::isnan(residuals.largest()));
}

// DISABLED: fails at cedfa1f. step_record.hpp says "NaN counts as largest", but
// Residuals::worst() replaces a NaN in equation e by equation e + 1 (!(v <= NaN) is true for
// every v) and never returns to it, so largest() reports a finite value (here 0, gas y
// momentum) and advance()'s !isfinite(largest) check cannot see the NaN: the iteration would
// pass the tolerance if no linear solve failed first. Fix: in worst(), stop at a NaN, e.g.
//   if (std::isnan(value[worst])) break;   before the comparison.
TEST(StepRecord, NaNInAnEarlierEquationStaysTheWorst) {
  solver::Residuals residuals;
  residuals.value[solver::gas_momentum_x] = std::nan("");
  residuals.value[solver::solids_continuity] = 0.0;
  EXPECT_EQ(residuals.worst(), solver::gas_momentum_x);
  EXPECT_FALSE(residuals.largest() < 1e-4);  // a NaN iterate must never pass the tolerance
  residuals.value[solver::mixture_continuity] = std::nan("");
  residuals.value[solver::solids_continuity] = 3e-3;
  EXPECT_TRUE(std::isnan(residuals.largest()));
}

TEST(StepRecord, WorstCellsKeepTheLargestRowAndNaNCountsAsLargest) {
  solver::WorstCells worst;
  worst.reset(solver::gas_momentum_x);
  worst.record(solver::gas_momentum_x, 2.0, 7);
  worst.record(solver::gas_momentum_x, 1.0, 8);
  EXPECT_EQ(worst.local(solver::gas_momentum_x), 7);
  worst.record(solver::gas_momentum_x, std::nan(""), 9);
  EXPECT_EQ(worst.local(solver::gas_momentum_x), 9);
  EXPECT_EQ(worst.value(solver::gas_momentum_x), INFINITY);
}

TEST(StepRecord, AStepThatFailedDivergedOnlyIfItsLargestResidualGrewOrBecameNonFinite) {
  solver::StepResult result;
  result.first_largest = 2e-2;
  result.residuals.value[solver::solids_continuity] = 1.3e-3;  // fell, not to the tolerance
  EXPECT_FALSE(result.diverged());
  result.residuals.value[solver::solids_continuity] = 5e-2;  // grew
  EXPECT_TRUE(result.diverged());
  result.residuals.value[solver::solids_continuity] = std::nan("");
  EXPECT_TRUE(result.diverged());
}

TEST(StepRecord, AnIterationWithADampedCompressionDoesNotEndTheStep) {
  solver::IterationSums sums;
  EXPECT_TRUE(solver::iteration_converged(5e-5, 1e-4, sums));
  EXPECT_FALSE(solver::iteration_converged(2e-4, 1e-4, sums));
  EXPECT_FALSE(solver::iteration_converged(std::nan(""), 1e-4, sums));
  // One cell's ε' damped anywhere (the sums are over all ranks): its continuity does not hold.
  sums.interventions[solver::compression_damped] = 1.0;
  EXPECT_FALSE(solver::iteration_converged(5e-5, 1e-4, sums));
  // The other limiters do not hold the step.
  sums.interventions[solver::compression_damped] = 0.0;
  sums.interventions[solver::fraction_clamped_at_zero] = 3.0;
  EXPECT_TRUE(solver::iteration_converged(5e-5, 1e-4, sums));
}

TEST(StallWatch, AStepStallsWhenItsLargestResidualHasNotFallenOverFiveIterations) {
  // MFIX's DETECT_STALL: checked at iterations 5, 10, 15, ...; from 15 on against the value 5
  // iterations before.
  const auto first_stall = [](auto residual_at) {
    solver::StallWatch watch;
    for (int it = 1; it <= 100; ++it)
      if (watch.has_stalled_after(it, residual_at(it))) return it;
    return 0;
  };
  EXPECT_EQ(first_stall([](int it) { return std::pow(0.95, it); }), 0);  // slow but falling
  EXPECT_EQ(first_stall([](int) { return 1e-3; }), 15);                 // flat: not before 15
  EXPECT_EQ(first_stall([](int it) { return it < 30 ? std::pow(0.9, it) : 0.05; }), 35);
  // An oscillation that rises at one check stalls there, even though it fell in between.
  EXPECT_EQ(first_stall([](int it) { return (it % 10 == 0 ? 2.0 : 1.0) * std::pow(0.99, it); }), 20);
  EXPECT_EQ(first_stall([](int it) { return it >= 17 ? NAN : 1.0 / it; }), 20);  // NaN stalls
}

TEST(StepRecord, ALocationReadsAsCellFaceAndRegion) {
  solver::CellLocation where;
  where.cell = {0, 2, 0};
  where.position = {0.005, 0.025, 0.005};
  where.face = "-z";
  where.region = "orifice";
  EXPECT_EQ(where.text(), "cell (0, 2, 0) at (0.005, 0.025, 0.005) m, its -z face (on boundary region 'orifice')");
}

}  // namespace
}  // namespace bagnold::tests
