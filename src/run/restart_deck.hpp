#pragma once
// Which deck a restart may use. A restart continues the run its snapshot belongs to, so its
// resolved deck must be the one the snapshot was written with (the snapshot's `deck` attribute,
// run/provenance.hpp), except for run control, which a continuation may change: the [run] table
// (title, end_time, dt_initial, dt_min, dt_max) and the [output] table (directory,
// snapshot_interval, progress, progress_interval), and numerics.partition_weights (a restart
// partitions anew; the answer is the same to the solver's tolerance). Everything else (physics, grid, geometry, boundaries,
// materials, models, initial state, numerics) must match unless the user says --force.

#include <string>
#include <vector>

#include "src/deck/differences.hpp"

namespace bagnold::run {

// Whether a restart may change `key` (a dotted deck key, "run.end_time").
bool is_run_control(const std::string& key);

// The keys outside run control in which `current` differs from the recorded deck text. Throws
// deck::DeckError when the recorded text does not load as a deck (a Bagnold with other keys).
std::vector<deck::KeyDifference> restart_conflicts(const std::string& recorded_deck,
                                                   const deck::Deck& current);

}  // namespace bagnold::run
