// Bad input never crashes: the shipped decks, mutated thousands of times (garbage bytes, deleted
// and repeated lines, values of the wrong type or out of range, truncation, missing sections),
// either load or fail with a DeckError that carries a message; no other exception escapes and
// nothing hangs. Decks that load also build their geometry when it is small enough, which either
// works or fails with a GeometryError that says why.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "src/deck/load.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::tests {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream s(text);
  for (std::string line; std::getline(s, line);) lines.push_back(line);
  return lines;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

const std::vector<std::string> wrong_values = {
    "-1", "0", "1e400", "-1e400", "nan", "inf", "\"text\"", "[1, 2]", "[]", "true", "{}",
    "9223372036854775807", "-0.0", "1e-320", "[\"a\", 1]", "2147483648", "\"\"", "[[1]]",
    "1979-05-27", "0x7fffffff"};

std::string mutate(const std::string& deck, std::mt19937& rng) {
  auto lines = lines_of(deck);
  std::uniform_int_distribution<std::size_t> pick_line(0, lines.size() - 1);
  switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
    case 0: {  // garbage bytes
      std::string text = deck;
      const int count = std::uniform_int_distribution<int>(1, 8)(rng);
      for (int i = 0; i < count; ++i)
        text[std::uniform_int_distribution<std::size_t>(0, text.size() - 1)(rng)] =
            static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
      return text;
    }
    case 1:  // a deleted line (a key or a section header)
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(pick_line(rng)));
      return joined(lines);
    case 2: {  // a repeated line
      const auto i = pick_line(rng);
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(i), lines[i]);
      return joined(lines);
    }
    case 3: {  // a value of the wrong type or range
      for (int attempt = 0; attempt < 20; ++attempt) {
        auto& line = lines[pick_line(rng)];
        const auto eq = line.find('=');
        if (eq == std::string::npos || line[0] == '#') continue;
        line = line.substr(0, eq + 1) + " " +
               wrong_values[std::uniform_int_distribution<std::size_t>(0, wrong_values.size() - 1)(rng)];
        break;
      }
      return joined(lines);
    }
    case 4:  // truncated
      return deck.substr(0, std::uniform_int_distribution<std::size_t>(0, deck.size())(rng));
    default: {  // a whole section removed
      std::vector<std::string> kept;
      bool skipping = false;
      const auto victim = pick_line(rng);
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (!lines[i].empty() && lines[i][0] == '[') skipping = i >= victim && !skipping && kept.size() >= victim;
        if (!skipping) kept.push_back(lines[i]);
      }
      return joined(kept);
    }
  }
}

TEST(DeckFuzz, MutatedShippedDecksLoadOrFailWithAMessage) {
  const std::string root = BAGNOLD_SOURCE_DIR;
  const std::vector<std::string> decks = {
      root + "/cases/bin/bin.toml", root + "/cases/hourglass/hourglass.toml",
      root + "/tests/verification/lid_driven_cavity/re100.toml",
      root + "/tests/verification/poiseuille/channel.toml"};
  std::mt19937 rng(20261122);  // fixed: the same 4000 mutations every run
  int loaded = 0, rejected = 0, built = 0;
  for (int round = 0; round < 1000; ++round) {
    for (const auto& path : decks) {
      const std::string text = mutate(read(path), rng);
      try {
        const auto deck = deck::load_deck_text(text, "mutated.toml");
        ++loaded;
        const auto cells = std::int64_t{deck.grid.x.cells} * deck.grid.y.cells * deck.grid.z.cells;
        if (cells <= 20000) {
          try {
            parallel::Domain domain(deck, parallel::Communicator());
            ++built;
          } catch (const grid::GeometryError& e) {
            ++rejected;  // e.g. every cell blocked: bad input, with a message
            ASSERT_FALSE(std::string(e.what()).empty());
          }
        }
      } catch (const deck::DeckError& e) {
        ++rejected;
        ASSERT_FALSE(std::string(e.what()).empty()) << text;
        ASSERT_FALSE(e.errors().empty()) << text;
      } catch (const std::exception& e) {
        FAIL() << "unexpected exception '" << e.what() << "' for the deck:\n" << text;
      }
    }
  }
  // Both outcomes occur, or the mutations are not exercising anything.
  EXPECT_GT(loaded, 100);
  EXPECT_GT(rejected, 1000);
  std::printf("fuzz: %d loaded (%d geometries built), %d rejected with a message\n", loaded, built,
              rejected);
}

}  // namespace
}  // namespace bagnold::tests
