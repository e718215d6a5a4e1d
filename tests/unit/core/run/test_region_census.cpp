// The regions' census and what check refuses from it: counts against a hand computation, the
// same on 1, 2 and 3 ranks (owned cells summed once, halos not counted), the solids mass equal to
// the initial state's inventory, and an error at the table's line for each region without cells.
#include <gtest/gtest.h>

#include <array>
#include <utility>

#include "src/run/initial_state.hpp"
#include "src/run/monitor_columns.hpp"
#include "src/run/region_census.hpp"
#include "src/run/region_report.hpp"
#include "tests/support/deck_domain.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

// 4 x 4 x 10 cells of 1 cm with solids; `regions` appended (the CLI test's
// tests/cli/overlapping_regions.toml works the same counts out in its header).
std::string deck_with(const std::string& regions) {
  return "[run]\nend_time = 0.0\n"
         "[grid.x]\nmax = 0.04\ncells = 4\n[grid.y]\nmax = 0.04\ncells = 4\n"
         "[grid.z]\nmax = 0.1\ncells = 10\n"
         "[solids]\ndensity = 2500.0\n[output]\ndirectory = \"out\"\n" + regions;
}

const std::string overlapping =
    "[[boundary]]\nname = \"left\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
    "min = [-1.0, -1.0, -1.0]\nmax = [0.02, 1.0, 0.0]\n"
    "[[boundary]]\nname = \"right\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
    "min = [0.01, -1.0, -1.0]\nmax = [1.0, 1.0, 0.0]\n"
    "[[initial]]\nmax = [1.0, 1.0, 0.05]\nsolids_fraction = 0.5\n"
    "[[initial]]\nmin = [-1.0, -1.0, 0.03]\nmax = [1.0, 1.0, 0.08]\nsolids_fraction = 0.4\n";

struct Censused : DeckAndDomain {
  run::RegionCensus census;
  explicit Censused(const std::string& text)
      : DeckAndDomain(text), census(run::take_region_census(deck, domain)) {}
};

// (selected, kept) of each region, and (first, second, shared) of each overlap, to compare whole.
using Counts = std::vector<std::pair<std::int64_t, std::int64_t>>;
Counts counts(const std::vector<run::RegionCount>& regions) {
  Counts out;
  for (const auto& r : regions) out.emplace_back(r.selected, r.kept);
  return out;
}
using Overlaps = std::vector<std::array<std::int64_t, 3>>;
Overlaps overlaps(const std::vector<run::RegionOverlap>& pairs) {
  Overlaps out;
  for (const auto& o : pairs) out.push_back({o.first, o.second, o.shared});
  return out;
}

TEST(RegionCensus, CountsOverlapsAndMassByHand) {
  const Censused c(deck_with(overlapping));
  // Floor boundary cells: 6 x 6 (i, j = -1 ... 4). "left" takes x = -0.005, 0.005, 0.015 (18);
  // "right" x = 0.015 ... 0.045 (24), of which the 6 at x = 0.015 go to "left" (first wins).
  EXPECT_EQ(counts(c.census.boundaries), (Counts{{18, 18}, {24, 18}}));
  EXPECT_EQ(overlaps(c.census.boundary_overlaps), (Overlaps{{0, 1, 6}}));
  EXPECT_EQ(c.census.walls, c.domain.flags.boundary_count - 36);
  // Initial: [0] layers z = 0.005 ... 0.045 (80 cells), [1] z = 0.035 ... 0.075 (80); the 32
  // cells of z = 0.035 and 0.045 are set by [1] (later wins).
  EXPECT_EQ(counts(c.census.initial), (Counts{{80, 48}, {80, 80}}));
  EXPECT_EQ(overlaps(c.census.initial_overlaps), (Overlaps{{0, 1, 32}}));
  // ρ_s ε_s V: 48 × 2500 × 0.5 × 1e-6 and 80 × 2500 × 0.4 × 1e-6 (sums of 1e-6-sized terms:
  // a few ulps).
  EXPECT_NEAR(c.census.initial_solids_mass[0], 0.06, 1e-14);
  EXPECT_NEAR(c.census.initial_solids_mass[1], 0.08, 1e-14);
}

// What the census says a region puts in is what the initial state holds.
TEST(RegionCensus, SolidsMassIsTheInitialInventory) {
  const Censused c(deck_with(overlapping));
  run::FlowState state(c.domain.layout.local_count());
  run::set_initial_state(c.deck, c.domain, state);
  const double inventory = run::phase_inventory(c.deck, c.domain, state).solids;
  EXPECT_NEAR(c.census.initial_solids_mass[0] + c.census.initial_solids_mass[1], inventory,
              1e-12 * inventory);
}

TEST(RegionReport, ValidRegionsGiveNoErrorAndNoteEachOverlap) {
  const Censused c(deck_with(overlapping));
  const auto report = run::report_regions(c.deck, c.domain, c.census);
  EXPECT_TRUE(report.errors.ok()) << report.errors.report();
  ASSERT_EQ(report.notes.size(), 2u);
  EXPECT_TRUE(contains(report.notes[0], "boundary[0] \"left\" and boundary[1] \"right\" both select 6"))
      << report.notes[0];
  EXPECT_TRUE(contains(report.notes[1], "so initial[0] sets none of these")) << report.notes[1];
}

// A region without cells is refused at its own table's line, each one named.
TEST(RegionReport, EachRegionWithoutCellsIsAnErrorAtItsLine) {
  const std::string text = deck_with(
      "[[geometry.block]]\nshape = \"box\"\nmin = [0.5, 0.5, 0.5]\nmax = [0.6, 0.6, 0.6]\n"
      "[[boundary]]\nname = \"floor\"\ntype = \"no_slip_wall\"\nface = \"z-\"\n"
      "[[boundary]]\nname = \"shadow\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
      "min = [-1.0, -1.0, -1.0]\nmax = [0.02, 1.0, 0.0]\n"
      "[[boundary]]\nname = \"on_the_face\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
      "min = [0.0, 0.0, 0.0]\nmax = [0.04, 0.04, 0.0]\n"
      "[[initial]]\nsolids_fraction = 0.5\n"
      "[[initial]]\nmin = [0.0, 0.0, 0.2]\nmax = [0.04, 0.04, 0.3]\nsolids_fraction = 0.5\n");
  const Censused c(text);
  const auto report = run::report_regions(c.deck, c.domain, c.census);
  const auto& errors = report.errors.errors();
  ASSERT_EQ(errors.size(), 4u) << report.errors.report();
  const auto block = error_on(errors, "geometry.block[0]");
  EXPECT_EQ(block.line, line_of(text, "[[geometry.block]]"));
  EXPECT_TRUE(contains(block.message, "blocks no cell")) << block.message;
  // "floor" (the whole floor) holds every cell "shadow" selects: nothing is left to it.
  const auto shadow = error_on(errors, "boundary[1]");
  EXPECT_EQ(shadow.line, line_of(text, "name = \"shadow\"") - 1);
  EXPECT_TRUE(contains(shadow.message, "holds no cell")) << shadow.message;
  EXPECT_TRUE(contains(shadow.message, "boundary[0] \"floor\"")) << shadow.message;
  const auto face = error_on(errors, "boundary[2]");
  EXPECT_EQ(face.line, line_of(text, "name = \"on_the_face\"") - 1);
  EXPECT_TRUE(contains(face.message, "selects no cell")) << face.message;
  EXPECT_TRUE(contains(face.message, "centres at z = -0.005 m")) << face.message;
  const auto initial = error_on(errors, "initial[1]");
  EXPECT_EQ(initial.line, line_of(text, "[[initial]]\nmin") );
  EXPECT_TRUE(contains(initial.message, "selects no cell")) << initial.message;
  EXPECT_EQ(initial.file, "t.toml");
}

}  // namespace
}  // namespace bagnold::tests
