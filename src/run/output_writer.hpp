#pragma once
// Where a run's output goes: the output directory (created, checked writable at start), the
// numbered HDF5 snapshots (snapshot_000000.h5, ...), the XDMF index run.xmf that ParaView opens,
// and the decision of when the next snapshot is due.

#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/io/xdmf.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

// The snapshot a --restart argument names: the file itself, or a run directory's last snapshot.
std::string find_snapshot(const std::string& file_or_directory);

class OutputWriter {
 public:
  // Collective. Throws io::Hdf5Error with the directory's name if it cannot be created or written.
  OutputWriter(const deck::Deck& deck, const parallel::Domain& domain);

  // True at the end of the first step that reaches the next scheduled snapshot time (steps are
  // not shortened to land on it).
  bool snapshot_due(double time) const { return time >= m_next_time - 1e-12 * (1.0 + time); }
  // Collective: writes a snapshot of `state` and updates the index; returns its path.
  // `time_step_memory`: the time-step controller's state, for an exact restart.
  std::string write(const FlowState& state, double time, long step, double dt, double dt_next = 0,
                    const std::vector<double>& time_step_memory = {});
  // Collective: the state of a failed step, as diagnostic.h5 (not in the index); returns its path.
  std::string write_diagnostic(const FlowState& state, double time, long step, double dt);
  // For a restart at `time`: keeps the directory's snapshots up to that time in the index (later
  // ones will be overwritten), numbers the next one after the last kept (gaps allowed) and
  // schedules it after `time`. Collective.
  void resume(double time);
  const std::string& directory() const { return m_directory; }
  // Whether the last snapshot in the index is at `time` (nothing new to write).
  bool written_at(double time) const { return !m_index.empty() && m_index.back().time == time; }

 private:
  const parallel::Domain& m_domain;
  std::string m_directory;
  std::string m_title;
  double m_interval;
  double m_next_time = 0.0;
  std::vector<io::IndexedSnapshot> m_index;
  std::size_t m_next_number = 0;  // of the next snapshot file
};

}  // namespace bagnold::run
