#include "src/io/monitor.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "src/io/io_error.hpp"
#include "src/io/xdmf.hpp"

namespace bagnold::io {

namespace {
// The file's columns: "time", then the monitor's.
std::vector<std::string> file_columns(const std::vector<std::string>& columns) {
  std::vector<std::string> names{"time"};
  names.insert(names.end(), columns.begin(), columns.end());
  return names;
}

std::string header_of(const std::vector<std::string>& names) {
  std::string h;
  for (const auto& name : names) h += (h.empty() ? "" : ",") + name;
  return h;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  return fields;
}

// The earlier series at `path` up to `resume_time` (inclusive, to round-off), as rows of the
// columns `names` ("time" first): each value under the column of its own name, "nan" under one
// the earlier series did not have; and whether the earlier series has a column `names` lacks.
struct EarlierRows {
  std::string rows;
  bool drops_columns = false;
};
EarlierRows earlier_rows(const std::string& path, const std::vector<std::string>& names, double resume_time) {
  EarlierRows earlier;
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line)) return earlier;
  const auto had = split_csv(line);
  const bool same = had == names;  // then each row is kept as it was written
  std::vector<std::ptrdiff_t> source;  // per wanted column: its index in the earlier rows, or -1
  for (const auto& name : names) {
    const auto at = std::find(had.begin(), had.end(), name);
    source.push_back(at == had.end() ? -1 : at - had.begin());
  }
  for (const auto& name : had)
    if (std::find(names.begin(), names.end(), name) == names.end()) earlier.drops_columns = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (std::stod(line.substr(0, line.find(','))) > resume_time * (1 + 1e-12)) break;
    if (same) {
      earlier.rows += line + "\n";
      continue;
    }
    const auto values = split_csv(line);
    for (std::size_t c = 0; c < source.size(); ++c) {
      const auto i = static_cast<std::size_t>(source[c]);
      earlier.rows += (c > 0 ? "," : "") + (source[c] >= 0 && i < values.size() ? values[i] : std::string("nan"));
    }
    earlier.rows += "\n";
  }
  return earlier;
}
}  // namespace

Monitor::Monitor(std::string path, std::vector<std::string> columns, bool active,
                 const double* resume_time)
    : m_path(std::move(path)), m_columns(std::move(columns)), m_active(active) {
  if (!m_active) return;
  const auto names = file_columns(m_columns);
  std::string kept = header_of(names) + "\n";
  if (resume_time) {
    const EarlierRows earlier = earlier_rows(m_path, names, *resume_time);
    kept += earlier.rows;
    // A column the continued series no longer has: the earlier file is kept whole beside it.
    if (earlier.drops_columns)
      std::filesystem::copy_file(m_path, m_path + ".before-restart",
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
