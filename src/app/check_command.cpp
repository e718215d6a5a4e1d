// bagnold check DECK: validate without running, print the resolved configuration and what the
// geometry builds (memory, cells, boundary regions, partition on the current number of ranks,
// every region's cells); refuse what `run` would refuse before running (src/app/preflight.hpp).
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/app/preflight.hpp"
#include "src/deck/load.hpp"

namespace bagnold::app {

namespace {
int not_valid(const std::string& report, std::size_t errors, const std::string& deck) {
  say(report + "bagnold check: " + deck + " is not valid (" + std::to_string(errors) + " error" +
          (errors == 1 ? "" : "s") + ")",
      true);
  return bad_input;
}
}  // namespace

int check_command(const DeckArguments& args) {
  deck::Deck deck;
  try {
    deck = deck::load_deck(args.deck, args.overrides);
  } catch (const deck::DeckError& e) {
    return not_valid(e.what(), e.errors().size(), args.deck);
  }
  say(deck::resolved_text(deck));
  try {
    const auto prepared = preflight(deck, parallel::Communicator());
    say(prepared.text);
    if (!prepared.errors.ok())
      return not_valid(prepared.errors.report(), prepared.errors.errors().size(), args.deck);
  } catch (const std::exception& e) {
    say(std::string("bagnold check: cannot build the geometry: ") + e.what(), true);
    return bad_input;
  }
  say("bagnold check: " + args.deck + " is valid");
  return success;
}

}  // namespace bagnold::app
