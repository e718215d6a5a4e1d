#include "src/run/restart_deck.hpp"

#include "src/deck/load.hpp"

namespace bagnold::run {

bool is_run_control(const std::string& key) {
  return key.starts_with("run.") || key.starts_with("output.") ||
         key == "numerics.partition_weights";
}

std::vector<deck::KeyDifference> restart_conflicts(const std::string& recorded_deck,
                                                   const deck::Deck& current) {
  const deck::Deck recorded = deck::load_deck_text(recorded_deck, "the snapshot's deck");
  auto out = deck::differences(recorded, current);
  std::erase_if(out, [](const deck::KeyDifference& d) { return is_run_control(d.key); });
  return out;
}

}  // namespace bagnold::run
