#pragma once
// Errors found while reading a deck, each with the file, line and column it points at.
// All errors of a deck are collected and reported together, so a user fixes them in one pass.

#include <toml++/toml.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "src/deck/deck.hpp"

namespace bagnold::deck {

struct Diagnostic {
  std::string file;  // deck path, or "--set" for a command-line override
  int line = 0;      // 0 when unknown
  int column = 0;
  std::string key;   // dotted path of the key, "" for the whole deck
  std::string message;

  std::string to_string() const;
};

class Diagnostics {
 public:
  void error(const toml::source_region& where, std::string key, std::string message);
  void error(const Origin& where, std::string key, std::string message);
  // Errors on this key (or below it) point at the override, whose value has no source position.
  void note_override(const std::string& key, const std::string& origin);
  // Where an error on `key`, written at `where`, points: the last --set of the key or of a table
  // above it; else, when --set changed keys below it (an error on a whole table, such as the
  // closure refusing [solids]), those --set arguments with the table's line in parentheses;
  // else `where`.
  Origin origin(const toml::source_region& where, const std::string& key) const;
  bool ok() const { return m_errors.empty(); }
  const std::vector<Diagnostic>& errors() const { return m_errors; }
  std::string report() const;  // one line per error

 private:
  std::vector<Diagnostic> m_errors;
  std::vector<std::pair<std::string, std::string>> m_overrides;  // key, "--set key=value"
};

// Thrown by load_deck when a deck has errors; what() is the full report.
class DeckError : public std::runtime_error {
 public:
  explicit DeckError(const Diagnostics& diagnostics)
      : std::runtime_error(diagnostics.report()), m_errors(diagnostics.errors()) {}
  const std::vector<Diagnostic>& errors() const { return m_errors; }

 private:
  std::vector<Diagnostic> m_errors;
};

}  // namespace bagnold::deck
