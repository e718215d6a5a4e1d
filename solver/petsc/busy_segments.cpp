// This rank's busy CPU seconds per segment of the time steps (busy_segments.hpp).
#include "solver/petsc/busy_segments.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstddef>

#include "src/parallel/mpi_wait_clock.hpp"

namespace bagnold::solver {

namespace {
std::vector<double> seconds;
std::vector<double> units;
std::vector<std::string> system_names;
double mark_cpu = 0.0;
double mark_wall = 0.0;
double mark_wait = 0.0;
}  // namespace

int next_system_segment(const std::string& name) {
  system_names.push_back(name);
  return system_segment_base + 2 * (static_cast<int>(system_names.size()) - 1);
}

void restart_busy_segment() {
  mark_cpu = parallel::thread_cpu_seconds();
  mark_wall = MPI_Wtime();
  mark_wait = parallel::mpi_wait_seconds();
}

void end_busy_segment(int key, double work_units) {
  const double cpu = parallel::thread_cpu_seconds(), wall = MPI_Wtime(), wait = parallel::mpi_wait_seconds();
  const double segment_cpu = cpu - mark_cpu, segment_wall = wall - mark_wall, segment_wait = wait - mark_wait;
  // Off the processor for segment_wall − segment_cpu seconds, taken as spread evenly over the
  // segment: the waits' share of it is no wait on the processor.
  const double off = std::max(0.0, segment_wall - segment_cpu);
  const double waiting_on_cpu = segment_wall > 0.0 ? segment_wait * (1.0 - off / segment_wall) : 0.0;
  const auto k = static_cast<std::size_t>(key);
  if (seconds.size() <= k) {
    seconds.resize(k + 1, 0.0);
    units.resize(k + 1, 0.0);
  }
  seconds[k] += std::max(0.0, segment_cpu - waiting_on_cpu);
  units[k] += work_units;
  mark_cpu = cpu;
  mark_wall = wall;
  mark_wait = wait;
}

std::vector<double> busy_segment_seconds() { return seconds; }

std::vector<double> busy_segment_units() { return units; }

std::vector<std::string> busy_segment_names() {
  std::vector<std::string> names(seconds.size());
  const char* fixed[system_segment_base] = {"step end",          "closures stage",
                                            "momentum stage",    "pressure stage",
                                            "fraction stage",    "energy stage", "", ""};
  for (std::size_t k = 0; k < names.size(); ++k)
    names[k] = k < system_segment_base
                   ? fixed[k]
                   : system_names[(k - system_segment_base) / 2] + ((k - system_segment_base) % 2 ? " solve" : " assembly");
  return names;
}

}  // namespace bagnold::solver
