// bagnold run DECK: set up the domain and the initial state, write it, and advance to
// run.end_time. The flow solver arrives with issue 3; until then a run writes its initial state.
#include <cstdio>

#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/deck/load.hpp"
#include "src/io/monitor.hpp"
#include "src/parallel/domain_summary.hpp"
#include "src/run/initial_state.hpp"
#include "src/run/monitor_columns.hpp"
#include "src/run/output_writer.hpp"

namespace bagnold::app {

int run_command(const DeckArguments& args) {
  deck::Deck deck;
  try {
    deck = deck::load_deck(args.deck, args.overrides);
  } catch (const deck::DeckError& e) {
    say(std::string(e.what()) + "bagnold run: " + args.deck + " is not valid; nothing was run",
        true);
    return bad_input;
  }
  const parallel::Communicator comm;
  try {
    const parallel::Domain domain(deck, comm);
    const auto summary = parallel::summarize(domain);
    say("bagnold run: " + args.deck + "\n" +
        parallel::summary_text(domain, summary,
                               static_cast<int>(run::FlowState::field_names().size())));
    run::FlowState state(domain.layout.local_count());
    run::set_initial_state(deck, domain, state);
    run::OutputWriter output(deck, domain);
    io::Monitor monitor(output.directory() + "/monitor.csv", run::monitor_columns(domain.regions),
                        comm.is_root());
    const auto inventory = run::phase_inventory(deck, domain, state);
    std::vector<double> row = {0.0, 0.0, 0.0, inventory.gas, inventory.solids};
    row.resize(monitor.columns().size(), 0.0);
    monitor.append(0.0, row);
    const std::string path = output.write(state, 0.0, 0, deck.run.dt_initial);
    char line[256];
    std::snprintf(line, sizeof line, "initial state: solids %.6g kg, gas %.6g kg; wrote %s",
                  inventory.solids, inventory.gas, path.c_str());
    say(line);
    if (deck.run.end_time > 0.0) {
      say("bagnold run: this build has no flow solver yet (issue 3), so the run stops at t = 0 "
          "after writing the initial state",
          true);
    }
  } catch (const std::exception& e) {
    say(std::string("bagnold run: failed: ") + e.what(), true);
    return run_failed;
  }
  return success;
}

}  // namespace bagnold::app
