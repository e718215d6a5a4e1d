// docs/deck.md is generated from the key declarations (`bagnold keys`); this test fails when the
// file and the code disagree, so the documentation cannot drift from what the program accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "src/deck/load.hpp"

#ifndef BAGNOLD_DECK_REFERENCE
#error "BAGNOLD_DECK_REFERENCE (path of docs/deck.md) must be defined by the build"
#endif

namespace bagnold::tests {
namespace {

TEST(KeyReference, DocsDeckMdEqualsTheGeneratedReference) {
  std::ifstream in(BAGNOLD_DECK_REFERENCE, std::ios::binary);
  ASSERT_TRUE(in) << "cannot read " << BAGNOLD_DECK_REFERENCE;
  std::ostringstream file;
  file << in.rdbuf();
  const std::string expected = deck::key_reference_markdown();
  if (file.str() == expected) return;
  // Point at the first line that differs, then say how to fix it.
  std::istringstream a(file.str()), b(expected);
  std::string la, lb;
  int line = 0;
  while (true) {
    ++line;
    const bool more_a = static_cast<bool>(std::getline(a, la));
    const bool more_b = static_cast<bool>(std::getline(b, lb));
    if (!more_a && !more_b) break;
    if (la != lb || more_a != more_b) break;
  }
  FAIL() << BAGNOLD_DECK_REFERENCE << " is out of date with the key declarations; regenerate it "
         << "with `build/bagnold keys > docs/deck.md`.\nFirst difference at line " << line
         << ":\n  docs/deck.md: " << la << "\n  generated:    " << lb;
}

TEST(KeyReference, ListsEverySectionAndModel) {
  const std::string md = deck::key_reference_markdown();
  for (const std::string heading :
       {"## `[run]`", "## `[physics]`", "## `[grid]`", "## `[grid.x]`, `[grid.y]`, `[grid.z]`",
        "## `[geometry]`", "## `[[geometry.block]]`", "## `[[boundary]]`", "## `[gas]`",
        "## `[solids]`", "## `[models.solids_stress]`", "## `[models.solids_stress.mkt]`",
        "## `[[initial]]`", "## `[output]`"})
    EXPECT_NE(md.find(heading), std::string::npos) << heading;
  // A required key says so; a key with a default shows it as TOML.
  EXPECT_NE(md.find("| `end_time` | a real number | s | **required** | >= 0.0 |"),
            std::string::npos);
  EXPECT_NE(md.find("| `dt_initial` | a real number | s | 0.0001 | > 0.0 |"), std::string::npos);
}

}  // namespace
}  // namespace bagnold::tests
