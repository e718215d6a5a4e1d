#include "src/io/monitor.hpp"

#include <cstdio>
#include <sstream>

#include "src/io/io_error.hpp"
#include "src/io/xdmf.hpp"

namespace bagnold::io {

namespace {
std::string header_of(const std::vector<std::string>& columns) {
  std::string h = "time";
  for (const auto& c : columns) h += "," + c;
  return h;
}
}  // namespace

Monitor::Monitor(std::string path, std::vector<std::string> columns, bool active,
                 const double* resume_time)
    : m_path(std::move(path)), m_columns(std::move(columns)), m_active(active) {
  if (!m_active) return;
  const std::string header = header_of(m_columns);
  std::string kept = header + "\n";
  if (resume_time) {
    std::ifstream in(m_path);
    std::string line;
    if (in && std::getline(in, line) && line == header) {
      while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (std::stod(line.substr(0, line.find(','))) > *resume_time * (1 + 1e-12)) break;
        kept += line + "\n";
      }
    }
  }
  write_file_atomically(m_path, kept);
  m_out.open(m_path, std::ios::app);
  if (!m_out) throw Hdf5Error("cannot open the monitor " + m_path + " for writing");
}

void Monitor::append(double time, const std::vector<double>& values) {
  if (!m_active) return;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", time);
  m_out << buffer;
  for (double v : values) {
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    m_out << ',' << buffer;
  }
  m_out << '\n';
  m_out.flush();
  if (!m_out) throw Hdf5Error("cannot append to the monitor " + m_path + " (disk full?)");
}

}  // namespace bagnold::io
