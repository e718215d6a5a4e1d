// bagnold run DECK: set up the domain and the initial state, write it, and advance to
// run.end_time. Gas-only decks (solids.enabled = false) run the SIMPLE gas solver; the
// two-fluid solver arrives with issue 4, until then a deck with solids writes its initial state.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "solver/time_loop.hpp"
#include "src/run/progress.hpp"
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
    solver::PetscSession petsc(nullptr, nullptr);
    if (!args.petsc_options.empty())
      solver::petsc_check(PetscOptionsInsertString(nullptr, args.petsc_options.c_str()),
                          "PetscOptionsInsertString");
    if (deck.solids.enabled) {
      const auto inventory = run::phase_inventory(deck, domain, state);
      monitor.append(0.0, std::vector<double>(monitor.columns().size(), 0.0));
      const std::string path = output.write(state, 0.0, 0, deck.run.dt_initial);
      say(fmt::format("initial state: solids {:.6g} kg, gas {:.6g} kg; wrote {}", inventory.solids,
                      inventory.gas, path));
      say("bagnold run: this build has no two-fluid solver yet (issue 4); a deck with solids "
          "stops at t = 0 after writing its initial state",
          true);
      return success;
    }
    solver::GasSolver gas(deck, domain);
    gas.apply_boundary_values(state);
    output.write(state, 0.0, 0, deck.run.dt_initial);
    run::ProgressLine progress(deck.output.progress, comm.is_root(), deck.run.end_time, 0.0);
    const solver::TimeLoopContext context{deck, domain, output, monitor, progress,
                                          [](const std::string& line) { say(line); }};
    const auto started = std::chrono::steady_clock::now();
    const auto result = solver::run_time_loop(context, gas, state, 0.0, 0);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    say(fmt::format("bagnold run: t = {:.6g} s after {} steps ({} redone), {:.2f} outer iterations "
                    "per step, {:.1f} s wall",
                    result.time, result.steps, result.redone_steps,
                    result.steps ? static_cast<double>(result.outer_iterations) / static_cast<double>(result.steps) : 0.0,
                    wall));
    if (!result.completed) {
      say("bagnold run: failed: " + result.failure, true);
      return run_failed;
    }
  } catch (const std::exception& e) {
    say(std::string("bagnold run: failed: ") + e.what(), true);
    return run_failed;
  }
  return success;
}

}  // namespace bagnold::app
