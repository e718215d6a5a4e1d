// The [[pressure_probe]]s' dp_<name> = p_g(lower) − p_g(upper): the layer mean weighted by the
// fluid cells' area across gravity (blocked cells left out, stretched cells weighed by area) and
// the single cell's value, summed over the ranks whichever holds the cells (run on 1, 2 and 3
// ranks: every rank gets the same values); the probes' monitor columns, and the points check
// refuses.
#include <gtest/gtest.h>

#include "src/run/initial_state.hpp"
#include "src/run/monitor_columns.hpp"
#include "src/run/pressure_probe.hpp"
#include "tests/support/deck_domain.hpp"

namespace bagnold::tests {
namespace {

// 4 × 1 × 6 cells, x stretched (ratio 3) over 0.04 m, z uniform over 0.06 m; a block makes the
// cell (i = 0, k = 2) solid.
std::string probe_deck(const std::string& probes) {
  return "[run]\nend_time = 0.1\n"
         "[grid.x]\nmax = 0.04\ncells = 4\nratio = 3.0\n[grid.y]\nmax = 0.01\ncells = 1\n"
         "[grid.z]\nmax = 0.06\ncells = 6\n"
         "[[geometry.block]]\nshape = \"box\"\nmin = [-1.0, -1.0, 0.02]\nmax = [0.003, 1.0, 0.03]\n"
         "[output]\ndirectory = \"out\"\n[solids]\nenabled = false\n" + probes;
}

const std::string two_probes =
    "[[pressure_probe]]\nname = \"column\"\nlower = [0.035, 0.005, 0.025]\n"
    "upper = [0.02, 0.005, 0.055]\n"
    "[[pressure_probe]]\nname = \"cells\"\nlower = [0.039, 0.005, 0.001]\n"
    "upper = [0.02, 0.005, 0.06]\naverage = \"cell\"\n";

// A pressure field that varies along x and z: p = 1e5 + 2000 (0.06 − z) + 3e4 x.
double field(const std::array<double, 3>& x) { return 1e5 + 2000.0 * (0.06 - x[2]) + 3e4 * x[0]; }

// The area-weighted mean of `field` over the fluid cells of layer k, from the whole grid (every
// rank holds the cell flags).
double layer_mean(const parallel::Domain& domain, int k) {
  double sum = 0.0, area = 0.0;
  for (int i = 0; i < domain.grid.cells(0); ++i) {
    const grid::Index3 ijk{i, 0, k};
    if (domain.flags.kind[static_cast<std::size_t>(domain.grid.natural(ijk))] != grid::CellKind::fluid)
      continue;
    const double a = domain.grid.axis(0).width(i) * domain.grid.axis(1).width(0);
    sum += a * field(domain.grid.centre(ijk));
    area += a;
  }
  return sum / area;
}

TEST(PressureProbe, LayerMeansAndCellsOnAnyRank) {
  const DeckAndDomain c(probe_deck(two_probes));
  const auto& layout = c.domain.layout;
  run::FlowState state(layout.local_count());
  for (int l = 0; l < layout.local_count(); ++l)
    state.gas_pressure[static_cast<std::size_t>(l)] =
        layout.kind(l) == grid::CellKind::fluid ? field(c.domain.grid.centre(layout.index3(l))) : -1e9;
  const auto drops = run::pressure_drops(c.deck, c.domain, state);
  ASSERT_EQ(drops.size(), 2u);
  // The column: layer 2 (z = 25 mm, its cell i = 0 blocked) to layer 5 (z = 55 mm).
  const double column = layer_mean(c.domain, 2) - layer_mean(c.domain, 5);
  EXPECT_NEAR(drops[0], column, 1e-9);
  // Not the plain mean of the layer's centres, nor one with the blocked cell in it.
  EXPECT_GT(std::abs(column - 2000.0 * 0.03), 1.0);
  // The cells: (i = 3, k = 0) and (i = 2 or 3, k = 5); the upper point lies on the domain's top
  // face, so in the last layer; x = 0.02 lies on a face and belongs to the cell above it.
  const auto& x_axis = c.domain.grid.axis(0);
  const int upper_i = x_axis.lower_face(2) <= 0.02 ? 2 : 1;
  const double cells = field(c.domain.grid.centre({3, 0, 0})) - field(c.domain.grid.centre({upper_i, 0, 5}));
  EXPECT_NEAR(drops[1], cells, 1e-9);
  EXPECT_GT(drops[1], 0.0);
}

TEST(PressureProbe, InitialGasWeightBetweenTwoLayers) {
  DeckAndDomain c(probe_deck(
      "[gas]\ndensity = 2.0\n"
      "[[pressure_probe]]\nname = \"h\"\nlower = [0.01, 0.005, 0.005]\nupper = [0.01, 0.005, 0.045]\n"));
  run::FlowState state(c.domain.layout.local_count());
  run::set_initial_state(c.deck, c.domain, state);
  EXPECT_NEAR(run::pressure_drops(c.deck, c.domain, state)[0], 2.0 * 9.81 * 0.04, 1e-9);
}

TEST(PressureProbe, MonitorColumns) {
  const DeckAndDomain c(probe_deck(two_probes));
  const auto columns = run::monitor_columns(c.domain.regions, c.deck.pressure_probes);
  ASSERT_GE(columns.size(), 2u);
  EXPECT_EQ(columns[columns.size() - 2], "dp_column");
  EXPECT_EQ(columns.back(), "dp_cells");
}

TEST(PressureProbe, PointsCheckRefuses) {
  const DeckAndDomain c(probe_deck(
      "[[pressure_probe]]\nname = \"out\"\nlower = [0.02, 0.005, 0.07]\nupper = [0.02, 0.005, 0.05]\n"
      "[[pressure_probe]]\nname = \"blocked\"\nlower = [0.0005, 0.005, 0.025]\n"
      "upper = [0.02, 0.005, 0.05]\naverage = \"cell\"\n"
      "[[pressure_probe]]\nname = \"fine\"\nlower = [0.0005, 0.005, 0.025]\n"
      "upper = [0.02, 0.005, 0.05]\n"));
  const auto problems = run::pressure_probe_problems(c.deck, c.domain);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0].key, "pressure_probe[0].lower");
  EXPECT_NE(problems[0].message.find("outside the domain"), std::string::npos) << problems[0].message;
  EXPECT_EQ(problems[1].key, "pressure_probe[1].lower");
  EXPECT_NE(problems[1].message.find("blocked cell"), std::string::npos) << problems[1].message;
}

}  // namespace
}  // namespace bagnold::tests
