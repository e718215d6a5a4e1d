// The differences between two resolved decks: every key whose value differs, with both values,
// found to the last bit; nothing for the same deck.
#include <gtest/gtest.h>

#include <cmath>

#include "src/deck/differences.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

deck::Deck load_with(const std::vector<std::string>& overrides, const std::string& tail = "") {
  return deck::load_deck_text(deck_text(tail), "deck.toml", overrides);
}

std::string listed(const std::vector<deck::KeyDifference>& differences) {
  std::string out;
  for (const auto& d : differences) out += d.key + ": " + d.recorded + " -> " + d.current + "\n";
  return out;
}

TEST(DeckDifferences, TheSameDeckHasNone) {
  const auto d = load_with({"solids.diameter=3e-3"});
  EXPECT_TRUE(deck::differences(d, d).empty()) << listed(deck::differences(d, d));
  // The same values reached another way (a default written out) are no difference either.
  EXPECT_TRUE(deck::differences(load_with({}), load_with({"solids.density=2500.0"})).empty());
}

TEST(DeckDifferences, EachChangedKeyIsListedWithBothValues) {
  const auto recorded = load_with({});
  const auto current = load_with({"solids.diameter=3e-3", "physics.gravity=[0, 0, -1]", "run.end_time=2"});
  const auto d = deck::differences(recorded, current);
  ASSERT_EQ(d.size(), 3u) << listed(d);
  EXPECT_EQ(d[0].key, "physics.gravity");
  EXPECT_EQ(d[0].recorded, "[0.0, 0.0, -9.81]");
  EXPECT_EQ(d[0].current, "[0.0, 0.0, -1.0]");
  EXPECT_EQ(d[1].key, "run.end_time");  // run control is still a difference; restarts filter it
  EXPECT_EQ(d[2].key, "solids.diameter");
  EXPECT_EQ(d[2].recorded, "0.001");
  EXPECT_EQ(d[2].current, "0.003");
}

TEST(DeckDifferences, TheLastBitCounts) {
  const double next = std::nextafter(1e-3, 1.0);
  char text[64];
  std::snprintf(text, sizeof text, "solids.diameter=%.17g", next);
  const auto d = deck::differences(load_with({}), load_with({text}));
  ASSERT_EQ(d.size(), 1u) << listed(d);
  EXPECT_EQ(d[0].key, "solids.diameter");
  EXPECT_NE(d[0].recorded, d[0].current);
}

TEST(DeckDifferences, AnotherModelListsItsNameAndBothCoefficientTables) {
  const auto d = deck::differences(load_with({}), load_with({"models.solids_stress.model=skt"}));
  const std::string text = listed(d);
  EXPECT_NE(text.find("models.solids_stress.model: \"mkt\" -> \"skt\"\n"), std::string::npos) << text;
  // The closure's own constants: MKT's were set and are now absent, SKT's the other way round.
  EXPECT_NE(text.find("models.solids_stress.mkt."), std::string::npos) << text;
  EXPECT_NE(text.find(" -> (absent)\n"), std::string::npos) << text;
  EXPECT_NE(text.find("models.solids_stress.skt."), std::string::npos) << text;
  EXPECT_NE(text.find(": (absent) -> "), std::string::npos) << text;
}

TEST(DeckDifferences, ArrayElementsAreIndexed) {
  const std::string outlet = "[[boundary]]\nname = \"out\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n";
  const auto d = deck::differences(load_with({}, outlet), load_with({"boundary[0].pressure=1e5"}, outlet));
  ASSERT_EQ(d.size(), 1u) << listed(d);
  EXPECT_EQ(d[0].key, "boundary[0].pressure");
  EXPECT_EQ(d[0].recorded, "101325.0");
  EXPECT_EQ(d[0].current, "100000.0");
  // A region only one deck has: each of its keys, absent in the other.
  const auto added = deck::differences(load_with({}), load_with({}, outlet));
  ASSERT_FALSE(added.empty());
  for (const auto& a : added) {
    EXPECT_EQ(a.key.rfind("boundary[0].", 0), 0u) << a.key;
    EXPECT_EQ(a.recorded, "(absent)");
  }
}

}  // namespace
}  // namespace bagnold::tests
