// The state at t = 0: [[initial]] regions in deck order (later wins) on fluid cells, ε_g = 1 − ε_s,
// and the gas pressure hydrostatic from gas.reference_pressure at the top along gravity: the
// gas's weight (gas-weight) or the gas's and solids' (bed-weight, against the column's weight per
// area from the phases' inventory).
// Run on 1 and 2 ranks: every stored cell, owned or halo, gets the same values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "src/run/initial_state.hpp"
#include "src/run/monitor_columns.hpp"
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

// A 2 × 2 column of 10 stretched layers (0.1 m, the top layer twice the bottom one) with a bed
// of ε_s = 0.5 in the layers whose centres lie at or below 5 cm, gravity `g_z` along z.
std::string bed_deck(double g_z, const std::string& initial_pressure, double solids_fraction = 0.5) {
  const std::string bed = g_z < 0 ? "max = [1.0, 1.0, 0.05]\n" : "min = [-1.0, -1.0, 0.05]\n";
  return "[run]\nend_time = 0.1\n"
         "[physics]\ngravity = [0.0, 0.0, " + std::to_string(g_z) + "]\n"
         "[grid.x]\nmax = 0.02\ncells = 2\n[grid.y]\nmax = 0.02\ncells = 2\n"
         "[grid.z]\nmax = 0.1\ncells = 10\nratio = 2.0\n"
         "[output]\ndirectory = \"out\"\n"
         "[gas]\ndensity = 1.5\nreference_pressure = 1e5\ninitial_pressure = \"" +
         initial_pressure + "\"\n"
         "[solids]\ndensity = 2000.0\n[models.solids_stress]\nmodel = \"plastic\"\n"
         "[[initial]]\n" + bed + "solids_fraction = " + std::to_string(solids_fraction) + "\n";
}

// The face of the grid's z axis between the bed's layers and the gas's: the first face above a
// bed cell's centre (gravity −z) or below it (gravity +z).
double bed_surface(const Initialized& s, bool down_is_minus) {
  const auto& faces = s.domain.grid.axis(2).faces();
  for (std::size_t k = 0; k + 1 < faces.size(); ++k) {
    const double centre = 0.5 * (faces[k] + faces[k + 1]);
    if (down_is_minus && centre > 0.05) return faces[k];
    if (!down_is_minus && centre >= 0.05) return faces[k];
  }
  return faces.back();
}

TEST(InitialState, BedWeightPressureCarriesTheColumnAbove) {
  for (const double g : {-9.81, 9.81}) {
    const bool down_is_minus = g < 0;
    const Initialized s(bed_deck(g, "bed-weight"));
    const auto& layout = s.domain.layout;
    const double top = down_is_minus ? 0.1 : 0.0;  // where p = reference_pressure
    const double surface = bed_surface(s, down_is_minus);
    const double rho_g = 1.5, rho_s = 2000.0, phi = 0.5, weight = std::abs(g);
    // p at height z: p_ref + |g| ∫ (ε_g ρ_g + ε_s ρ_s) along the way up to the top.
    auto expected = [&](double z) {
      const double depth = std::abs(top - z);
      const double in_bed = down_is_minus ? std::max(0.0, surface - z) : std::max(0.0, z - surface);
      return 1e5 + weight * (rho_g * depth + phi * (rho_s - rho_g) * in_bed);
    };
    int fluid = 0;
    for (int l = 0; l < layout.local_count(); ++l) {
      if (layout.kind(l) != grid::CellKind::fluid) continue;
      ++fluid;
      const double z = s.domain.grid.centre(layout.index3(l))[2];
      EXPECT_NEAR(s.state.gas_pressure[static_cast<std::size_t>(l)], expected(z), 1e-9)
          << "g = " << g << ", z = " << z;
    }
    EXPECT_GT(fluid, 0);
    // At the floor (the lowest layer's centre plus its half layer's weight), the whole column's
    // weight per area: (gas + solids inventory) |g| / A.
    const auto inventory = run::phase_inventory(s.deck, s.domain, s.state);
    const double column = (inventory.gas + inventory.solids) * weight / (0.02 * 0.02);
    const auto& z_axis = s.domain.grid.axis(2);
    const int bottom = down_is_minus ? 0 : z_axis.cells() - 1;
    const double half = 0.5 * z_axis.width(bottom) * weight * (phi * rho_s + (1 - phi) * rho_g);
    for (int l = 0; l < layout.local_count(); ++l)
      if (layout.kind(l) == grid::CellKind::fluid && layout.index3(l)[2] == bottom) {
        EXPECT_NEAR(s.state.gas_pressure[static_cast<std::size_t>(l)] + half - 1e5, column,
                    1e-9 * column);
        EXPECT_GT(column, 0.5 * phi * rho_s * weight * 0.04);  // the bed, not the gas alone
      }
  }
}

TEST(InitialState, BedWeightWithoutSolidsIsTheGasWeight) {
  const Initialized bed(bed_deck(-9.81, "bed-weight", 0.0));
  const Initialized gas(bed_deck(-9.81, "gas-weight", 0.0));
  ASSERT_EQ(bed.domain.layout.local_count(), gas.domain.layout.local_count());
  for (int l = 0; l < bed.domain.layout.local_count(); ++l)
    EXPECT_NEAR(bed.state.gas_pressure[static_cast<std::size_t>(l)],
                gas.state.gas_pressure[static_cast<std::size_t>(l)], 1e-8)
        << "cell " << l << " (ring cells included)";
}

TEST(InitialState, GasWeightIgnoresTheSolids) {
  const Initialized s(bed_deck(-9.81, "gas-weight"));
  const auto& layout = s.domain.layout;
  for (int l = 0; l < layout.local_count(); ++l) {
    const double z = s.domain.grid.centre(layout.index3(l))[2];
    EXPECT_NEAR(s.state.gas_pressure[static_cast<std::size_t>(l)], 1e5 + 1.5 * 9.81 * (0.1 - z), 1e-9);
  }
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
