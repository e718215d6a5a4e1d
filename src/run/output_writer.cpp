#include "src/run/output_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "src/io/agree.hpp"
#include "src/run/run_directory.hpp"

namespace bagnold::run {

namespace fs = std::filesystem;

OutputWriter::OutputWriter(const deck::Deck& deck, const parallel::Domain& domain,
                           std::vector<io::RecordAttribute> record)
    : m_domain(domain),
      m_directory(deck.output.directory),
      m_title(deck.run.title),
      m_record(std::move(record)),
      m_viewing(domain),
      m_interval(deck.output.snapshot_interval) {
  const auto& comm = domain.layout.comm();
  std::string problem;
  if (comm.is_root()) {
    std::error_code ec;
    fs::create_directories(m_directory, ec);
    const fs::path probe = fs::path(m_directory) / ".bagnold-write-test";
    std::ofstream out(probe);
    out << "ok\n";
    out.flush();
    if (ec || !out) {
      problem = "cannot write to the output directory '" + m_directory + "'" +
                (ec ? " (" + ec.message() + ")" : std::string());
    }
    out.close();
    fs::remove(probe, ec);
  }
  // Every rank learns whether rank 0 could write, so all of them stop together.
  const std::int64_t failed = comm.max(std::int64_t{problem.empty() ? 0 : 1});
  if (failed) throw io::Hdf5Error(problem.empty() ? "cannot write to the output directory '" + m_directory + "'" : problem);
}

std::uintmax_t OutputWriter::check_room(const std::string& path, const io::SnapshotInfo& info) const {
  const auto& comm = m_domain.layout.comm();
  std::string problem;
  // Test-only (tests/reliability/disk_full_in_write.sh): without the check the disk fills at the
  // reservation, and without the reservation too inside a snapshot's HDF5 calls: the failures
  // the writer must survive on every rank.
  static const bool unchecked = std::getenv("BAGNOLD_TEST_SKIP_ROOM_CHECK") != nullptr;
  static const bool unreserved = std::getenv("BAGNOLD_TEST_SKIP_RESERVATION") != nullptr;
  std::uintmax_t needed = 0;
  if (comm.is_root()) {
    // The run's snapshots differ in size only by their attributes (time_step_memory grows).
    needed =
        m_largest > 0 ? m_largest + 8192
                      : io::snapshot_size_estimate(m_domain.layout, m_domain.flags,
                                                   FlowState::field_names().size(), info,
                                                   ViewingFields::cell_vector_names().size(),
                                                   m_viewing.opening_face_count(),
                                                   ViewingFields::opening_values_per_face());
    std::error_code ec;
    const auto space = fs::space(m_directory, ec);
    if (!ec && !unchecked && space.available < needed)
      problem = "cannot write the snapshot " + path + " (" + std::to_string(space.available / 1024) +
                " kB free on its disk, about " + std::to_string(needed / 1024) +
                " kB needed; disk full?)";
  }
  if (comm.max(std::int64_t{problem.empty() ? 0 : 1}))
    throw io::Hdf5Error(problem.empty() ? "cannot write the snapshot " + path + " (disk full?)" : problem);
  return unreserved ? 0 : needed;
}

void OutputWriter::note_size(const std::string& path) {
  std::error_code ec;
  if (m_domain.layout.comm().is_root())
    if (const auto size = fs::file_size(path, ec); !ec) m_largest = std::max(m_largest, size);
}

std::string OutputWriter::write_diagnostic(const FlowState& state, double time, long step,
                                           double dt) {
  const std::string path = (fs::path(m_directory) / "diagnostic.h5").string();
  const io::SnapshotInfo info{time, step, dt, m_title + " (diagnostic: a step that failed)", dt, {}, m_record};
  const auto reserve = check_room(path, info);
  io::write_snapshot(path, m_domain.layout, m_domain.flags, state.views(), info, m_viewing.of(state),
                     reserve);
  return path;
}

void OutputWriter::resume(double time) {
  // The directory's snapshots in number order, gaps allowed (a run directory may hold only the
  // snapshot copied in to restart from): the index keeps them up to the first written after
  // `time`, and numbering continues after the last kept, so no kept snapshot is overwritten.
  // Every rank reads the directory; all stop together if one cannot, or if they disagree.
  const auto& comm = m_domain.layout.comm();
  auto fields = FlowState::field_names();
  for (const auto& name : ViewingFields::cell_vector_names()) fields.push_back(name);
  std::string problem;
  m_index.clear();
  m_next_number = 0;
  try {
    for (const std::size_t n : snapshot_numbers(m_directory)) {
      const std::string name = snapshot_name(n);
      const std::string path = (fs::path(m_directory) / name).string();
      // A snapshot that cannot be read (truncated, corrupted) is left out of the index; if it
      // follows the last kept one, the next snapshot written takes its number.
      io::SnapshotHeader header;
      try {
        header = io::read_snapshot_header(path, fields);
      } catch (const io::Hdf5Error&) {
        continue;
      }
      if (header.time > time * (1 + 1e-12) + 1e-300) break;
      m_index.push_back({name, header.time, std::move(header.absent_fields), header.opening_faces});
      m_next_number = n + 1;
    }
  } catch (const std::exception& e) {  // io::Hdf5Error, or the file system's
    problem = e.what();
  }
  if (comm.max(std::int64_t{problem.empty() ? 0 : 1}))
    throw io::Hdf5Error(problem.empty() ? "another rank could not read the snapshots in " + m_directory
                                        : problem);
  const auto next = static_cast<std::int64_t>(m_next_number);
  if (comm.min(next) != comm.max(next))
    throw io::Hdf5Error("the ranks see different snapshots in " + m_directory +
                        " (is the output directory on a shared file system?)");
  m_next_time = 0.0;
  while (m_next_time <= time * (1 + 1e-12)) m_next_time += m_interval;
}

std::string OutputWriter::write(const FlowState& state, double time, long step, double dt,
                                double dt_next, const std::vector<double>& time_step_memory) {
  const std::string name = snapshot_name(m_next_number++);
  const std::string path = (fs::path(m_directory) / name).string();
  const io::SnapshotInfo info{time, step, dt, m_title, dt_next, time_step_memory, m_record};
  const auto reserve = check_room(path, info);
  io::write_snapshot(path, m_domain.layout, m_domain.flags, state.views(), info, m_viewing.of(state),
                     reserve);
  note_size(path);
  m_index.push_back({name, time, {}, m_viewing.opening_face_count()});
  io::agree(m_domain.layout.comm(), [&] {
    if (m_domain.layout.comm().is_root())
      io::write_file_atomically((fs::path(m_directory) / "run.xmf").string(),
                                io::xdmf_text(m_domain.grid, m_index, ViewingFields::indexed_fields()));
  });
  while (m_next_time <= time * (1 + 1e-12)) m_next_time += m_interval;
  return path;
}

}  // namespace bagnold::run
