// The deck schema: values read and defaults filled, and every error path, each asserted by the
// key it names, the line and column it points at and what it says (suggestion, expected type or
// range), so a message that loses its position or its way out fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "models/stress/solids_stress.hpp"
#include "models/wall/wall_law.hpp"
#include "src/deck/load.hpp"
#include "src/deck/sections.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

// ---------------------------------------------------------------------------------------------
// Values and defaults

TEST(DeckLoad, MinimalDeckGetsEveryDefault) {
  const auto d = deck::load_deck_text(deck_text(), "deck.toml");
  EXPECT_EQ(d.source, "deck.toml");
  EXPECT_EQ(d.run.title, "");
  EXPECT_EQ(d.run.end_time, 1.0);
  EXPECT_EQ(d.run.dt_initial, 1e-4);
  EXPECT_EQ(d.run.dt_min, 1e-7);
  EXPECT_EQ(d.run.dt_max, 1e-2);
  EXPECT_EQ(d.physics.gravity, (std::array<double, 3>{0.0, 0.0, -9.81}));
  EXPECT_EQ(d.grid.x.min, 0.0);
  EXPECT_EQ(d.grid.x.max, 1.0);
  EXPECT_EQ(d.grid.x.cells, 4);
  EXPECT_EQ(d.grid.x.ratio, 1.0);
  EXPECT_TRUE(d.grid.periodic.empty());
  EXPECT_EQ(d.geometry.default_wall, "no_slip_wall");
  EXPECT_TRUE(d.geometry.blocks.empty());
  EXPECT_TRUE(d.boundaries.empty());
  EXPECT_TRUE(d.gas.enabled);
  EXPECT_EQ(d.gas.density, 1.2);
  EXPECT_EQ(d.gas.viscosity, 1.8e-5);
  EXPECT_EQ(d.gas.reference_pressure, 101325.0);
  EXPECT_TRUE(d.solids.enabled);
  EXPECT_EQ(d.solids.material.diameter, 1e-3);
  EXPECT_EQ(d.solids.material.density, 2500.0);
  EXPECT_EQ(d.solids.material.restitution, 0.8);
  EXPECT_EQ(d.solids.material.friction, 0.3);
  EXPECT_EQ(d.models.solids_stress.name, "mkt");
  EXPECT_TRUE(d.initial.empty());
  EXPECT_EQ(d.output.directory, "out");
  EXPECT_EQ(d.output.snapshot_interval, 0.1);
  EXPECT_EQ(d.output.progress, "auto");
}

// A default is written once, as the struct's initializer (deck.hpp): the key reference shows
// that value, and a deck that leaves a table out gets exactly a default-constructed struct.
template <class T>
void expect_defaults_from(const deck::Section<T>& section, const T& prototype) {
  for (const auto& k : section.keys) {
    if (k.info.default_text.empty()) continue;  // required, or no default to show
    EXPECT_EQ(k.info.default_text, k.show(prototype)) << section.name << "." << k.info.name;
  }
}

TEST(DeckLoad, EveryDocumentedDefaultIsTheStructInitializer) {
  expect_defaults_from(deck::run_section(), deck::RunControl{});
  expect_defaults_from(deck::physics_section(), deck::Physics{});
  expect_defaults_from(deck::grid_section(), deck::Grid{});
  expect_defaults_from(deck::axis_section(), deck::Axis{});
  expect_defaults_from(deck::geometry_section(), deck::Geometry{});
  expect_defaults_from(deck::block_section(), deck::Block{});
  expect_defaults_from(deck::boundary_section(), deck::BoundaryRegion{});
  expect_defaults_from(deck::gas_section(), deck::Gas{});
  expect_defaults_from(deck::solids_section(), models::Material{});
  expect_defaults_from(deck::solids_switch_section(), deck::Solids{});
  expect_defaults_from(deck::solids_stress_section(), deck::Models{}.solids_stress);
  expect_defaults_from(deck::drag_section(), deck::Models{}.drag);
  expect_defaults_from(deck::initial_section(), deck::InitialRegion{});
  expect_defaults_from(deck::numerics_section(), deck::Numerics{});
  expect_defaults_from(deck::output_section(), deck::Output{});
  // Spot checks against the values themselves, so the test fails if both sides move together.
  EXPECT_EQ(deck::Numerics{}.max_outer_iterations, 40);
  EXPECT_EQ(deck::Models{}.drag.name, "gidaspow");
}

TEST(DeckLoad, SolidsWallChoicesAreTheWallLawRegistry) {
  // One list: adding a law to models/wall/ adds it to the deck.
  std::string expected = "one of: ";
  const auto names = models::wall::wall_law_registry().names();
  for (std::size_t i = 0; i < names.size(); ++i) expected += (i ? ", " : "") + names[i];
  int found = 0;
  for (const auto& k : deck::boundary_section().keys) {
    if (k.info.name != "solids_wall") continue;
    EXPECT_EQ(k.info.range, expected);
    ++found;
  }
  EXPECT_EQ(found, 1);
  EXPECT_EQ(names.size(), 4u);
}

TEST(DeckLoad, LeftOutTablesAreDefaultConstructed) {
  const auto d = deck::load_deck_text(deck_text(), "deck.toml");
  EXPECT_EQ(deck::show_section(deck::numerics_section(), d.numerics),
            deck::show_section(deck::numerics_section(), deck::Numerics{}));
  EXPECT_EQ(deck::show_section(deck::gas_section(), d.gas),
            deck::show_section(deck::gas_section(), deck::Gas{}));
  EXPECT_EQ(deck::show_section(deck::solids_section(), d.solids.material),
            deck::show_section(deck::solids_section(), models::Material{}));
  EXPECT_EQ(d.models.drag.name, deck::Models{}.drag.name);
}

TEST(DeckLoad, SelectedModelGetsEveryDeclaredCoefficient) {
  const auto d = deck::load_deck_text(
      deck_text("[models.solids_stress]\nmodel = \"mkt\"\n[models.solids_stress.mkt]\n"
                "psi_exponent = \"openfoam\"\nalpha_1 = 0.07\n"),
      "deck.toml");
  const auto& entry = models::stress_registry().find("mkt");
  ASSERT_FALSE(entry.coefficients.empty());
  for (const auto& spec : entry.coefficients)
    EXPECT_EQ(d.models.solids_stress.coefficients.count(spec.name), 1u) << spec.name;
  EXPECT_EQ(d.models.solids_stress.coefficients.size(), entry.coefficients.size());
  EXPECT_EQ(models::string_coefficient(d.models.solids_stress.coefficients, "psi_exponent"),
            "openfoam");
  EXPECT_EQ(models::real_coefficient(d.models.solids_stress.coefficients, "alpha_1"), 0.07);
}

TEST(DeckLoad, ReadsEverySectionsValues) {
  const std::string tail =
      "[physics]\ngravity = [0.5, -1.0, -9.0]\n"
      "[grid]\nperiodic = [\"y\"]\n"
      "[geometry]\ndefault_wall = \"free_slip_wall\"\n"
      "[[geometry.block]]\nshape = \"cone\"\nblocks = \"outside\"\nbase = [0.5, 0.5, 0.0]\n"
      "axis = [0.0, 0.0, 2.0]\nlength = 0.5\nradius = 0.1\ntop_radius = 0.4\n"
      "[[boundary]]\nname = \"out\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
      "min = [0.0, 0.0, -1.0]\nmax = [0.25, 1.0, 0.0]\npressure = 2e5\n"
      "[[boundary]]\nname = \"lid\"\ntype = \"moving_wall\"\nface = \"z+\"\n"
      "wall_velocity = [1.0, 0.0, 0.0]\n"
      "[gas]\nenabled = false\ndensity = 1.5\n"
      "[solids]\ndiameter = 2e-3\nfriction = 0.5\n"
      "[models.solids_stress]\nmodel = \"skt\"\n"
      "[[initial]]\nmax = [1.0, 1.0, 0.5]\nsolids_fraction = 0.55\n"
      "[[initial]]\nmin = [0.0, 0.0, 0.25]\nsolids_velocity = [0.0, 0.0, -1.0]\n";
  const auto d = deck::load_deck_text(
      deck_text(tail, "title = \"t\"\nend_time = 2.5\ndt_initial = 1e-3\n",
                "min = -1.0\nmax = 2.0\ncells = 12\nratio = 3.0\n",
                "directory = \"o\"\nsnapshot_interval = 0.25\nprogress = \"never\"\n"),
      "deck.toml");
  EXPECT_EQ(d.run.title, "t");
  EXPECT_EQ(d.run.end_time, 2.5);
  EXPECT_EQ(d.run.dt_initial, 1e-3);
  EXPECT_EQ(d.physics.gravity, (std::array<double, 3>{0.5, -1.0, -9.0}));
  EXPECT_EQ(d.grid.x.min, -1.0);
  EXPECT_EQ(d.grid.x.max, 2.0);
  EXPECT_EQ(d.grid.x.cells, 12);
  EXPECT_EQ(d.grid.x.ratio, 3.0);
  EXPECT_EQ(d.grid.periodic, std::vector<std::string>{"y"});
  EXPECT_FALSE(d.grid.is_periodic(0));
  EXPECT_TRUE(d.grid.is_periodic(1));
  EXPECT_FALSE(d.grid.is_periodic(2));
  EXPECT_EQ(d.geometry.default_wall, "free_slip_wall");
  ASSERT_EQ(d.geometry.blocks.size(), 1u);
  const auto& b = d.geometry.blocks[0];
  EXPECT_EQ(b.shape, "cone");
  EXPECT_EQ(b.blocks, "outside");
  EXPECT_EQ(b.base, (std::array<double, 3>{0.5, 0.5, 0.0}));
  EXPECT_EQ(b.axis, (std::array<double, 3>{0.0, 0.0, 2.0}));
  EXPECT_EQ(b.length, 0.5);
  EXPECT_EQ(b.radius, 0.1);
  EXPECT_EQ(b.top_radius, 0.4);
  ASSERT_EQ(d.boundaries.size(), 2u);
  EXPECT_EQ(d.boundaries[0].name, "out");
  EXPECT_EQ(d.boundaries[0].type, "pressure_outflow");
  EXPECT_EQ(d.boundaries[0].face, "z-");
  EXPECT_EQ(d.boundaries[0].max, (std::array<double, 3>{0.25, 1.0, 0.0}));
  EXPECT_EQ(d.boundaries[0].pressure, 2e5);
  EXPECT_EQ(d.boundaries[1].name, "lid");
  EXPECT_EQ(d.boundaries[1].wall_velocity, (std::array<double, 3>{1.0, 0.0, 0.0}));
  EXPECT_EQ(d.boundaries[1].pressure, 101325.0);  // default per element
  EXPECT_EQ(d.boundaries[1].min, (std::array<double, 3>{-1e30, -1e30, -1e30}));
  EXPECT_FALSE(d.gas.enabled);
  EXPECT_EQ(d.gas.density, 1.5);
  EXPECT_EQ(d.solids.material.diameter, 2e-3);
  EXPECT_EQ(d.solids.material.friction, 0.5);
  EXPECT_EQ(d.models.solids_stress.name, "skt");
  ASSERT_EQ(d.initial.size(), 2u);
  EXPECT_EQ(d.initial[0].solids_fraction, 0.55);
  EXPECT_EQ(d.initial[0].min, (std::array<double, 3>{-1e30, -1e30, -1e30}));
  EXPECT_EQ(d.initial[1].solids_fraction, 0.0);
  EXPECT_EQ(d.initial[1].solids_velocity, (std::array<double, 3>{0.0, 0.0, -1.0}));
  EXPECT_EQ(d.output.directory, "o");
  EXPECT_EQ(d.output.snapshot_interval, 0.25);
  EXPECT_EQ(d.output.progress, "never");
}

TEST(DeckLoad, IntegersAreAcceptedForReals) {
  const auto d = deck::load_deck_text(
      deck_text("[physics]\ngravity = [0, 0, -10]\n[gas]\ndensity = 2\n", "end_time = 3\n",
                "max = 2\ncells = 4\n"),
      "deck.toml");
  EXPECT_EQ(d.run.end_time, 3.0);
  EXPECT_EQ(d.grid.x.max, 2.0);
  EXPECT_EQ(d.physics.gravity, (std::array<double, 3>{0.0, 0.0, -10.0}));
  EXPECT_EQ(d.gas.density, 2.0);
}

TEST(DeckLoad, RangeEndsThatAreAllowed) {
  // at_least(0) takes 0; within(0, 1) takes both ends (e = 1 with a closure that allows it:
  // the kinetic ones need e < 1, which check_closure_material reports).
  const auto d = deck::load_deck_text(
      deck_text("[solids]\nrestitution = 1.0\nfriction = 0.0\n[models.solids_stress]\nmodel = \"plastic\"\n",
                "end_time = 0.0\n"),
      "deck.toml");
  EXPECT_EQ(d.run.end_time, 0.0);
  EXPECT_EQ(d.solids.material.restitution, 1.0);
  EXPECT_EQ(d.solids.material.friction, 0.0);
}

TEST(DeckLoad, WithoutSolidsTheModelTableIsOptional) {
  const auto d = deck::load_deck_text(deck_text("[solids]\nenabled = false\n"), "deck.toml");
  EXPECT_FALSE(d.solids.enabled);
}

// ---------------------------------------------------------------------------------------------
// TOML syntax

TEST(DeckErrors, SyntaxErrorNamesFileAndLine) {
  const std::string text = "[run]\nend_time = 1.0\ntitle = = \"x\"\n";
  const auto errors = errors_of(text, {}, "cases/broken.toml");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].file, "cases/broken.toml");
  EXPECT_EQ(errors[0].line, 3);
  EXPECT_GT(errors[0].column, 0);
  EXPECT_TRUE(contains(errors[0].message, "TOML syntax error")) << errors[0].message;
  EXPECT_EQ(errors[0].to_string().rfind("cases/broken.toml:3:", 0), 0u) << errors[0].to_string();
}

// ---------------------------------------------------------------------------------------------
// Unknown keys: file, line, column, and the closest valid key

TEST(DeckErrors, UnknownTopLevelTableSuggestsTheClosest) {
  const std::string text = deck_text("[ouptut]\nx = 1\n");
  const auto e = error_on(errors_of(text), "ouptut");
  EXPECT_EQ(e.file, "deck.toml");
  EXPECT_EQ(e.line, line_of(text, "[ouptut]"));
  EXPECT_TRUE(contains(e.message, "unknown key; did you mean 'output'?")) << e.message;
  EXPECT_TRUE(contains(e.message, "valid keys here:")) << e.message;
}

TEST(DeckErrors, UnknownTopLevelKeySuggestsTheClosest) {
  const std::string text = "extend = \"base.toml\"\n" + deck_text();
  const auto e = error_on(errors_of(text), "extend");
  EXPECT_EQ(e.line, 1);
  EXPECT_EQ(e.column, 1);
  EXPECT_TRUE(contains(e.message, "did you mean 'extends'?")) << e.message;
}

TEST(DeckErrors, UnknownKeyInASection) {
  const std::string text = deck_text("[solids]\ndensity = 2500.0\n  diametr = 1e-3\n");
  const auto e = error_on(errors_of(text), "solids.diametr");
  EXPECT_EQ(e.line, line_of(text, "diametr"));
  EXPECT_EQ(e.column, 3);
  EXPECT_TRUE(contains(e.message, "did you mean 'diameter'?")) << e.message;
  EXPECT_EQ(e.to_string().rfind("deck.toml:" + std::to_string(e.line) + ":3: solids.diametr: ", 0),
            0u)
      << e.to_string();
}

TEST(DeckErrors, UnknownKeyInANestedSection) {
  const std::string text = deck_text("", "end_time = 1.0\n", "max = 1.0\ncells = 4\nratoi = 2.0\n");
  const auto e = error_on(errors_of(text), "grid.x.ratoi");
  EXPECT_EQ(e.line, line_of(text, "ratoi"));
  EXPECT_TRUE(contains(e.message, "did you mean 'ratio'?")) << e.message;
}

// mfix-default's ε_g* has no default (MFIX's EP_STAR has none): selecting the model without it
// is an error at the model key's line that names the missing key; giving it is accepted.
TEST(DeckErrors, MfixDefaultWithoutPackedGasFractionNamesTheKey) {
  const std::string without = deck_text("[models.solids_stress]\nmodel = \"mfix-default\"\n");
  const auto e = error_on(errors_of(without), "models.solids_stress.mfix-default.packed_gas_fraction");
  EXPECT_EQ(e.line, line_of(without, "mfix-default"));
  EXPECT_TRUE(contains(e.message, "missing key required by model")) << e.message;
  const std::string with = deck_text(
      "[models.solids_stress]\nmodel = \"mfix-default\"\n[models.solids_stress.mfix-default]\n"
      "packed_gas_fraction = 0.42\n");
  EXPECT_NO_THROW((void)deck::load_deck_text(with, "deck.toml", {}));
}

// An initial solids fraction above the selected closure's packing limit is refused at the key:
// MKT at μ = 0.3 jams at φ_c = 0.596 (App. A Table I), the plastic closure at 1 − ε_g*. At the
// limit is accepted, and so is any fraction where the closure is not used (frozen solids).
TEST(DeckErrors, InitialFractionAbovePackingLimitNamesTheKey) {
  const std::string fill = "[solids]\nfriction = 0.3\n[[initial]]\nsolids_fraction = 0.5\n"
                           "[[initial]]\nsolids_fraction = 0.6\n";
  const std::string text = deck_text(fill);
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "initial[1].solids_fraction");
  EXPECT_EQ(e.line, line_of(text, "solids_fraction = 0.6"));
  EXPECT_TRUE(contains(e.message, "above the packing limit 0.596 of the closure "
                                  "models.solids_stress.model = \"mkt\"")) << e.message;
  EXPECT_NO_THROW((void)deck::load_deck_text(
      deck_text("[solids]\nfriction = 0.3\n[[initial]]\nsolids_fraction = 0.596\n"), "deck.toml"));
  const std::string plastic = "[models.solids_stress]\nmodel = \"plastic\"\n"
                              "[models.solids_stress.plastic]\npacked_gas_fraction = 0.45\n";
  EXPECT_NO_THROW((void)deck::load_deck_text(
      deck_text(plastic + "[[initial]]\nsolids_fraction = 0.55\n"), "deck.toml"));
  const auto over = error_on(errors_of(deck_text(plastic + "[[initial]]\nsolids_fraction = 0.56\n")),
                             "initial[0].solids_fraction");
  EXPECT_TRUE(contains(over.message, "packing limit 0.55 ")) << over.message;
  EXPECT_NO_THROW((void)deck::load_deck_text(
      deck_text("[solids]\nmomentum = false\n[[initial]]\nsolids_fraction = 0.7\n"), "deck.toml"));
}

// A value of the wrong type is echoed in the message, as the deck wrote it.
TEST(DeckErrors, WrongTypeEchoesTheValue) {
  const std::string text = deck_text("[solids]\ndiameter = \"big\"\n");
  const auto e = error_on(errors_of(text), "solids.diameter");
  EXPECT_TRUE(contains(e.message, "expected a real number")) << e.message;
  EXPECT_TRUE(contains(e.message, "got 'big'")) << e.message;
}

TEST(DeckErrors, UnknownKeyFarFromAnyGetsNoSuggestion) {
  const std::string text = deck_text("[gas]\nzzzzzzzzzz = 1.0\n");
  const auto e = error_on(errors_of(text), "gas.zzzzzzzzzz");
  EXPECT_TRUE(contains(e.message, "unknown key")) << e.message;
  EXPECT_FALSE(contains(e.message, "did you mean")) << e.message;
}

TEST(DeckErrors, UnknownKeyInAnArrayElementNamesTheElement) {
  const std::string text = deck_text(
      "[[boundary]]\nname = \"a\"\ntype = \"no_slip_wall\"\n"
      "[[boundary]]\nname = \"b\"\ntype = \"pressure_outflow\"\npresure = 1e5\n"
      "[[initial]]\nsolid_fraction = 0.5\n"
      "[[geometry.block]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n"
      "block = \"outside\"\n");
  const auto errors = errors_of(text);
  const auto b = error_on(errors, "boundary[1].presure");
  EXPECT_EQ(b.line, line_of(text, "presure"));
  EXPECT_TRUE(contains(b.message, "did you mean 'pressure'?")) << b.message;
  const auto i = error_on(errors, "initial[0].solid_fraction");
  EXPECT_EQ(i.line, line_of(text, "solid_fraction"));
  EXPECT_TRUE(contains(i.message, "did you mean 'solids_fraction'?")) << i.message;
  const auto g = error_on(errors, "geometry.block[0].block");
  EXPECT_EQ(g.line, line_of(text, "block = \"outside\""));
  EXPECT_TRUE(contains(g.message, "did you mean 'blocks'?")) << g.message;
}

TEST(DeckErrors, UnknownCoefficientOfTheSelectedModel) {
  const std::string text =
      deck_text("[models.solids_stress]\nmodel = \"mkt\"\n[models.solids_stress.mkt]\n"
                "psi_exponnt = \"report\"\n");
  const auto e = error_on(errors_of(text), "models.solids_stress.mkt.psi_exponnt");
  EXPECT_EQ(e.line, line_of(text, "psi_exponnt"));
  EXPECT_TRUE(contains(e.message, "did you mean 'psi_exponent'?")) << e.message;
}

TEST(DeckErrors, UnknownCoefficientOfAModelNotSelectedStillReported) {
  const std::string text =
      deck_text("[models.solids_stress]\nmodel = \"mkt\"\n[models.solids_stress.skt]\n"
                "radial_distributon = \"carnahan-starling\"\n");
  const auto e = error_on(errors_of(text), "models.solids_stress.skt.radial_distributon");
  EXPECT_EQ(e.line, line_of(text, "radial_distributon"));
  EXPECT_TRUE(contains(e.message, "did you mean 'radial_distribution'?")) << e.message;
}

TEST(DeckErrors, UnknownKeysUnderModels) {
  const std::string text =
      deck_text("[models.solid_stress]\nmodel = \"mkt\"\n[models.solids_stress]\nmodl = \"mkt\"\n");
  const auto errors = errors_of(text);
  const auto family = error_on(errors, "models.solid_stress");
  EXPECT_TRUE(contains(family.message, "did you mean 'solids_stress'?")) << family.message;
  const auto key = error_on(errors, "models.solids_stress.modl");
  EXPECT_EQ(key.line, line_of(text, "modl"));
  EXPECT_TRUE(contains(key.message, "did you mean 'model'?")) << key.message;
}

// ---------------------------------------------------------------------------------------------
// Wrong types: the message names what was expected, and the error points at the value

TEST(DeckErrors, WrongTypeOfReal) {
  const std::string text = deck_text("", "end_time = \"1 s\"\n");
  const auto e = error_on(errors_of(text), "run.end_time");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, column_of(text, "\"1 s\""));
  EXPECT_TRUE(contains(e.message, "expected a real number")) << e.message;
  EXPECT_TRUE(contains(e.message, "[s]")) << e.message;
}

TEST(DeckErrors, WrongTypeOfInteger) {
  const std::string text = deck_text("", "end_time = 1.0\n", "max = 1.0\ncells = 4.5\n");
  const auto e = error_on(errors_of(text), "grid.x.cells");
  EXPECT_EQ(e.line, line_of(text, "4.5"));
  EXPECT_TRUE(contains(e.message, "expected an integer")) << e.message;
}

TEST(DeckErrors, WrongTypeOfBool) {
  const std::string text = deck_text("[gas]\nenabled = 1\n");
  const auto e = error_on(errors_of(text), "gas.enabled");
  EXPECT_EQ(e.line, line_of(text, "enabled = 1"));
  EXPECT_TRUE(contains(e.message, "expected true or false")) << e.message;
}

TEST(DeckErrors, WrongTypeOfString) {
  const std::string text = deck_text("", "end_time = 1.0\n", "max = 1.0\ncells = 4\n",
                                     "directory = 42\n");
  const auto e = error_on(errors_of(text), "output.directory");
  EXPECT_EQ(e.line, line_of(text, "directory = 42"));
  EXPECT_TRUE(contains(e.message, "expected a string")) << e.message;
}

TEST(DeckErrors, WrongTypeOfArray3) {
  for (const std::string value : {"[0.0, -9.81]", "[0.0, 0.0, 0.0, -9.81]", "[0.0, \"a\", 1.0]",
                                  "-9.81"}) {
    const std::string text = deck_text("[physics]\ngravity = " + value + "\n");
    const auto e = error_on(errors_of(text), "physics.gravity");
    EXPECT_EQ(e.line, line_of(text, "gravity"));
    EXPECT_TRUE(contains(e.message, "expected an array of 3 real numbers")) << value << ": "
                                                                           << e.message;
  }
}

TEST(DeckErrors, WrongTypeOfStringList) {
  for (const std::string value : {"\"x\"", "[1, 2]"}) {
    const std::string text = deck_text("[grid]\nperiodic = " + value + "\n");
    const auto e = error_on(errors_of(text), "grid.periodic");
    EXPECT_EQ(e.line, line_of(text, "periodic"));
    EXPECT_TRUE(contains(e.message, "expected an array of strings")) << e.message;
  }
}

TEST(DeckErrors, WrongTypeOfTableAndArrayOfTables) {
  const std::string text = "gas = 3\nboundary = 4\n" + deck_text();
  const auto errors = errors_of(text);
  const auto gas = error_on(errors, "gas");
  EXPECT_EQ(gas.line, 1);
  EXPECT_TRUE(contains(gas.message, "expected a table")) << gas.message;
  const auto boundary = error_on(errors, "boundary");
  EXPECT_EQ(boundary.line, 2);
  EXPECT_TRUE(contains(boundary.message, "expected an array of tables")) << boundary.message;
}

TEST(DeckErrors, WrongTypeOfModelCoefficient) {
  const std::string text =
      deck_text("[models.solids_stress.mkt]\nalpha_1 = \"big\"\npsi_exponent = 2.0\n");
  const auto errors = errors_of(text);
  EXPECT_TRUE(contains(error_on(errors, "models.solids_stress.mkt.alpha_1").message,
                       "expected a real number"));
  EXPECT_TRUE(contains(error_on(errors, "models.solids_stress.mkt.psi_exponent").message,
                       "expected a string"));
}

// ---------------------------------------------------------------------------------------------
// Out of range

TEST(DeckErrors, OutOfRangeAbove) {
  const std::string text = deck_text("[gas]\ndensity = 0.0\n");
  const auto e = error_on(errors_of(text), "gas.density");
  EXPECT_EQ(e.line, line_of(text, "density = 0.0"));
  EXPECT_TRUE(contains(e.message, "value 0.0 is out of range")) << e.message;
  EXPECT_TRUE(contains(e.message, "> 0.0")) << e.message;
}

TEST(DeckErrors, OutOfRangeAtLeast) {
  const std::string text = deck_text("", "end_time = -1.0\n");
  const auto e = error_on(errors_of(text), "run.end_time");
  EXPECT_EQ(e.line, 2);
  EXPECT_TRUE(contains(e.message, "out of range")) << e.message;
  EXPECT_TRUE(contains(e.message, ">= 0.0")) << e.message;
}

// inf is a value only where the range closes on it ("for ever"): nowhere else, and nan never.
TEST(DeckLoad, InfinityOnlyWhereTheRangeClosesOnIt) {
  const auto d = deck::load_deck_text(deck_text("[numerics]\nsolids_bulk_viscosity_until = inf\n"), "deck.toml");
  EXPECT_TRUE(std::isinf(d.numerics.solids_bulk_viscosity_until));
  const std::string text = deck_text("[gas]\ndensity = inf\n[numerics]\nsolids_bulk_viscosity_until = nan\n");
  const auto errors = errors_of(text);
  EXPECT_TRUE(contains(error_on(errors, "gas.density").message, "value inf is out of range"));
  EXPECT_TRUE(contains(error_on(errors, "numerics.solids_bulk_viscosity_until").message, "out of range"));
}

TEST(DeckErrors, OutOfRangeWithin) {
  const std::string text = deck_text("[solids]\nrestitution = 1.5\n[[initial]]\nsolids_fraction = -0.1\n",
                                     "end_time = 1.0\n", "max = 1.0\ncells = 0\n");
  const auto errors = errors_of(text);
  const auto e = error_on(errors, "solids.restitution");
  EXPECT_EQ(e.line, line_of(text, "restitution"));
  EXPECT_TRUE(contains(e.message, "out of range")) << e.message;
  EXPECT_TRUE(contains(e.message, "in [0.0, 1.0]")) << e.message;
  EXPECT_TRUE(contains(error_on(errors, "initial[0].solids_fraction").message, "out of range"));
  EXPECT_TRUE(contains(error_on(errors, "grid.x.cells").message, "out of range"));
}

TEST(DeckErrors, OutOfRangeOneOf) {
  const std::string text = deck_text(
      "[geometry]\ndefault_wall = \"sticky\"\n[grid]\nperiodic = [\"x\", \"w\"]\n"
      "[[boundary]]\nname = \"a\"\ntype = \"outflow\"\n");
  const auto errors = errors_of(text);
  const auto wall = error_on(errors, "geometry.default_wall");
  EXPECT_EQ(wall.line, line_of(text, "sticky"));
  EXPECT_TRUE(contains(wall.message, "one of: no_slip_wall, free_slip_wall")) << wall.message;
  EXPECT_TRUE(contains(error_on(errors, "grid.periodic").message, "one of: x, y, z"));
  EXPECT_TRUE(contains(error_on(errors, "boundary[0].type").message, "pressure_outflow"));
}

TEST(DeckErrors, NonFiniteRealIsOutOfRange) {
  const auto e = error_on(errors_of(deck_text("[gas]\nviscosity = nan\n")), "gas.viscosity");
  EXPECT_TRUE(contains(e.message, "out of range")) << e.message;
}

TEST(DeckErrors, ModelCoefficientOutOfRangeOrUnknownChoice) {
  const std::string text =
      deck_text("[models.solids_stress.mkt]\ni0 = 100.0\npsi_exponent = \"opnfoam\"\n");
  const auto errors = errors_of(text);
  const auto range = error_on(errors, "models.solids_stress.mkt.i0");
  EXPECT_EQ(range.line, line_of(text, "i0"));
  EXPECT_TRUE(contains(range.message, "out of range")) << range.message;
  const auto choice = error_on(errors, "models.solids_stress.mkt.psi_exponent");
  EXPECT_TRUE(contains(choice.message, "did you mean \"openfoam\"?")) << choice.message;
}

// ---------------------------------------------------------------------------------------------
// Missing keys and tables

TEST(DeckErrors, MissingRequiredKey) {
  const std::string text = deck_text("", "title = \"no end\"\n");
  const auto e = error_on(errors_of(text), "run.end_time");
  EXPECT_EQ(e.file, "deck.toml");
  EXPECT_EQ(e.line, 1);  // the [run] table
  EXPECT_TRUE(contains(e.message, "missing required key")) << e.message;
  EXPECT_TRUE(contains(e.message, "[s]")) << e.message;
}

TEST(DeckErrors, MissingRequiredKeyOfAnArrayElement) {
  const std::string text = deck_text("[[boundary]]\nface = \"z-\"\n");
  const auto errors = errors_of(text);
  EXPECT_EQ(error_on(errors, "boundary[0].name").line, line_of(text, "[[boundary]]"));
  EXPECT_TRUE(contains(error_on(errors, "boundary[0].type").message, "missing required key"));
}

TEST(DeckErrors, MissingGridTable) {
  const std::string text = "[run]\nend_time = 1.0\n[output]\ndirectory = \"o\"\n";
  const auto e = error_on(errors_of(text), "grid");
  EXPECT_TRUE(contains(e.message, "missing required table [grid]")) << e.message;
}

TEST(DeckErrors, MissingGridAxis) {
  const std::string text =
      "[run]\nend_time = 1.0\n[grid.x]\nmax = 1.0\ncells = 2\n[grid.z]\nmax = 1.0\ncells = 2\n"
      "[output]\ndirectory = \"o\"\n";
  const auto errors = errors_of(text);
  EXPECT_TRUE(contains(error_on(errors, "grid.y.max").message, "missing required key"));
  EXPECT_TRUE(contains(error_on(errors, "grid.y.cells").message, "missing required key"));
}

TEST(DeckErrors, MissingOutputTable) {
  const std::string text = "[run]\nend_time = 1.0\n[grid.x]\nmax = 1.0\ncells = 2\n"
                           "[grid.y]\nmax = 1.0\ncells = 2\n[grid.z]\nmax = 1.0\ncells = 2\n";
  const auto e = error_on(errors_of(text), "output.directory");
  EXPECT_TRUE(contains(e.message, "missing required key")) << e.message;
  EXPECT_EQ(e.file, "deck.toml");
}

TEST(DeckErrors, MissingRunTable) {
  const std::string text = "[grid.x]\nmax = 1.0\ncells = 2\n[grid.y]\nmax = 1.0\ncells = 2\n"
                           "[grid.z]\nmax = 1.0\ncells = 2\n[output]\ndirectory = \"o\"\n";
  EXPECT_TRUE(contains(error_on(errors_of(text), "run.end_time").message, "missing required key"));
}

// ---------------------------------------------------------------------------------------------
// Checks across keys

TEST(DeckErrors, GridMaxNotAboveMin) {
  for (const std::string axis : {"min = 1.0\nmax = 1.0\ncells = 2\n",
                                 "min = 1.0\nmax = 0.5\ncells = 2\n"}) {
    const std::string text = deck_text("", "end_time = 1.0\n", axis);
    const auto e = error_on(errors_of(text), "grid.x.max");
    EXPECT_EQ(e.line, line_of(text, "max = "));
    EXPECT_TRUE(contains(e.message, "must be greater than grid.x.min (1.0)")) << e.message;
  }
}

TEST(DeckErrors, TimeStepsOutOfOrder) {
  for (const std::string run : {"end_time = 1.0\ndt_min = 1e-3\ndt_initial = 1e-4\n",
                                "end_time = 1.0\ndt_initial = 0.1\ndt_max = 0.01\n"}) {
    const std::string text = deck_text("", run);
    const auto e = error_on(errors_of(text), "run");
    EXPECT_EQ(e.line, 1);
    EXPECT_TRUE(contains(e.message, "expected dt_min <= dt_initial <= dt_max")) << e.message;
  }
  // Equal is allowed.
  EXPECT_NO_THROW(deck::load_deck_text(
      deck_text("", "end_time = 1.0\ndt_min = 1e-3\ndt_initial = 1e-3\ndt_max = 1e-3\n"), "d"));
}

TEST(DeckErrors, BlockShapeKeyMissing) {
  const std::string text = deck_text(
      "[[geometry.block]]\nshape = \"cone\"\nbase = [0.0, 0.0, 0.0]\naxis = [0.0, 0.0, 1.0]\n"
      "length = 1.0\nradius = 0.5\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "geometry.block[0].top_radius");
  EXPECT_EQ(e.line, line_of(text, "[[geometry.block]]"));
  EXPECT_TRUE(contains(e.message, "missing key required by shape \"cone\"")) << e.message;
}

TEST(DeckErrors, BlockShapeKeyNotApplicable) {
  const std::string text = deck_text(
      "[[geometry.block]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n"
      "[[geometry.block]]\nshape = \"half_space\"\npoint = [0.0, 0.0, 0.5]\n"
      "normal = [0.0, 0.0, 1.0]\nradius = 0.2\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "geometry.block[1].radius");
  EXPECT_EQ(e.line, line_of(text, "radius"));
  EXPECT_TRUE(contains(e.message, "does not apply to shape \"half_space\"")) << e.message;
  EXPECT_TRUE(contains(e.message, "point, normal")) << e.message;
}

TEST(DeckErrors, QuadricMatrixAndRangeAreChecked) {
  const std::string text = deck_text(
      "[[geometry.block]]\nshape = \"quadric\"\nblocks = \"outside\"\n"
      "matrix = [1.0, 1.0, 1.0, 1.0]\nconstant = -0.25\nalong = \"z\"\nrange = [0.5, 0.2]\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 2u) << report_of(errors);
  const auto m = error_on(errors, "geometry.block[0].matrix");
  EXPECT_EQ(m.line, line_of(text, "matrix"));
  EXPECT_TRUE(contains(m.message, "3 entries (the diagonal of A) or 9")) << m.message;
  const auto r = error_on(errors, "geometry.block[0].range");
  EXPECT_EQ(r.line, line_of(text, "range"));
  EXPECT_TRUE(contains(r.message, "lower < upper")) << r.message;
}

TEST(DeckErrors, QuadricNeedsARangeButNotACentre) {
  const std::string text = deck_text(
      "[[geometry.block]]\nshape = \"quadric\"\nmatrix = [1.0, 1.0, 1.0]\n"
      "constant = -0.25\nalong = \"z\"\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "geometry.block[0].range");
  EXPECT_TRUE(contains(e.message, "missing key required by shape \"quadric\"")) << e.message;
  const auto d = deck::load_deck_text(deck_text(
      "[[geometry.block]]\nshape = \"quadric\"\nmatrix = [4.0, 4.0, 4.0]\n"
      "constant = -1.0\nalong = \"x\"\nrange = [0.0, 1.0]\nlinear = [0.0, 0.0, 1.0]\n"), "d");
  ASSERT_EQ(d.geometry.blocks.size(), 1u);
  const auto& b = d.geometry.blocks[0];
  EXPECT_EQ(b.centre, (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(b.linear, (std::array<double, 3>{0.0, 0.0, 1.0}));
  EXPECT_EQ(b.matrix, (std::vector<double>{4.0, 4.0, 4.0}));
  EXPECT_EQ(b.along, "x");
  EXPECT_EQ(b.range, (std::vector<double>{0.0, 1.0}));
}

TEST(DeckErrors, BlockUnknownShape) {
  const std::string text = deck_text("[[geometry.block]]\nshape = \"sphere\"\nradius = 1.0\n");
  const auto e = error_on(errors_of(text), "geometry.block[0].shape");
  EXPECT_TRUE(contains(e.message, "one of: box, half_space, cylinder, cone, quadric")) << e.message;
}

TEST(DeckErrors, DuplicateBoundaryNames) {
  const std::string text = deck_text(
      "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n"
      "[[boundary]]\nname = \"side\"\ntype = \"free_slip_wall\"\nface = \"x-\"\n"
      "[[boundary]]\nname = \"top\"\ntype = \"pressure_inflow\"\nface = \"z-\"\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].key, "boundary[2].name");
  EXPECT_EQ(errors[0].line, line_of(text, "[[boundary]]\nname = \"top\"\ntype = \"pressure_inflow\""));
  EXPECT_TRUE(contains(errors[0].message, "duplicate boundary name \"top\"")) << errors[0].message;
}

TEST(DeckErrors, BoundaryOnAPeriodicFace) {
  const std::string text = deck_text(
      "[grid]\nperiodic = [\"y\"]\n"
      "[[boundary]]\nname = \"a\"\ntype = \"no_slip_wall\"\nface = \"x-\"\n"
      "[[boundary]]\nname = \"b\"\ntype = \"no_slip_wall\"\nface = \"y+\"\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  EXPECT_EQ(errors[0].key, "boundary[1].face");
  EXPECT_TRUE(contains(errors[0].message, "face y+ is periodic")) << errors[0].message;
}

TEST(DeckErrors, UnknownModelSuggestsTheClosest) {
  const std::string text = deck_text("[models.solids_stress]\nmodel = \"mtk\"\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "models.solids_stress.model");
  EXPECT_EQ(e.line, line_of(text, "mtk"));
  EXPECT_EQ(e.column, column_of(text, "\"mtk\""));
  EXPECT_TRUE(contains(e.message, "unknown model \"mtk\"; did you mean \"mkt\"?")) << e.message;
  for (const auto& name : models::stress_registry().names())
    EXPECT_TRUE(contains(e.message, name)) << "known models list misses " << name;
}

TEST(DeckErrors, UnknownModelIsAnErrorEvenWithoutSolids) {
  const std::string text =
      deck_text("[solids]\nenabled = false\n[models.solids_stress]\nmodel = \"nonsense\"\n");
  EXPECT_TRUE(contains(error_on(errors_of(text), "models.solids_stress.model").message,
                       "unknown model \"nonsense\""));
}

// ---------------------------------------------------------------------------------------------
// All errors of a deck are reported together

TEST(DeckErrors, EveryErrorIsCollected) {
  const std::string text = deck_text(
      "[solids]\ndiametr = 1e-3\n[gas]\ndensity = -1.0\n"
      "[models.solids_stress]\nmodel = \"mtk\"\n",
      "end_time = \"soon\"\n", "max = 1.0\ncells = 2.5\n");
  try {
    (void)deck::load_deck_text(text, "many.toml");
    FAIL() << "the deck loaded";
  } catch (const deck::DeckError& e) {
    const auto& errors = e.errors();
    EXPECT_EQ(errors.size(), 5u) << e.what();
    for (const std::string key : {"run.end_time", "grid.x.cells", "solids.diametr", "gas.density",
                                  "models.solids_stress.model"}) {
      const auto d = error_on(errors, key);
      EXPECT_TRUE(contains(e.what(), d.to_string() + "\n")) << key;
    }
    // One line per error.
    const std::string report = e.what();
    EXPECT_EQ(std::count(report.begin(), report.end(), '\n'), static_cast<long>(errors.size()));
  }
}

// ---------------------------------------------------------------------------------------------
// Fluidized-bed options: gas.initial_pressure and [[pressure_probe]]

TEST(DeckLoad, PressureProbesAndBedWeightPressure) {
  const auto d = deck::load_deck_text(
      deck_text("[gas]\ninitial_pressure = \"bed-weight\"\n"
                "[[pressure_probe]]\nname = \"bed\"\nlower = [0.5, 0.5, 0.1]\nupper = [0.5, 0.5, 0.9]\n"
                "[[pressure_probe]]\nname = \"wall\"\nlower = [0.1, 0.5, 0.1]\n"
                "upper = [0.1, 0.5, 0.3]\naverage = \"cell\"\n"),
      "deck.toml");
  EXPECT_EQ(d.gas.initial_pressure, "bed-weight");
  ASSERT_EQ(d.pressure_probes.size(), 2u);
  EXPECT_EQ(d.pressure_probes[0].name, "bed");
  EXPECT_EQ(d.pressure_probes[0].average, "layer");
  EXPECT_EQ(d.pressure_probes[0].upper, (std::array<double, 3>{0.5, 0.5, 0.9}));
  EXPECT_EQ(d.pressure_probes[1].average, "cell");
  EXPECT_EQ(deck::load_deck_text(deck_text(), "deck.toml").gas.initial_pressure, "gas-weight");
}

TEST(DeckErrors, BedWeightPressureNeedsGravityAlongOneAxis) {
  const std::string text =
      deck_text("[physics]\ngravity = [1.0, 0.0, -9.81]\n[gas]\ninitial_pressure = \"bed-weight\"\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "gas.initial_pressure");
  EXPECT_EQ(e.line, line_of(text, "initial_pressure"));
  EXPECT_TRUE(contains(e.message, "needs gravity along one axis")) << e.message;
}

TEST(DeckErrors, PartitionByLayersNeedsGravityAlongOneAxisAndNoRepartition) {
  const std::string text = deck_text(
      "[physics]\ngravity = [1.0, 0.0, -9.81]\n"
      "[numerics]\npartition_weights = \"layers\"\nrepartition_imbalance = 0.2\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 2u) << report_of(errors);
  const auto weights = error_on(errors, "numerics.partition_weights");
  EXPECT_EQ(weights.line, line_of(text, "partition_weights"));
  EXPECT_TRUE(contains(weights.message, "needs gravity along one axis")) << weights.message;
  const auto repartition = error_on(errors, "numerics.repartition_imbalance");
  EXPECT_EQ(repartition.line, line_of(text, "repartition_imbalance"));
  EXPECT_TRUE(contains(repartition.message, "does not depend on the state")) << repartition.message;
  EXPECT_EQ(deck::load_deck_text(deck_text("[numerics]\npartition_weights = \"layers\"\n"), "deck.toml")
                .numerics.partition_weights,
            "layers");
}

TEST(DeckErrors, LayerProbeNeedsTheGravityAxisNotPeriodic) {
  const std::string text = deck_text(
      "[grid]\nperiodic = [\"z\"]\n"
      "[[pressure_probe]]\nname = \"bed\"\nlower = [0.5, 0.5, 0.1]\nupper = [0.5, 0.5, 0.9]\n");
  const auto errors = errors_of(text);
  ASSERT_EQ(errors.size(), 1u) << report_of(errors);
  const auto e = error_on(errors, "pressure_probe[0].average");
  EXPECT_EQ(e.line, line_of(text, "[[pressure_probe]]"));
  EXPECT_TRUE(contains(e.message, "not periodic")) << e.message;
}

TEST(DeckErrors, PressureProbeNamesAndPoints) {
  const std::string text = deck_text(
      "[[pressure_probe]]\nname = \"a\"\nlower = [0.5, 0.5, 0.1]\nupper = [0.5, 0.5, 0.9]\n"
      "[[pressure_probe]]\nname = \"a\"\nlower = [0.5, 0.5, 0.1]\nupper = [0.5, 0.5]\n"
      "[[pressure_probe]]\nname = \"c\"\nupper = [0.5, 0.5, 0.9]\naverage = \"plane\"\n");
  const auto errors = errors_of(text);
  EXPECT_TRUE(contains(error_on(errors, "pressure_probe[1].name").message,
                       "duplicate pressure probe name \"a\""));
  EXPECT_EQ(error_on(errors, "pressure_probe[1].upper").line, line_of(text, "upper = [0.5, 0.5]\n"));
  EXPECT_TRUE(contains(error_on(errors, "pressure_probe[2].lower").message, "missing"))
      << report_of(errors);
  EXPECT_TRUE(contains(error_on(errors, "pressure_probe[2].average").message, "layer"))
      << report_of(errors);
}

}  // namespace
}  // namespace bagnold::tests
