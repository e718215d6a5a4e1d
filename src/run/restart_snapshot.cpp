#include "src/run/restart_snapshot.hpp"

#include <filesystem>

#include "src/run/flow_state.hpp"
#include "src/run/run_directory.hpp"

namespace bagnold::run {

namespace fs = std::filesystem;

std::vector<io::FieldRange> restart_ranges() {
  std::vector<io::FieldRange> ranges;
  for (const auto& name : FlowState::field_names()) {
    io::FieldRange r{name};
    if (name == "solids_fraction" || name == "gas_fraction") {
      r.low = 0.0;
      r.high = 1.0;
    } else if (name == "solids_pressure") {
      r.low = 0.0;
    } else if (name == "granular_temperature" || name == "pressure_shear_rate") {
      r.low = 0.0;
      r.nan_allowed = true;
    }
    ranges.push_back(r);
  }
  return ranges;
}

namespace {
// Rank 0's choice: the candidates newest first, the first that verifies.
RestartChoice choose_serially(const std::string& file_or_directory) {
  RestartChoice choice;
  std::vector<std::string> candidates;
  if (fs::is_directory(file_or_directory)) {
    const auto numbers = snapshot_numbers(file_or_directory);
    for (auto n = numbers.rbegin(); n != numbers.rend(); ++n)
      candidates.push_back((fs::path(file_or_directory) / snapshot_name(*n)).string());
    if (candidates.empty()) choice.problem = "no snapshot in " + file_or_directory;
  } else if (!fs::exists(file_or_directory)) {
    choice.problem = "no snapshot " + file_or_directory;
  } else {
    candidates.push_back(file_or_directory);
  }
  const auto ranges = restart_ranges();
  for (const auto& path : candidates) {
    const auto problem = io::verify_snapshot(path, ranges);
    if (!problem) {
      choice.snapshot = path;
      return choice;
    }
    const std::string why = "snapshot " + path + " refused: " + *problem;
    if (candidates.size() == 1) {
      choice.problem = why;
      return choice;
    }
    choice.notes.push_back(why);
  }
  if (!candidates.empty()) choice.problem = "no good snapshot in " + file_or_directory;
  return choice;
}

}  // namespace

RestartChoice choose_restart_snapshot(const std::string& file_or_directory,
                                      const parallel::Communicator& comm) {
  RestartChoice choice;
  if (comm.is_root()) choice = choose_serially(file_or_directory);
  comm.broadcast(choice.snapshot, 0);
  comm.broadcast(choice.problem, 0);
  long notes = static_cast<long>(choice.notes.size());
  MPI_Bcast(&notes, 1, MPI_LONG, 0, comm.get());
  choice.notes.resize(static_cast<std::size_t>(notes));
  for (auto& note : choice.notes) comm.broadcast(note, 0);
  return choice;
}

}  // namespace bagnold::run
