#pragma once
// The monitor time series (monitor.csv in the output directory): one row per time step with the
// time, the step, iterations, residuals, the inventory of each phase and the mass flux through
// each boundary region, appended and flushed as the run goes so a crash loses at most one row.
// Written by rank 0 only. On restart, rows later than the restart time are dropped first; the
// earlier rows are kept under the continued run's columns, matched by name ("nan" under a column
// they did not have: a run of an older build, or a deck with another [[pressure_probe]]), and
// when the earlier series has a column the continued one lacks, its file is also kept whole as
// monitor.csv.before-restart.

#include <fstream>
#include <string>
#include <vector>

namespace bagnold::io {

class Monitor {
 public:
  // Opens (or continues) the series. `columns` are the names after "time". When `resume_time`
  // is given, an existing file's rows up to that time are kept (above); otherwise a new file is
  // started.
  Monitor(std::string path, std::vector<std::string> columns, bool active,
          const double* resume_time = nullptr);
  void append(double time, const std::vector<double>& values);
  const std::vector<std::string>& columns() const { return m_columns; }

 private:
  std::string m_path;
  std::vector<std::string> m_columns;
  bool m_active;
  std::ofstream m_out;
};

}  // namespace bagnold::io
