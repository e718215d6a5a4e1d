#pragma once
// Where a run's output goes: the output directory (created, checked writable at start), the
// numbered HDF5 snapshots (snapshot_000000.h5, ...), the XDMF index run.xmf that ParaView opens,
// and the decision of when the next snapshot is due. Which files are the run's, and how they
// are found and replaced: run_directory.hpp.

#include <string>
#include <vector>

#include "src/deck/deck.hpp"
#include "src/io/xdmf.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"
#include "src/run/viewing_fields.hpp"

namespace bagnold::run {

class OutputWriter {
 public:
  // Collective. Throws io::Hdf5Error with the directory's name if it cannot be created or written.
  // `record`: the run's provenance and deck (run/provenance.hpp), on every snapshot's root.
  OutputWriter(const deck::Deck& deck, const parallel::Domain& domain,
               std::vector<io::RecordAttribute> record = {});

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
  // Collective, before a snapshot is written to `path`: throws io::Hdf5Error on every rank when
  // rank 0 finds less free space on the directory's disk than the snapshot needs (8 KiB more than
  // the largest written so far, or io::snapshot_size_estimate), with a message saying how much.
  // Returns that size on rank 0 (0 on the others): the writer reserves it on disk before writing
  // (io/disk_reservation.hpp; docs/reliability.md, "Disk full").
  std::uintmax_t check_room(const std::string& path, const io::SnapshotInfo& info) const;
  // Rank 0 notes the size of the snapshot just written.
  void note_size(const std::string& path);

  const parallel::Domain& m_domain;
  std::string m_directory;
  std::string m_title;
  std::vector<io::RecordAttribute> m_record;
  ViewingFields m_viewing;  // the cell vectors and opening faces each snapshot carries
  double m_interval;
  double m_next_time = 0.0;
  std::vector<io::IndexedSnapshot> m_index;
  std::size_t m_next_number = 0;  // of the next snapshot file
  std::uintmax_t m_largest = 0;   // [bytes] of the snapshots this writer wrote (rank 0)
};

}  // namespace bagnold::run
