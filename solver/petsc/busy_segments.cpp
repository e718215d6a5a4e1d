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
std::vector<std::string> names;
double mark_cpu = 0.0;
double mark_wall = 0.0;
double mark_wait = 0.0;
}  // namespace

int new_busy_segment(const std::string& name) {
  names.push_back(name);
  seconds.push_back(0.0);
  units.push_back(0.0);
  return static_cast<int>(names.size()) - 1;
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
  seconds[k] += std::max(0.0, segment_cpu - waiting_on_cpu);
  units[k] += work_units;
  mark_cpu = cpu;
  mark_wall = wall;
  mark_wait = wait;
}

std::vector<double> busy_segment_seconds() { return seconds; }

std::vector<double> busy_segment_units() { return units; }

std::vector<std::string> busy_segment_names() { return names; }

}  // namespace bagnold::solver
