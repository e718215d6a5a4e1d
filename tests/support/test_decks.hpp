#pragma once
// Small decks for tests, built in code so each test states the geometry it relies on.

#include <string>

namespace bagnold::tests {

// A box of nx × ny × nz cells of 1 cm, gas only, with extra TOML appended (blocks, boundaries).
inline std::string box_deck(int nx, int ny, int nz, const std::string& extra = "") {
  auto n = [](int c) { return std::to_string(c); };
  auto len = [](int c) { return std::to_string(0.01 * c); };
  return "[run]\nend_time = 0.1\n"
         "[grid.x]\nmax = " + len(nx) + "\ncells = " + n(nx) + "\n"
         "[grid.y]\nmax = " + len(ny) + "\ncells = " + n(ny) + "\n"
         "[grid.z]\nmax = " + len(nz) + "\ncells = " + n(nz) + "\n"
         "[output]\ndirectory = \"out\"\n[solids]\nenabled = false\n" + extra;
}

}  // namespace bagnold::tests
