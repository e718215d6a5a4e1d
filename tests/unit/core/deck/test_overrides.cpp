// Command-line overrides (--set key=value): each value kind, array elements, and the errors of a
// bad override, which name the override itself rather than a line of the deck.
#include <gtest/gtest.h>

#include "src/deck/load.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

const std::string with_boundaries = deck_text(
    "[[boundary]]\nname = \"orifice\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
    "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n");

deck::Deck load_with(const std::vector<std::string>& overrides,
                     const std::string& text = with_boundaries) {
  return deck::load_deck_text(text, "deck.toml", overrides);
}

TEST(DeckOverride, RealReplacesTheDecksValue) {
  EXPECT_EQ(load_with({}).run.end_time, 1.0);
  EXPECT_EQ(load_with({"run.end_time=0.25"}).run.end_time, 0.25);
  EXPECT_EQ(load_with({"solids.diameter=2e-3"}).solids.material.diameter, 2e-3);
  EXPECT_EQ(load_with({"run.end_time=0"}).run.end_time, 0.0);  // integer for a real
}

TEST(DeckOverride, IntegerBoolArrayAndString) {
  const auto d = load_with({"grid.x.cells=7", "gas.enabled=false",
                            "physics.gravity=[0.0, -9.81, 0]", "run.title=\"quoted title\""});
  EXPECT_EQ(d.grid.x.cells, 7);
  EXPECT_FALSE(d.gas.enabled);
  EXPECT_EQ(d.physics.gravity, (std::array<double, 3>{0.0, -9.81, 0.0}));
  EXPECT_EQ(d.run.title, "quoted title");
}

TEST(DeckOverride, BareWordIsAString) {
  const auto d = load_with({"models.solids_stress.model=skt", "output.directory=runs/a-b.c",
                            "output.progress=never"});
  EXPECT_EQ(d.models.solids_stress.name, "skt");
  EXPECT_EQ(d.output.directory, "runs/a-b.c");
  EXPECT_EQ(d.output.progress, "never");
}

// As a deck line: `--set 'solids.diameter = 1e-3'` is `--set solids.diameter=1e-3`.
TEST(DeckOverride, SpacesAroundTheEqualsSignAreIgnored) {
  const auto d = load_with({"solids.diameter = 2e-3", " run.end_time=0.5 ", "models.solids_stress.model =  skt"});
  EXPECT_EQ(d.solids.material.diameter, 2e-3);
  EXPECT_EQ(d.run.end_time, 0.5);
  EXPECT_EQ(d.models.solids_stress.name, "skt");
}

TEST(DeckOverride, CreatesMissingTables) {
  // The deck has no [models] table: the override makes it, down to a model's coefficients.
  const auto d = load_with({"models.solids_stress.mkt.alpha_1=0.09"});
  EXPECT_EQ(models::real_coefficient(d.models.solids_stress.coefficients, "alpha_1"), 0.09);
}

TEST(DeckOverride, ArrayElement) {
  const auto d = load_with({"boundary[0].pressure=2e5", "boundary[1].name=lid"});
  ASSERT_EQ(d.boundaries.size(), 2u);
  EXPECT_EQ(d.boundaries[0].pressure, 2e5);
  EXPECT_EQ(d.boundaries[0].name, "orifice");
  EXPECT_EQ(d.boundaries[1].pressure, 101325.0);
  EXPECT_EQ(d.boundaries[1].name, "lid");
}

TEST(DeckOverride, LaterOverrideWins) {
  EXPECT_EQ(load_with({"run.end_time=0.5", "run.end_time=0.75"}).run.end_time, 0.75);
}

TEST(DeckOverride, BadValueIsAttributedToTheOverride) {
  const auto errors = errors_of(with_boundaries, {"solids.diameter=-1"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "--set solids.diameter=-1");
  EXPECT_EQ(errors[0].key, "solids.diameter");
  EXPECT_TRUE(contains(errors[0].message, "out of range")) << errors[0].message;
  EXPECT_EQ(errors[0].to_string().rfind("--set solids.diameter=-1: solids.diameter: ", 0), 0u)
      << errors[0].to_string();
}

TEST(DeckOverride, WrongTypeInAnArrayElementIsAttributedToTheOverride) {
  const auto errors = errors_of(with_boundaries, {"boundary[1].pressure=high"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "--set boundary[1].pressure=high");
  EXPECT_EQ(errors[0].key, "boundary[1].pressure");
  EXPECT_TRUE(contains(errors[0].message, "expected a real number")) << errors[0].message;
}

TEST(DeckOverride, UnknownKeySuggestsAndNamesTheOverride) {
  const auto errors = errors_of(with_boundaries, {"solids.diametr=1e-3"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "--set solids.diametr=1e-3");
  EXPECT_EQ(errors[0].key, "solids.diametr");
  EXPECT_TRUE(contains(errors[0].message, "did you mean 'diameter'?")) << errors[0].message;
}

TEST(DeckOverride, ErrorsElsewhereKeepTheirDeckPosition) {
  // An override of one key does not move the deck's own errors onto the command line.
  const std::string text = deck_text("[gas]\ndensity = -1.0\n");
  const auto errors = errors_of(text, {"solids.diameter=2e-3"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "deck.toml");
  EXPECT_EQ(errors[0].line, line_of(text, "density = -1.0"));
}

TEST(DeckOverride, NotAnAssignment) {
  for (const std::string bad : {"solids.diameter", "=1e-3"}) {
    const auto errors = errors_of(with_boundaries, {bad});
    ASSERT_EQ(errors.size(), 1u) << report_of(errors);
    EXPECT_EQ(errors[0].file, "--set " + bad);
    EXPECT_TRUE(contains(errors[0].message, "expected KEY=VALUE")) << errors[0].message;
  }
}

TEST(DeckOverride, BadPath) {
  for (const std::string bad : {"solids..diameter=1", "boundary[x].name=a", "boundary[-1].name=a",
                                ".run=1"}) {
    const auto errors = errors_of(with_boundaries, {bad});
    ASSERT_EQ(errors.size(), 1u) << bad << "\n" << report_of(errors);
    EXPECT_EQ(errors[0].file, "--set " + bad);
    EXPECT_EQ(errors[0].line, 0);
    EXPECT_EQ(errors[0].column, 0);
    EXPECT_TRUE(contains(errors[0].message, "not a valid key path")) << errors[0].message;
  }
}

TEST(DeckOverride, PathThroughAValueIsAnError) {
  const auto errors = errors_of(with_boundaries, {"run.end_time.value=1"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "--set run.end_time.value=1");
  EXPECT_TRUE(contains(errors[0].message, "'end_time' is not a table")) << errors[0].message;
}

TEST(DeckOverride, NonExistentArrayElement) {
  const auto errors = errors_of(with_boundaries, {"boundary[2].pressure=1e5"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].file, "--set boundary[2].pressure=1e5");
  EXPECT_EQ(errors[0].key, "boundary[2].pressure");
  EXPECT_TRUE(contains(errors[0].message, "no [[boundary]] element 2")) << errors[0].message;
  // A deck without the array at all.
  const auto none = errors_of(deck_text(), {"initial[0].solids_fraction=0.5"});
  ASSERT_EQ(none.size(), 1u) << report_of(none);
  EXPECT_TRUE(contains(none[0].message, "no [[initial]] element 0")) << none[0].message;
}

TEST(DeckOverride, WholeArrayElementCannotBeReplaced) {
  const auto errors = errors_of(with_boundaries, {"boundary[0]=1"});
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_TRUE(contains(errors[0].message, "cannot replace a whole array element"))
      << errors[0].message;
}

TEST(DeckOverride, ReplacingATableWithAValueIsReported) {
  const auto errors = errors_of(with_boundaries, {"gas=3"});
  const auto e = error_on(errors, "gas");
  EXPECT_EQ(e.file, "--set gas=3");
  EXPECT_TRUE(contains(e.message, "expected a table")) << e.message;
}

TEST(DeckOverride, SeveralBadOverridesAreAllReported) {
  const auto errors =
      errors_of(with_boundaries, {"solids.diameter=-1", "boundary[5].name=x", "gas.density=0"});
  EXPECT_EQ(errors.size(), 3u) << report_of(errors);
  EXPECT_EQ(error_on(errors, "gas.density").file, "--set gas.density=0");
}

// An error on a whole table that --set changed (the closure refusing the [solids] material)
// points at those --set arguments, with the table's line in parentheses; without an override
// it keeps the table's line.
TEST(DeckOverride, TableErrorPointsAtTheOverridesBelowIt) {
  const std::string text = deck_text("[solids]\nrestitution = 0.8\n");
  const auto errors = errors_of(text, {"solids.restitution=1.0", "run.end_time=2"});
  const auto e = error_on(errors, "solids");
  EXPECT_EQ(e.file, "--set solids.restitution=1.0 (deck.toml:" +
                        std::to_string(line_of(text, "[solids]")) + ")");
  EXPECT_EQ(e.line, 0);
  EXPECT_EQ(e.to_string().rfind("--set solids.restitution=1.0 (deck.toml:", 0), 0u) << e.to_string();
  const std::string in_deck = deck_text("[solids]\nrestitution = 1.0\n");
  const auto own = error_on(errors_of(in_deck, {"run.end_time=2"}), "solids");
  EXPECT_EQ(own.file, "deck.toml");
  EXPECT_EQ(own.line, line_of(in_deck, "[solids]"));
}

// The deck records where each table, array element and key was written, for the checks made
// after loading (a region without cells, a grid too large); an overridden key's is its --set.
TEST(DeckOverride, OriginsOfTablesElementsAndKeys) {
  const auto d = load_with({"grid.z.cells=8"});
  EXPECT_EQ(d.origin_of("boundary[1]").file, "deck.toml");
  EXPECT_EQ(d.origin_of("boundary[1]").line, line_of(with_boundaries, "[[boundary]]\nname = \"top\""));
  EXPECT_EQ(d.origin_of("grid.x.cells").line, line_of(with_boundaries, "cells = 4"));
  EXPECT_EQ(d.origin_of("grid.z.cells").file, "--set grid.z.cells=8");
  EXPECT_EQ(d.origin_of("grid.z.cells").line, 0);
  EXPECT_EQ(d.origin_of("no.such.key").file, "deck.toml");  // the deck, without a line
  EXPECT_EQ(d.origin_of("no.such.key").line, 0);
}

}  // namespace
}  // namespace bagnold::tests
