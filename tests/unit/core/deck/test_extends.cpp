// `extends = "base.toml"`: a deck laid over a base deck (relative to the deck's own folder),
// with errors that still name the file and line they come from, a missing base and a cycle.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "src/deck/load.hpp"
#include "tests/unit/core/deck/deck_test_support.hpp"

namespace bagnold::tests {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, outside the working directory, so relative paths are only resolved
// against the deck's folder.
class DeckExtends : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    m_dir = fs::temp_directory_path() /
            ("bagnold_extends_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path path = m_dir / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
    return path.string();
  }

  fs::path m_dir;
};

const std::string base_text = deck_text(
    "[solids]\ndiameter = 2e-3\ndensity = 2600.0\n"
    "[[boundary]]\nname = \"orifice\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n",
    "title = \"base\"\nend_time = 2.0\n", "max = 0.5\ncells = 16\n");

TEST_F(DeckExtends, OverlaysKeyByKey) {
  write("base.toml", base_text);
  const auto path = write("rung.toml",
                          "extends = \"base.toml\"\n[run]\ntitle = \"rung\"\n"
                          "[grid.x]\ncells = 4\n[solids]\ndensity = 1500.0\n");
  const auto d = deck::load_deck(path);
  EXPECT_EQ(d.source, path);
  EXPECT_EQ(d.run.title, "rung");        // replaced
  EXPECT_EQ(d.run.end_time, 2.0);        // kept from the base, same table
  EXPECT_EQ(d.grid.x.cells, 4);          // replaced in a nested table
  EXPECT_EQ(d.grid.x.max, 0.5);          // kept in the same nested table
  EXPECT_EQ(d.solids.material.density, 1500.0);
  EXPECT_EQ(d.solids.material.diameter, 2e-3);
  ASSERT_EQ(d.boundaries.size(), 1u);    // arrays of tables come from the base when not given
  EXPECT_EQ(d.boundaries[0].name, "orifice");
}

TEST_F(DeckExtends, ArraysOfTablesReplaceTheBases) {
  write("base.toml", base_text);
  const auto path = write("rung.toml",
                          "extends = \"base.toml\"\n"
                          "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n"
                          "[[boundary]]\nname = \"lid\"\ntype = \"no_slip_wall\"\nface = \"x+\"\n");
  const auto d = deck::load_deck(path);
  ASSERT_EQ(d.boundaries.size(), 2u);
  EXPECT_EQ(d.boundaries[0].name, "top");
  EXPECT_EQ(d.boundaries[1].name, "lid");
}

TEST_F(DeckExtends, PathIsRelativeToTheDecksFolderAndChains) {
  write("common/root.toml", base_text);
  write("common/middle.toml", "extends = \"root.toml\"\n[grid.x]\ncells = 8\n");
  const auto path =
      write("cases/bin/leaf.toml", "extends = \"../../common/middle.toml\"\n[run]\nend_time = 0.5\n");
  const auto d = deck::load_deck(path);
  EXPECT_EQ(d.grid.x.cells, 8);
  EXPECT_EQ(d.run.end_time, 0.5);
  EXPECT_EQ(d.run.title, "base");
}

TEST_F(DeckExtends, AbsolutePath) {
  const auto base = write("elsewhere/base.toml", base_text);
  const auto path = write("rung.toml", "extends = \"" + base + "\"\n[grid.x]\ncells = 2\n");
  EXPECT_EQ(deck::load_deck(path).grid.x.cells, 2);
}

TEST_F(DeckExtends, OverridesApplyAfterTheOverlay) {
  write("base.toml", base_text);
  const auto path = write("rung.toml", "extends = \"base.toml\"\n[grid.x]\ncells = 4\n");
  const auto d = deck::load_deck(path, {"grid.x.cells=3", "boundary[0].pressure=9e4"});
  EXPECT_EQ(d.grid.x.cells, 3);
  EXPECT_EQ(d.boundaries[0].pressure, 9e4);
}

TEST_F(DeckExtends, MissingBaseFile) {
  const auto path = write("rung.toml", "# a rung\n\nextends = \"nowhere.toml\"\n[run]\ntitle = \"x\"\n");
  try {
    (void)deck::load_deck(path);
    FAIL() << "loaded a deck whose base does not exist";
  } catch (const deck::DeckError& e) {
    ASSERT_EQ(e.errors().size(), 1u) << e.what();
    const auto& d = e.errors()[0];
    EXPECT_EQ(d.key, "extends");
    EXPECT_EQ(d.file, path);
    EXPECT_EQ(d.line, 3);
    EXPECT_TRUE(contains(d.message, "cannot open the base deck")) << d.message;
    EXPECT_TRUE(contains(d.message, (m_dir / "nowhere.toml").string())) << d.message;
  }
}

TEST_F(DeckExtends, ExtendsMustBeAString) {
  const auto path = write("rung.toml", "extends = 3\n");
  try {
    (void)deck::load_deck(path);
    FAIL();
  } catch (const deck::DeckError& e) {
    ASSERT_EQ(e.errors().size(), 1u) << e.what();
    EXPECT_EQ(e.errors()[0].key, "extends");
    EXPECT_TRUE(contains(e.errors()[0].message, "expected a string")) << e.what();
  }
}

TEST_F(DeckExtends, CycleIsReported) {
  write("a.toml", "extends = \"b.toml\"\n");
  const auto b = write("b.toml", "extends = \"a.toml\"\n");
  const auto self = write("self.toml", "extends = \"self.toml\"\n");
  for (const auto& path : {b, self}) {
    try {
      (void)deck::load_deck(path);
      FAIL() << "a cycle of extends loaded";
    } catch (const deck::DeckError& e) {
      ASSERT_EQ(e.errors().size(), 1u) << e.what();
      EXPECT_EQ(e.errors()[0].key, "extends");
      EXPECT_TRUE(contains(e.errors()[0].message, "a cycle?")) << e.what();
    }
  }
}

TEST_F(DeckExtends, SyntaxErrorInTheBaseNamesTheBase) {
  const auto base = write("base.toml", "[run]\n\nend_time = \n");
  const auto path = write("rung.toml", "extends = \"base.toml\"\n");
  try {
    (void)deck::load_deck(path);
    FAIL();
  } catch (const deck::DeckError& e) {
    ASSERT_EQ(e.errors().size(), 1u) << e.what();
    EXPECT_EQ(e.errors()[0].file, base);
    EXPECT_EQ(e.errors()[0].line, 3);
    EXPECT_TRUE(contains(e.errors()[0].message, "TOML syntax error")) << e.what();
  }
}

TEST_F(DeckExtends, ErrorsNameTheFileAndLineTheyComeFrom) {
  // A misspelt key in the extending deck points at that deck's line; one in the base at the
  // base's line: bin-10mm.toml extends bin.toml and either may hold the typo.
  const auto base = write("base.toml", deck_text("[gas]\ndensty = 1.2\n"));
  const auto path = write("rung.toml", "extends = \"base.toml\"\n[grid.x]\ncells = 4\n"
                                       "[solids]\n\ndiametr = 1e-3\n");
  try {
    (void)deck::load_deck(path);
    FAIL();
  } catch (const deck::DeckError& e) {
    EXPECT_EQ(e.errors().size(), 2u) << e.what();
    const auto child = error_on(e.errors(), "solids.diametr");
    EXPECT_EQ(child.file, path) << e.what();
    EXPECT_EQ(child.line, 6) << e.what();
    EXPECT_EQ(child.column, 1) << e.what();
    EXPECT_TRUE(contains(child.message, "did you mean 'diameter'?")) << child.message;
    const auto in_base = error_on(e.errors(), "gas.densty");
    EXPECT_EQ(in_base.file, base) << e.what();
    EXPECT_EQ(in_base.line, line_of(deck_text("[gas]\ndensty = 1.2\n"), "densty")) << e.what();
  }
}

TEST_F(DeckExtends, BadValueInTheExtendingDeckPointsAtIt) {
  write("base.toml", base_text);
  const auto path = write("rung.toml", "extends = \"base.toml\"\n[grid.x]\ncells = -4\n");
  try {
    (void)deck::load_deck(path);
    FAIL();
  } catch (const deck::DeckError& e) {
    ASSERT_EQ(e.errors().size(), 1u) << e.what();
    EXPECT_EQ(e.errors()[0].key, "grid.x.cells");
    EXPECT_EQ(e.errors()[0].file, path) << e.what();
    EXPECT_EQ(e.errors()[0].line, 3) << e.what();
  }
}

TEST_F(DeckExtends, MissingDeckFile) {
  try {
    (void)deck::load_deck((m_dir / "absent.toml").string());
    FAIL();
  } catch (const deck::DeckError& e) {
    ASSERT_EQ(e.errors().size(), 1u);
    EXPECT_EQ(e.errors()[0].file, (m_dir / "absent.toml").string());
    EXPECT_EQ(e.errors()[0].line, 0);  // no position in a file that cannot be read
    EXPECT_EQ(e.errors()[0].to_string(),
              (m_dir / "absent.toml").string() + ": cannot open the deck file for reading");
    EXPECT_TRUE(contains(e.errors()[0].message, "cannot open")) << e.what();
  }
}

}  // namespace
}  // namespace bagnold::tests
