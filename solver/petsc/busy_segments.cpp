// This rank's busy CPU seconds per segment of the time steps (busy_segments.hpp).
#include "solver/petsc/busy_segments.hpp"

#include <cstddef>

#include "src/parallel/mpi_wait_clock.hpp"

namespace bagnold::solver {

namespace {
std::vector<double> seconds;
int systems = 0;
double mark_cpu = 0.0;
double mark_wait_cpu = 0.0;
}  // namespace

int next_system_segment() { return system_segment_base + systems++; }

void restart_busy_segment() {
  mark_cpu = parallel::thread_cpu_seconds();
  mark_wait_cpu = parallel::mpi_wait_cpu_seconds();
}

void end_busy_segment(int key) {
  const double cpu = parallel::thread_cpu_seconds(), wait_cpu = parallel::mpi_wait_cpu_seconds();
  const auto k = static_cast<std::size_t>(key);
  if (seconds.size() <= k) seconds.resize(k + 1, 0.0);
  seconds[k] += (cpu - mark_cpu) - (wait_cpu - mark_wait_cpu);
  mark_cpu = cpu;
  mark_wait_cpu = wait_cpu;
}

std::vector<double> busy_segment_seconds() { return seconds; }

}  // namespace bagnold::solver
