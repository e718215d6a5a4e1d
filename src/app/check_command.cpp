// bagnold check DECK: validate without running, print the resolved configuration and what the
// geometry builds (cells, boundary regions, partition on the current number of ranks).
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/deck/load.hpp"
#include "src/parallel/domain_summary.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::app {

int check_command(const DeckArguments& args) {
  deck::Deck deck;
  try {
    deck = deck::load_deck(args.deck, args.overrides);
  } catch (const deck::DeckError& e) {
    say(std::string(e.what()) + "bagnold check: " + args.deck + " is not valid (" +
            std::to_string(e.errors().size()) + " error" + (e.errors().size() == 1 ? "" : "s") + ")",
        true);
    return bad_input;
  }
  say(deck::resolved_text(deck));
  try {
    const parallel::Domain domain(deck, parallel::Communicator());
    const auto summary = parallel::summarize(domain);
    say("# Geometry\n" + parallel::summary_text(domain, summary,
                                                static_cast<int>(run::FlowState::field_names().size())));
    if (summary.fluid_cells == 0) {
      say("bagnold check: the geometry blocks every cell; nothing would flow", true);
      return bad_input;
    }
  } catch (const std::exception& e) {
    say(std::string("bagnold check: cannot build the geometry: ") + e.what(), true);
    return bad_input;
  }
  say("bagnold check: " + args.deck + " is valid");
  return success;
}

}  // namespace bagnold::app
