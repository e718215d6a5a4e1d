#include "src/app/output_directory.hpp"

#include <filesystem>
#include <functional>
#include <optional>

#include "src/app/exit_codes.hpp"
#include "src/deck/load.hpp"
#include "src/io/io_error.hpp"
#include "src/run/restart_deck.hpp"
#include "src/run/run_directory.hpp"

namespace bagnold::app {

namespace {

namespace fs = std::filesystem;

// Every rank returns bad_input when rank 0 decided `refuse`.
int verdict(bool refuse, const parallel::Communicator& comm) {
  return comm.max(std::int64_t{refuse ? 1 : 0}) ? bad_input : success;
}

// Runs `write` on rank 0; when it throws io::Hdf5Error every rank throws, so all stop together.
void on_root(const parallel::Communicator& comm, const std::function<void()>& write) {
  std::string problem;
  if (comm.is_root()) {
    try {
      write();
    } catch (const io::Hdf5Error& e) {
      problem = e.what();
    }
  }
  if (comm.max(std::int64_t{problem.empty() ? 0 : 1}))
    throw io::Hdf5Error(problem.empty() ? std::string("rank 0 could not write its files") : problem);
}

bool same_directory(const std::string& a, const std::string& b) {
  std::error_code ec;
  return fs::equivalent(a, b, ec);
}

// Rank 0: whether the restart may go on; says why not, or what --force lets through.
bool deck_matches_snapshot(const DeckArguments& args, const std::string& snapshot,
                           const deck::Deck& deck) {
  std::optional<std::string> recorded;
  try {
    recorded = io::read_text_attribute(snapshot, "deck");
  } catch (const io::Hdf5Error& e) {
    say(std::string("bagnold run: cannot restart: ") + e.what(), true);
    return false;
  }
  if (!recorded) {
    say("restart: " + snapshot + " records no deck (written by an older Bagnold); the deck is not "
        "compared with it");
    return true;
  }
  std::vector<deck::KeyDifference> conflicts;
  try {
    conflicts = run::restart_conflicts(*recorded, deck);
  } catch (const deck::DeckError& e) {
    say(std::string(e.what()) + "bagnold run: the deck recorded in " + snapshot +
            " does not load with this Bagnold" +
            (args.force ? "; restarting anyway (--force)" : "; --force restarts without comparing"),
        !args.force);
    return args.force;
  }
  if (conflicts.empty()) return true;
  std::string text = "bagnold run: the deck differs from the one " + snapshot +
                     " was written with, outside run control ([run], [output]):\n";
  for (const auto& c : conflicts)
    text += "  " + c.key + ": " + c.recorded + " in the snapshot, " + c.current + " now\n";
  text += args.force ? "bagnold run: restarting with the new values anyway (--force)"
                     : "bagnold run: a restart continues the same run, so nothing was run; give "
                       "--force to restart with these changes, or start a fresh run";
  say(text, !args.force);
  return args.force;
}

}  // namespace

int continue_run_directory(const DeckArguments& args, const std::string& snapshot,
                           deck::Deck& deck, const parallel::Communicator& comm) {
  if (!deck::overrides_key(args.overrides, "output.directory"))
    deck.output.directory = run::restart_directory(args.restart);
  const bool refuse = comm.is_root() && !deck_matches_snapshot(args, snapshot, deck);
  return verdict(refuse, comm);
}

DirectoryClaim claim_output_directory(const DeckArguments& args, const std::string& snapshot,
                                      const deck::Deck& deck, const parallel::Communicator& comm) {
  const std::string& directory = deck.output.directory;
  bool refuse = false;
  bool replace = false;
  if (comm.is_root()) {
    if (!snapshot.empty() && same_directory(run::restart_directory(args.restart), directory)) {
      // The continuation replaces the snapshots after the restart time itself (OutputWriter::resume).
      if (args.overwrite) {
        say("bagnold run: --overwrite would remove the snapshot this restart continues from (" +
                directory + " is its run directory); nothing was run",
            true);
        refuse = true;
      } else {
        say("restart: writing into " + directory +
            ", the snapshot's run directory (--set output.directory=DIR writes elsewhere)");
      }
    } else if (run::holds_run(directory)) {
      replace = args.overwrite;
      if (!replace) {
        say("bagnold run: the output directory " + directory +
                " already holds a run (snapshots or monitor.csv); nothing was run. Give --overwrite "
                "to remove that run's files first (snapshots, run.xmf, monitor.csv, run.toml, "
                "provenance.toml, diagnostic.h5), --restart " + directory +
                " to continue it, or another output.directory",
            true);
        refuse = true;
      }
    }
  }
  return {verdict(refuse, comm), comm.max(std::int64_t{replace ? 1 : 0}) != 0};
}

void remove_earlier_run(const deck::Deck& deck, const parallel::Communicator& comm) {
  on_root(comm, [&] {
    try {
      const auto removed = run::remove_run(deck.output.directory);
      say("bagnold run: --overwrite: removed the earlier run in " + deck.output.directory + " (" +
          std::to_string(removed.size()) + " files)");
    } catch (const std::exception& e) {  // io::Hdf5Error, or the file system's
      throw io::Hdf5Error(std::string("--overwrite: ") + e.what());
    }
  });
}

void record_run(const deck::Deck& deck, const run::Provenance& provenance,
                const parallel::Communicator& comm) {
  on_root(comm, [&] {
    run::write_run_record(deck.output.directory, deck::resolved_text(deck),
                          run::provenance_toml(provenance), !provenance.restart_from.empty());
  });
}

}  // namespace bagnold::app
