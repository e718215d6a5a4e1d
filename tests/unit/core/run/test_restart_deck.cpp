// Which deck a restart may use: the snapshot's own, except for run control ([run], [output]).
#include <gtest/gtest.h>

#include "src/deck/load.hpp"
#include "src/run/restart_deck.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

// The deck a snapshot records: the resolved text of the minimal deck.
std::string recorded() { return deck::resolved_text(deck::load_deck_text(deck_text(), "deck.toml")); }

std::vector<deck::KeyDifference> conflicts_with(const std::vector<std::string>& overrides) {
  return run::restart_conflicts(recorded(), deck::load_deck_text(deck_text(), "deck.toml", overrides));
}

TEST(RestartDeck, RunControlIsTheRunAndOutputTablesAndThePartition) {
  for (const auto* key : {"run.end_time", "run.dt_max", "run.dt_min", "run.dt_initial", "run.title",
                          "output.directory", "output.snapshot_interval", "output.progress",
                          "numerics.partition_weights"})
    EXPECT_TRUE(run::is_run_control(key)) << key;
  for (const auto* key : {"solids.diameter", "numerics.tolerance", "numerics.max_outer_iterations",
                          "grid.x.cells", "boundary[0].pressure", "initial[0].solids_fraction",
                          "models.solids_stress.model", "physics.gravity", "runs.x", "outputs"})
    EXPECT_FALSE(run::is_run_control(key)) << key;
}

TEST(RestartDeck, ARestartMayChangeRunControl) {
  const auto c = conflicts_with({"run.end_time=5", "run.dt_max=1e-3", "run.dt_initial=1e-5",
                                 "run.title=\"longer\"", "output.directory=\"elsewhere\"",
                                 "output.snapshot_interval=0.01", "output.progress=\"never\""});
  EXPECT_TRUE(c.empty()) << c.front().key;
}

TEST(RestartDeck, EverythingElseConflictsWithBothValues) {
  const auto c = conflicts_with({"run.end_time=5", "solids.diameter=3e-3",
                                 "numerics.tolerance=1e-6", "grid.x.cells=8"});
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].key, "grid.x.cells");
  EXPECT_EQ(c[0].recorded, "4");
  EXPECT_EQ(c[0].current, "8");
  EXPECT_EQ(c[1].key, "numerics.tolerance");
  EXPECT_EQ(c[2].key, "solids.diameter");
  EXPECT_EQ(c[2].recorded, "0.001");
  EXPECT_EQ(c[2].current, "0.003");
}

TEST(RestartDeck, ARecordedDeckThatDoesNotLoadIsAnError) {
  const auto current = deck::load_deck_text(deck_text(), "deck.toml");
  // A key this Bagnold does not know, as a deck written by another version may hold.
  EXPECT_THROW(run::restart_conflicts("renamed_key = 1\n" + recorded(), current), deck::DeckError);
}

}  // namespace
}  // namespace bagnold::tests
