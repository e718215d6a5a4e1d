#pragma once
// Which snapshot a --restart argument restarts from. Every candidate is checked first
// (io::verify_snapshot: each dataset against its checksum, the fluid cells' values against the
// ranges below), so a corrupted or truncated snapshot is never read into a run:
//   --restart FILE  that snapshot, or a refusal naming it and its first bad dataset;
//   --restart DIR   the newest good snapshot of the directory, each newer one refused with its
//                   reason in `notes` (the run says it fell back).
// Rank 0 reads and checks; the choice is broadcast, so every rank restarts from the same file.

#include <string>
#include <vector>

#include "src/io/snapshot_check.hpp"
#include "src/parallel/communicator.hpp"

namespace bagnold::run {

// What a restart accepts in the fluid cells: 0 ≤ ε ≤ 1, P_s ≥ 0, Θ and γ̇_P ≥ 0 or NaN (not
// evaluated), every other field finite.
std::vector<io::FieldRange> restart_ranges();

struct RestartChoice {
  std::string snapshot;            // empty: none acceptable (`problem` says why)
  std::vector<std::string> notes;  // each newer snapshot refused, with its reason
  std::string problem;
};

// Collective.
RestartChoice choose_restart_snapshot(const std::string& file_or_directory,
                                      const parallel::Communicator& comm);

}  // namespace bagnold::run
