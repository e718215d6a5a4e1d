// The per-rank counters (src/run/rank_balance.hpp) on a box 4 x 4 x 6 with solids in its lower
// half: the ranks' owned fluid cells sum to the box's 96, their solids cells to the 48 below
// z = 0.03, each rank counting exactly its own cells there; gathered in rank order on every rank.
// The partition by phases (work_weights.hpp) gives every rank its share of both kinds of cell.
// Run on 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include "src/run/initial_state.hpp"
#include "src/run/rank_balance.hpp"
#include "src/run/work_weights.hpp"
#include "tests/support/deck_domain.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

struct HalfFilledBox : DeckAndDomain {
  run::FlowState state;
  HalfFilledBox()
      : DeckAndDomain(box_deck(4, 4, 6, "[[initial]]\nmax = [1.0, 1.0, 0.03]\nsolids_fraction = 0.4\n")),
        state(domain.layout.local_count()) {
    run::set_initial_state(deck, domain, state);
  }
};

TEST(RankBalance, CountsEachRanksOwnCells) {
  const HalfFilledBox box;
  const auto& layout = box.domain.layout;
  const auto mine = run::count_rank(layout, box.state, 1e-6, {1.0, 2.0, 0.5});
  int below = 0;
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    if (box.domain.grid.centre(layout.index3(l))[2] < 0.03) ++below;
  EXPECT_EQ(mine.fluid_cells, layout.owned_fluid_count());
  EXPECT_EQ(mine.owned_cells, layout.owned_count());
  EXPECT_EQ(mine.solids_cells, below) << "solids cells are the owned cells below the fill";
  EXPECT_DOUBLE_EQ(mine.wait_share(), 0.5 / 3.0);

  const auto ranks = run::gather_rank_counters(layout.comm(), mine);
  ASSERT_EQ(static_cast<int>(ranks.size()), layout.comm().size());
  double fluid = 0.0, solids = 0.0, owned = 0.0;
  for (const auto& r : ranks) {
    fluid += r.fluid_cells;
    solids += r.solids_cells;
    owned += r.owned_cells;
  }
  EXPECT_EQ(fluid, 96.0);
  EXPECT_EQ(solids, 48.0);
  EXPECT_EQ(owned, static_cast<double>(6 * 6 * 8)) << "every stored cell of the box is owned once";
  EXPECT_EQ(ranks[static_cast<std::size_t>(layout.comm().rank())].solids_cells, mine.solids_cells);

  // Busy segments of different lengths (rank r marked r + 1 segments, each r + 1 s) arrive
  // padded with zeros to the longest.
  const int rank = layout.comm().rank(), size = layout.comm().size();
  const auto with_segments = run::gather_rank_counters(
      layout.comm(), run::count_rank(layout, box.state, 1e-6, {}, std::vector<double>(rank + 1, rank + 1.0)));
  for (int r = 0; r < size; ++r) {
    const auto& busy = with_segments[static_cast<std::size_t>(r)].busy_segments;
    ASSERT_EQ(static_cast<int>(busy.size()), size);
    for (int k = 0; k < size; ++k) EXPECT_EQ(busy[static_cast<std::size_t>(k)], k <= r ? r + 1.0 : 0.0);
  }
}

TEST(RankBalance, ThresholdExcludesTraces) {
  const HalfFilledBox box;
  EXPECT_EQ(run::count_rank(box.domain.layout, box.state, 0.5, {}).solids_cells, 0.0);
}

TEST(RankBalance, WorkImbalanceWeighsSolidsCellsAsThePartitionDoes) {
  // Work gas_cell_work per gas cell, solids_cell_work per solids cell (work_weights.hpp).
  const double gas_work = run::gas_cell_work, solids_work = run::solids_cell_work;
  run::RankCounters gas, bed;
  gas.fluid_cells = 800;  // all gas
  bed.fluid_cells = 800;
  bed.solids_cells = 800;  // all solids
  const double mean = 400.0 * (gas_work + solids_work);
  EXPECT_NEAR(run::work_imbalance({gas, bed}), 800.0 * solids_work / mean - 1.0, 1e-15);
  EXPECT_NEAR(run::work_imbalance({bed, bed}), 0.0, 1e-15);
  run::RankCounters fewer = bed;
  fewer.fluid_cells = 700;
  fewer.solids_cells = 700;  // the largest, 800 solids cells, against the mean of 750
  EXPECT_NEAR(run::work_imbalance({fewer, bed}), 800.0 / 750.0 - 1.0, 1e-15);
  EXPECT_EQ(run::work_imbalance({}), 0.0);
  EXPECT_EQ(run::work_imbalance({run::RankCounters{}}), 0.0);
}

TEST(RankBalance, TableGivesMaxOverMin) {
  const std::vector<run::RankCounters> ranks = {{10, 8, 0, {3.0, 1.0, 1.0}, {}, {}},
                                                {12, 8, 4, {6.0, 2.0, 0.2}, {}, {}}};
  const auto table = run::rank_balance_table(ranks);
  EXPECT_NE(table.find("max/min       1.20       1.00        inf         2.00       2.00       5.00"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("25.0"), std::string::npos) << "rank 0 waits 1 s of 4\n" << table;
  EXPECT_EQ(run::rank_balance_line(ranks),
            "ranks: fluid cells max/min 1.00, solids cells inf, assembly 2.00, solves 2.00; "
            "wait 2.5–25.0 %, from the imbalance 0.0–0.0 %; work max 20.0 % above the mean");
  // work 80 and 120; no busy segments
}

TEST(RankBalance, CountedWorkSplitsEachSegmentsSecondsByTheRanksUnits) {
  // Segment 0: 10 busy seconds over 100 + 300 units, so 0.025 s per unit whatever each rank's
  // own seconds (a slower core's 6 s for 100 units counts as 2.5 s); segment 1 has no units:
  // its busy seconds stand.
  run::RankCounters slow, fast;
  slow.busy_segments = {6.0, 1.0};
  slow.work_units = {100.0, 0.0};
  fast.busy_segments = {4.0, 2.0};
  fast.work_units = {300.0, 0.0};
  const auto work = run::counted_work({slow, fast});
  EXPECT_NEAR(work[0][0], 2.5, 1e-14);
  EXPECT_NEAR(work[1][0], 7.5, 1e-14);
  EXPECT_EQ(work[0][1], 1.0);
  EXPECT_EQ(work[1][1], 2.0);
  // The largest counted work sums to 7.5 + 2; the slow rank waits 5 + 1 of it.
  const auto shares = run::imbalance_wait_shares({slow, fast});
  EXPECT_NEAR(shares[0], 6.0 / 9.5, 1e-14);
  EXPECT_NEAR(shares[1], 0.0, 1e-14);
}

TEST(RankBalance, ImbalanceWaitIsTheBusiestRanksLeadPerSegment) {
  // Without units the counted work is the busy seconds.
  // Segment 0: rank 1 busier by 1 s; segment 1: rank 0 busier by 2 s; segment 2 only on rank 0
  // (rank 1 never marked it). The busiest ranks sum to 4 + 5 + 1 = 10 s.
  run::RankCounters first, second;
  first.busy_segments = {3.0, 5.0, 1.0};
  second.busy_segments = {4.0, 3.0};
  const auto shares = run::imbalance_wait_shares({first, second});
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_NEAR(shares[0], 1.0 / 10.0, 1e-15) << "rank 0 waits for rank 1 in segment 0 only";
  EXPECT_NEAR(shares[1], (2.0 + 1.0) / 10.0, 1e-15) << "rank 1 waits in segments 1 and 2";
  // Balanced per segment: no imbalance wait, however the totals compare.
  EXPECT_EQ(run::imbalance_wait_shares({first, first}), (std::vector<double>{0.0, 0.0}));
  // Equal totals, opposite segments: each waits for the other (the totals hide it).
  run::RankCounters swapped;
  swapped.busy_segments = {5.0, 3.0, 1.0};
  const auto opposite = run::imbalance_wait_shares({first, swapped});
  EXPECT_NEAR(opposite[0], 2.0 / 11.0, 1e-15);
  EXPECT_NEAR(opposite[1], 2.0 / 11.0, 1e-15);
  EXPECT_EQ(run::imbalance_wait_shares({run::RankCounters{}}), (std::vector<double>{0.0}));
  const auto line = run::rank_balance_line({first, second});
  EXPECT_NE(line.find("from the imbalance 10.0–30.0 %"), std::string::npos) << line;
}

TEST(RankBalance, PartitionByPhasesSharesOutBothKindsOfCell) {
  const HalfFilledBox box;
  const auto weights = run::partition_weights("phases", box.domain, box.state, 1e-6);
  ASSERT_EQ(weights.constraints, 2);
  const parallel::Domain by_phase(box.deck, parallel::Communicator(), weights);
  run::FlowState state(by_phase.layout.local_count());
  run::set_initial_state(box.deck, by_phase, state);
  const auto ranks = run::gather_rank_counters(by_phase.layout.comm(),
                                               run::count_rank(by_phase.layout, state, 1e-6, {}));
  const double n = static_cast<double>(ranks.size());
  for (const auto& r : ranks) {
    // Bagnold asks METIS for 1 % per constraint (partition.cpp); a cell more or less on these
    // small counts.
    EXPECT_NEAR(r.fluid_cells, 96.0 / n, 0.02 * 96.0 / n + 1.0);
    EXPECT_NEAR(r.solids_cells, 48.0 / n, 0.02 * 48.0 / n + 1.0) << "each rank its share of the bed";
  }
  // The work weights: one constraint, a solids cell weighing solids_cell_work.
  const auto work = run::partition_weights("work", box.domain, box.state, 1e-6);
  EXPECT_EQ(work.constraints, 1);
  long long total = 0;
  for (std::int64_t c = 0; c < box.domain.grid.extended_cell_count(); ++c)
    if (box.domain.flags.kind[static_cast<std::size_t>(c)] == grid::CellKind::fluid) total += work.at(c, 0);
  EXPECT_EQ(total, 48 * run::gas_cell_work + 48 * run::solids_cell_work);
}

}  // namespace
}  // namespace bagnold::tests
