// The resolved configuration (`bagnold check` prints it) is itself a valid deck holding the same
// values: loading it back gives an identical Deck, bit for bit, and the same text again.
#include <gtest/gtest.h>

#include "src/deck/load.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

void expect_same(const deck::Deck& a, const deck::Deck& b) {
  EXPECT_EQ(a.run.title, b.run.title);
  EXPECT_EQ(a.run.end_time, b.run.end_time);
  EXPECT_EQ(a.run.dt_initial, b.run.dt_initial);
  EXPECT_EQ(a.run.dt_min, b.run.dt_min);
  EXPECT_EQ(a.run.dt_max, b.run.dt_max);
  EXPECT_EQ(a.physics.gravity, b.physics.gravity);
  const deck::Axis* ax[] = {&a.grid.x, &a.grid.y, &a.grid.z};
  const deck::Axis* bx[] = {&b.grid.x, &b.grid.y, &b.grid.z};
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(ax[d]->min, bx[d]->min) << "axis " << d;
    EXPECT_EQ(ax[d]->max, bx[d]->max) << "axis " << d;
    EXPECT_EQ(ax[d]->cells, bx[d]->cells) << "axis " << d;
    EXPECT_EQ(ax[d]->ratio, bx[d]->ratio) << "axis " << d;
  }
  EXPECT_EQ(a.grid.periodic, b.grid.periodic);
  EXPECT_EQ(a.geometry.default_wall, b.geometry.default_wall);
  ASSERT_EQ(a.geometry.blocks.size(), b.geometry.blocks.size());
  for (std::size_t i = 0; i < a.geometry.blocks.size(); ++i) {
    const auto& p = a.geometry.blocks[i];
    const auto& q = b.geometry.blocks[i];
    EXPECT_EQ(p.shape, q.shape);
    EXPECT_EQ(p.blocks, q.blocks);
    EXPECT_EQ(p.min, q.min);
    EXPECT_EQ(p.max, q.max);
    EXPECT_EQ(p.point, q.point);
    EXPECT_EQ(p.normal, q.normal);
    EXPECT_EQ(p.base, q.base);
    EXPECT_EQ(p.axis, q.axis);
    EXPECT_EQ(p.length, q.length);
    EXPECT_EQ(p.radius, q.radius);
    EXPECT_EQ(p.top_radius, q.top_radius);
  }
  ASSERT_EQ(a.boundaries.size(), b.boundaries.size());
  for (std::size_t i = 0; i < a.boundaries.size(); ++i) {
    const auto& p = a.boundaries[i];
    const auto& q = b.boundaries[i];
    EXPECT_EQ(p.name, q.name);
    EXPECT_EQ(p.type, q.type);
    EXPECT_EQ(p.face, q.face);
    EXPECT_EQ(p.min, q.min);
    EXPECT_EQ(p.max, q.max);
    EXPECT_EQ(p.pressure, q.pressure);
    EXPECT_EQ(p.wall_velocity, q.wall_velocity);
    EXPECT_EQ(p.gas_velocity, q.gas_velocity);
    EXPECT_EQ(p.solids_velocity, q.solids_velocity);
    EXPECT_EQ(p.solids_fraction, q.solids_fraction);
  }
  EXPECT_EQ(a.gas.enabled, b.gas.enabled);
  EXPECT_EQ(a.gas.density, b.gas.density);
  EXPECT_EQ(a.gas.viscosity, b.gas.viscosity);
  EXPECT_EQ(a.gas.reference_pressure, b.gas.reference_pressure);
  EXPECT_EQ(a.solids.enabled, b.solids.enabled);
  EXPECT_EQ(a.solids.material.diameter, b.solids.material.diameter);
  EXPECT_EQ(a.solids.material.density, b.solids.material.density);
  EXPECT_EQ(a.solids.material.restitution, b.solids.material.restitution);
  EXPECT_EQ(a.solids.material.friction, b.solids.material.friction);
  EXPECT_EQ(a.solids.material.stiffness, b.solids.material.stiffness);
  EXPECT_EQ(a.solids.material.bond_number, b.solids.material.bond_number);
  EXPECT_EQ(a.models.solids_stress.name, b.models.solids_stress.name);
  EXPECT_EQ(a.models.solids_stress.coefficients, b.models.solids_stress.coefficients);
  ASSERT_EQ(a.initial.size(), b.initial.size());
  for (std::size_t i = 0; i < a.initial.size(); ++i) {
    EXPECT_EQ(a.initial[i].min, b.initial[i].min);
    EXPECT_EQ(a.initial[i].max, b.initial[i].max);
    EXPECT_EQ(a.initial[i].solids_fraction, b.initial[i].solids_fraction);
    EXPECT_EQ(a.initial[i].gas_velocity, b.initial[i].gas_velocity);
    EXPECT_EQ(a.initial[i].solids_velocity, b.initial[i].solids_velocity);
  }
  EXPECT_EQ(a.numerics.solids_bulk_viscosity_until, b.numerics.solids_bulk_viscosity_until);
  EXPECT_EQ(a.output.directory, b.output.directory);
  EXPECT_EQ(a.output.snapshot_interval, b.output.snapshot_interval);
  EXPECT_EQ(a.output.progress, b.output.progress);
}

void expect_round_trip(const deck::Deck& first) {
  const std::string text = deck::resolved_text(first);
  deck::Deck second;
  try {
    second = deck::load_deck_text(text, first.source);
  } catch (const deck::DeckError& e) {
    FAIL() << "the resolved text does not load:\n" << e.what() << "\n" << text;
  }
  expect_same(first, second);
  EXPECT_EQ(deck::resolved_text(second), text);
}

TEST(ResolvedText, MinimalDeckRoundTrips) {
  expect_round_trip(deck::load_deck_text(deck_text(), "deck.toml"));
}

TEST(ResolvedText, EverySectionRoundTrips) {
  const std::string tail =
      "[physics]\ngravity = [0.1, -0.2, -9.80665]\n"
      "[grid]\nperiodic = [\"x\", \"y\"]\n"
            "[geometry]\ndefault_wall = \"free_slip_wall\"\n"
      "[[geometry.block]]\nshape = \"box\"\nblocks = \"inside\"\nmin = [0.1, 0.1, 0.1]\n"
      "max = [0.2, 0.3, 0.4]\n"
      "[[geometry.block]]\nshape = \"half_space\"\npoint = [0.5, 0.0, 0.0]\nnormal = [1.0, 0.0, -1.0]\n"
      "[[geometry.block]]\nshape = \"cylinder\"\nblocks = \"outside\"\nbase = [0.5, 0.5, 0.0]\n"
      "axis = [0.0, 0.0, 1.0]\nlength = 1.0\nradius = 0.45\n"
      "[[geometry.block]]\nshape = \"cone\"\nblocks = \"outside\"\nbase = [0.5, 0.5, 0.4]\n"
      "axis = [0.0, 0.0, 1.0]\nlength = 0.2\nradius = 0.1\ntop_radius = 0.45\n"
      "[[boundary]]\nname = \"in\"\ntype = \"mass_inflow\"\nface = \"z+\"\nmin = [0.0, 0.0, 1.0]\n"
      "max = [0.5, 0.5, 2.0]\ngas_velocity = [0.0, 0.0, -0.5]\n"
      "solids_velocity = [0.0, 0.0, -0.25]\nsolids_fraction = 0.3\n"
      "[[boundary]]\nname = \"out\"\ntype = \"pressure_outflow\"\nface = \"z-\"\npressure = 9.5e4\n"
      "[[boundary]]\nname = \"hopper\"\ntype = \"moving_wall\"\nface = \"internal\"\n"
      "wall_velocity = [0.0, 1e-3, 0.0]\n"
      "[gas]\nenabled = false\ndensity = 1.3\nviscosity = 2e-5\nreference_pressure = 1e5\n"
      "[solids]\nenabled = true\ndiameter = 0.000875123456789012\ndensity = 2650.0\n"
      "restitution = 0.9\nfriction = 0.45\nstiffness = 2.5e6\nbond_number = 0.125\n"
      "[models.solids_stress]\nmodel = \"mkt\"\n[models.solids_stress.mkt]\nalpha_1 = 0.07\n"
      "psi_exponent = \"openfoam\"\n"
      "[[initial]]\nmax = [1.0, 1.0, 0.5]\nsolids_fraction = 0.58\n"
      "[[initial]]\nmin = [0.0, 0.0, 0.25]\nsolids_fraction = 0.1\ngas_velocity = [1.0, 2.0, 3.0]\n"
      "solids_velocity = [-1.0, -2.0, -3.0]\n";
  // Values that need more than 10 significant digits, and a title with characters TOML escapes.
  const auto first = deck::load_deck_text(
      deck_text(tail,
                "title = \"Bin \\\"2.5 mm\\\" \\\\ rung\\nsecond line\\tend\"\n"
                "end_time = 0.3333333333333333\ndt_initial = 1.2345678901234e-4\n"
                "dt_min = 1e-9\ndt_max = 0.02\n",
                "min = -0.1\nmax = 0.7000000000000001\ncells = 7\nratio = 0.25\n",
                "directory = \"runs/a \\\"b\\\"\"\nsnapshot_interval = 0.05\nprogress = \"always\"\n"),
      "deck.toml");
  ASSERT_EQ(first.run.title, "Bin \"2.5 mm\" \\ rung\nsecond line\tend");
  ASSERT_EQ(first.geometry.blocks.size(), 4u);
  ASSERT_EQ(first.boundaries.size(), 3u);
  expect_round_trip(first);
}

TEST(ResolvedText, OverriddenValuesAreInTheText) {
  const auto d = deck::load_deck_text(deck_text(), "deck.toml",
                                      {"solids.diameter=0.00123", "models.solids_stress.model=skt"});
  const auto text = deck::resolved_text(d);
  EXPECT_TRUE(contains(text, "diameter = 0.00123  # [m]\n")) << text;
  EXPECT_TRUE(contains(text, "[models.solids_stress.skt]\n")) << text;
  EXPECT_TRUE(contains(text, "# Resolved configuration of deck.toml")) << text;
  expect_round_trip(d);
}

}  // namespace
}  // namespace bagnold::tests
