#pragma once
// How a run was made (its provenance): the command line, the build (version, git hash), the
// number of ranks, the PETSc options and the start time. `bagnold run` records it in two places
// (docs/output.md, "Provenance"): one [[run]] table per start or restart in the output
// directory's provenance.toml, and, together with the resolved deck, as attributes on the root
// of every snapshot it writes, so a snapshot copied away still says where it came from.

#include <chrono>
#include <string>
#include <vector>

#include "src/io/snapshot.hpp"

namespace bagnold::run {

struct Provenance {
  std::string command_line;               // as a POSIX shell would read it back
  std::string version;                    // Bagnold's
  std::string git_hash;                   // of the build ("unknown" outside a git checkout)
  int ranks = 1;
  std::string petsc_options;              // --petsc-options
  std::string petsc_options_environment;  // PETSC_OPTIONS, which PETSc reads as well
  std::string start_time;                 // UTC, ISO 8601 ("2026-12-01T09:30:00Z")
  std::string restart_from;               // the snapshot a restart continued from; "" if none
};

// This process's record: the build's identity, the environment's PETSC_OPTIONS, the time now.
Provenance describe_run(const std::vector<std::string>& arguments, int ranks,
                        const std::string& petsc_options, const std::string& restart_from);

// "2026-12-01T09:30:00Z"
std::string utc_iso8601(std::chrono::system_clock::time_point time);
// The arguments joined by spaces, each quoted ('a b') where a shell would split or expand it.
std::string shell_command_line(const std::vector<std::string>& arguments);

// One [[run]] table of provenance.toml (valid TOML; appended per restart).
std::string provenance_toml(const Provenance& p);

// The snapshot root attributes: `deck` (the resolved deck as TOML text), `command_line`,
// `git_hash`, `ranks` (int64), `petsc_options`, `petsc_options_environment`, `start_time`,
// `restart_from`; the version is the snapshot's `bagnold_version`.
std::vector<io::RecordAttribute> snapshot_record(const Provenance& p, const std::string& resolved_deck);

}  // namespace bagnold::run
