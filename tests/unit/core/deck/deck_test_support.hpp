#pragma once
// Helpers of the deck tests: a minimal valid deck with replaceable parts, and lookups of the
// errors a deck produces by their key, so each test asserts the exact key, line and message.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "src/deck/load.hpp"

namespace bagnold::tests {

// [run], [grid.x] and [output] are the parts tests vary; `tail` appends more sections.
inline std::string deck_text(const std::string& tail = "",
                             const std::string& run = "end_time = 1.0\n",
                             const std::string& x = "max = 1.0\ncells = 4\n",
                             const std::string& output = "directory = \"out\"\n") {
  return "[run]\n" + run + "[grid.x]\n" + x +
         "[grid.y]\nmax = 1.0\ncells = 4\n"
         "[grid.z]\nmax = 1.0\ncells = 4\n"
         "[output]\n" + output + tail;
}

// 1-based line and column of the first occurrence of `needle` in `text` (after `from`).
inline int line_of(const std::string& text, const std::string& needle, std::size_t from = 0) {
  const auto at = text.find(needle, from);
  EXPECT_NE(at, std::string::npos) << needle;
  int line = 1;
  for (std::size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}
inline int column_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  const auto newline = text.rfind('\n', at);
  return static_cast<int>(newline == std::string::npos ? at + 1 : at - newline);
}

// The errors of a deck that must not load; a failure when it loads.
inline std::vector<deck::Diagnostic> errors_of(const std::string& text,
                                               const std::vector<std::string>& overrides = {},
                                               const std::string& name = "deck.toml") {
  try {
    (void)deck::load_deck_text(text, name, overrides);
  } catch (const deck::DeckError& e) {
    EXPECT_FALSE(e.errors().empty());
    EXPECT_EQ(std::string(e.what()).empty(), false);
    return e.errors();
  }
  ADD_FAILURE() << "the deck loaded, but errors were expected:\n" << text;
  return {};
}

inline std::string report_of(const std::vector<deck::Diagnostic>& errors) {
  std::string out;
  for (const auto& e : errors) out += e.to_string() + "\n";
  return out;
}

// The error on `key`; a failure (and an empty diagnostic) when there is none.
inline deck::Diagnostic error_on(const std::vector<deck::Diagnostic>& errors,
                                 const std::string& key) {
  for (const auto& e : errors)
    if (e.key == key) return e;
  ADD_FAILURE() << "no error on key '" << key << "'; errors:\n" << report_of(errors);
  return {};
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace bagnold::tests
