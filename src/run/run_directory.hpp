#pragma once
// The files of a run directory (output.directory) and the rules for finding and replacing them:
//
//   snapshot_NNNNNN.h5  the snapshots (OutputWriter)        run.xmf        their XDMF index
//   monitor.csv         one row per step (io::Monitor)      diagnostic.h5  a failed step's iterate
//   run.toml            the resolved deck of the latest start or restart (loads as a deck)
//   provenance.toml     one [[run]] table per start or restart (run/provenance.hpp)
//
// and, for each, the NAME.tmp a write in progress goes through. Nothing else in the directory
// is the run's: a fresh run into it leaves other files alone.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace bagnold::run {

// "snapshot_000012.h5"
std::string snapshot_name(std::size_t number);
// The number of a snapshot file (exactly the form snapshot_name writes), or nothing for any other
// name (temporary files, other digit forms).
std::optional<std::size_t> snapshot_number(const std::string& file_name);
// The directory's snapshot files, ordered by number.
std::vector<std::size_t> snapshot_numbers(const std::string& directory);

// The run directory a --restart argument names: the directory itself, or the snapshot's ("."
// for a bare file name).
std::string restart_directory(const std::string& file_or_directory);

// Whether `directory` holds a run: a snapshot or monitor.csv (false when it does not exist).
bool holds_run(const std::string& directory);
// Removes the run's files listed above from `directory` and returns their names; other files
// stay. Throws io::Hdf5Error naming a file that cannot be removed.
std::vector<std::string> remove_run(const std::string& directory);

// Writes run.toml (`resolved_deck`) and provenance.toml through temporaries and renames:
// `provenance_entry` starts a new provenance.toml, or is appended to the existing one when
// `continuing` (a restart). Rank 0 only. Throws io::Hdf5Error naming the file.
void write_run_record(const std::string& directory, const std::string& resolved_deck,
                      const std::string& provenance_entry, bool continuing);

}  // namespace bagnold::run
