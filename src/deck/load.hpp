#pragma once
// Reading a deck: parse the TOML file, apply command-line overrides (--set key=value), check
// every key against the schema and fill a Deck. All errors are collected into one DeckError.

#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/deck/diagnostics.hpp"

namespace bagnold::deck {

// Loads and validates a deck; `overrides` are "dotted.key=value" strings (array elements as
// "boundary[1].type=..."). Throws DeckError listing every problem found.
Deck load_deck(const std::string& path, const std::vector<std::string>& overrides = {});

// Whether one of `overrides` sets `key` ("output.directory"), spaces around it ignored.
bool overrides_key(const std::vector<std::string>& overrides, const std::string& key);

// Same, from TOML text (tests, and the rheometer's --set-only material).
Deck load_deck_text(const std::string& text, const std::string& source_name,
                    const std::vector<std::string>& overrides = {});

// Only [solids] and [models], for the rheometer: other sections are not required.
Deck load_material_and_models(const std::string& path_or_empty,
                              const std::vector<std::string>& overrides);

// The resolved deck as TOML text (every key, defaults filled), for `bagnold check`.
std::string resolved_text(const Deck& deck);

// The key reference (docs/deck.md), generated from the declarations.
std::string key_reference_markdown();

}  // namespace bagnold::deck
