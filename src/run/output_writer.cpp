#include "src/run/output_writer.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bagnold::run {

namespace fs = std::filesystem;

OutputWriter::OutputWriter(const deck::Deck& deck, const parallel::Domain& domain)
    : m_domain(domain),
      m_directory(deck.output.directory),
      m_title(deck.run.title),
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

std::string OutputWriter::write(const FlowState& state, double time, long step, double dt) {
  char name[64];
  std::snprintf(name, sizeof name, "snapshot_%06zu.h5", m_index.size());
  const std::string path = (fs::path(m_directory) / name).string();
  io::write_snapshot(path, m_domain.layout, m_domain.flags, state.views(), {time, step, dt, m_title});
  m_index.push_back({name, time});
  if (m_domain.layout.comm().is_root())
    io::write_file_atomically((fs::path(m_directory) / "run.xmf").string(),
                              io::xdmf_text(m_domain.grid, m_index, FlowState::field_names()));
  while (m_next_time <= time * (1 + 1e-12)) m_next_time += m_interval;
  return path;
}

}  // namespace bagnold::run
