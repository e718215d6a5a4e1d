#pragma once
// A deck loaded from text and the domain it builds on every rank, for tests of what is computed
// on a domain (the initial state, the regions' census).

#include <string>

#include "src/deck/load.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::tests {

struct DeckAndDomain {
  deck::Deck deck;
  parallel::Domain domain;
  explicit DeckAndDomain(const std::string& text)
      : deck(deck::load_deck_text(text, "t.toml")), domain(deck, parallel::Communicator()) {}
};

}  // namespace bagnold::tests
