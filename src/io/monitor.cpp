#include "src/io/monitor.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
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

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

// The earlier series at `path` up to `resume_time` (inclusive, to round-off), as rows under
// `header`: each value under the column of its own name, "nan" under a column the earlier
// series did not have. Sets `drops_columns` when the earlier series has a column `header` lacks.
std::string earlier_rows(const std::string& path, const std::string& header, double resume_time,
                         bool& drops_columns) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return "";
  const auto had = split_csv(line), wants = split_csv(header);
  std::vector<int> source;  // per wanted column: its index in the earlier rows, or -1
  for (const auto& name : wants) {
    int found = -1;
    for (std::size_t i = 0; i < had.size(); ++i)
      if (had[i] == name) found = static_cast<int>(i);
    source.push_back(found);
  }
  for (const auto& name : had)
    if (std::find(wants.begin(), wants.end(), name) == wants.end()) drops_columns = true;
  std::string kept;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (std::stod(line.substr(0, line.find(','))) > resume_time * (1 + 1e-12)) break;
    if (had == wants) {  // the same columns: the row as it was written
      kept += line + "\n";
      continue;
    }
    const auto values = split_csv(line);
    for (std::size_t c = 0; c < source.size(); ++c) {
      if (c > 0) kept += ',';
      const int i = source[c];
      kept += i >= 0 && static_cast<std::size_t>(i) < values.size() ? values[static_cast<std::size_t>(i)] : "nan";
    }
    kept += "\n";
  }
  return kept;
}
}  // namespace

Monitor::Monitor(std::string path, std::vector<std::string> columns, bool active,
                 const double* resume_time)
    : m_path(std::move(path)), m_columns(std::move(columns)), m_active(active) {
  if (!m_active) return;
  const std::string header = header_of(m_columns);
  std::string kept = header + "\n";
  if (resume_time) {
    bool drops_columns = false;
    kept += earlier_rows(m_path, header, *resume_time, drops_columns);
    // A column the continued series no longer has: the earlier file is kept whole beside it.
    if (drops_columns) std::filesystem::copy_file(m_path, m_path + ".before-restart",
                                                  std::filesystem::copy_options::overwrite_existing);
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
