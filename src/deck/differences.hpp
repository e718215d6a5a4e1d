#pragma once
// The keys in which two resolved decks differ, each with both values as TOML text: what a
// restart lists when its deck is not the one its snapshot was written with.

#include <string>
#include <vector>

#include "src/deck/deck.hpp"

namespace bagnold::deck {

struct KeyDifference {
  std::string key;       // dotted, array elements indexed: "boundary[1].pressure"
  std::string recorded;  // TOML text; "(absent)" when that deck has no such key
  std::string current;
};

// Every key of the two decks' resolved text (load.hpp, resolved_text) whose value differs,
// compared exactly (doubles to the last bit), in key order.
std::vector<KeyDifference> differences(const Deck& recorded, const Deck& current);

}  // namespace bagnold::deck
