#pragma once
// Where `bagnold run` writes, and whether it may (docs/reliability.md, "Run directories"):
//
//   1. A restart continues in its snapshot's run directory (the directory given to --restart,
//      or the snapshot file's) unless the command line sets output.directory with --set.
//   2. A restart's resolved deck must be the one its snapshot was written with, outside run
//      control (run/restart_deck.hpp): the differing keys are listed with both values and the
//      restart refused unless --force.
//   3. Runs never mix: a fresh run, or a restart writing somewhere other than its snapshot's
//      directory, into a directory that already holds a run refuses unless --overwrite, which
//      first removes that run's files (run/run_directory.hpp) and nothing else.
//
// Each step is collective: rank 0 looks at the files and says why it refuses, every rank gets
// the verdict (success or bad_input, exit_codes.hpp).

#include <string>

#include "src/app/commands.hpp"
#include "src/deck/deck.hpp"
#include "src/parallel/communicator.hpp"
#include "src/run/provenance.hpp"

namespace bagnold::app {

// Steps 1 and 2, for a restart from `snapshot`: sets deck.output.directory.
int continue_run_directory(const DeckArguments& args, const std::string& snapshot,
                           deck::Deck& deck, const parallel::Communicator& comm);

// Step 3; `snapshot` is empty for a fresh run. `replace`: --overwrite met an earlier run, which
// remove_earlier_run removes once the run is set up (a deck or restart that fails later keeps it).
struct DirectoryClaim {
  int code = 0;  // success or bad_input
  bool replace = false;
};
DirectoryClaim claim_output_directory(const DeckArguments& args, const std::string& snapshot,
                                      const deck::Deck& deck, const parallel::Communicator& comm);
// Rank 0 removes the earlier run's files from the output directory; throws io::Hdf5Error on
// every rank if it cannot.
void remove_earlier_run(const deck::Deck& deck, const parallel::Communicator& comm);

// Rank 0 writes run.toml (the resolved deck) and provenance.toml (a new one, or this restart's
// entry appended) into the output directory; throws io::Hdf5Error on every rank if it cannot.
void record_run(const deck::Deck& deck, const run::Provenance& provenance,
                const parallel::Communicator& comm);

}  // namespace bagnold::app
