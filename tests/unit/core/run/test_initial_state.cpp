// The state at t = 0: [[initial]] regions in deck order (later wins) on fluid cells, ε_g = 1 − ε_s,
// and the gas pressure hydrostatic from gas.reference_pressure at the top along gravity.
// Run on 1 and 2 ranks: every stored cell, owned or halo, gets the same values.
#include <gtest/gtest.h>

#include <map>

#include "src/run/initial_state.hpp"
#include "tests/support/deck_domain.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

struct Initialized : DeckAndDomain {
  run::FlowState state;
  explicit Initialized(const std::string& text)
      : DeckAndDomain(text), state(domain.layout.local_count()) {
    run::set_initial_state(deck, domain, state);
  }
};

TEST(InitialState, HydrostaticGasPressureFromTheTop) {
  const Initialized s(box_deck(2, 2, 4, "[gas]\ndensity = 2.0\nreference_pressure = 1e5\n"));
  const auto& layout = s.domain.layout;
  ASSERT_GT(layout.local_count(), 0);
  for (int l = 0; l < layout.local_count(); ++l) {
    const double z = s.domain.grid.centre(layout.index3(l))[2];
    EXPECT_NEAR(s.state.gas_pressure[static_cast<std::size_t>(l)],
                1e5 + 2.0 * 9.81 * (0.04 - z), 1e-9)
        << "z = " << z;
    EXPECT_EQ(s.state.solids_fraction[static_cast<std::size_t>(l)], 0.0);
    EXPECT_EQ(s.state.gas_fraction[static_cast<std::size_t>(l)], 1.0);
  }
}

TEST(InitialState, HydrostaticAlongATiltedGravity) {
  // Gravity along −x and +y: the reference is the x = max, y = min edge.
  const Initialized s(box_deck(3, 2, 2, "[physics]\ngravity = [-3.0, 4.0, 0.0]\n"));
  const auto& layout = s.domain.layout;
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto x = s.domain.grid.centre(layout.index3(l));
    EXPECT_NEAR(s.state.gas_pressure[static_cast<std::size_t>(l)],
                101325.0 + 1.2 * (3.0 * (0.03 - x[0]) + 4.0 * x[1]), 1e-9);
  }
}

TEST(InitialState, RegionsInOrderLaterWins) {
  const Initialized s(box_deck(
      2, 2, 4,
      "[[initial]]\nmax = [1.0, 1.0, 0.02]\nsolids_fraction = 0.5\n"
      "gas_velocity = [1.0, 2.0, 3.0]\nsolids_velocity = [0.0, 0.0, -1.0]\n"
      "[[initial]]\nmin = [-1.0, -1.0, 0.01]\nmax = [1.0, 1.0, 0.03]\nsolids_fraction = 0.1\n"));
  const auto& layout = s.domain.layout;
  int fluid = 0;
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const double z = s.domain.grid.centre(layout.index3(l))[2];
    if (layout.kind(l) != grid::CellKind::fluid) {
      EXPECT_EQ(s.state.solids_fraction[i], 0.0) << "boundary cells are not set";
      continue;
    }
    ++fluid;
    // Cells k = 0 (first region), 1 (both: the second wins), 2 (second), 3 (neither).
    const double expected = z > 0.03 ? 0.0 : z > 0.01 ? 0.1 : 0.5;
    EXPECT_DOUBLE_EQ(s.state.solids_fraction[i], expected) << "z = " << z;
    EXPECT_DOUBLE_EQ(s.state.gas_fraction[i], 1.0 - expected);
    // The second region sets velocities too (its defaults: at rest).
    const double w = z < 0.01 ? 3.0 : 0.0;
    EXPECT_EQ(s.state.gas_velocity[2][i], w) << "z = " << z;
    EXPECT_EQ(s.state.gas_velocity[0][i], z < 0.01 ? 1.0 : 0.0);
    EXPECT_EQ(s.state.solids_velocity[2][i], z < 0.01 ? -1.0 : 0.0);
  }
  EXPECT_GT(fluid, 0);
}

TEST(FlowState, EverySnapshotFieldHasItsSIUnits) {
  const run::FlowState state(1);
  std::map<std::string, std::string> units;
  for (const auto& view : state.views()) units[view.name] = view.units;
  EXPECT_EQ(units.size(), run::FlowState::field_names().size());
  EXPECT_EQ(units["solids_fraction"], "1");
  EXPECT_EQ(units["gas_fraction"], "1");
  EXPECT_EQ(units["gas_pressure"], "Pa");
  EXPECT_EQ(units["solids_pressure"], "Pa");
  EXPECT_EQ(units["granular_temperature"], "m^2/s^2");
  EXPECT_EQ(units["pressure_shear_rate"], "1/s");
  EXPECT_EQ(units["gas_velocity_x"], "m/s");
  EXPECT_EQ(units["solids_velocity_z"], "m/s");
}

}  // namespace
}  // namespace bagnold::tests
