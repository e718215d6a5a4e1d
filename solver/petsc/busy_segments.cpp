// This rank's busy CPU seconds per segment of the time steps (busy_segments.hpp).
#include "solver/petsc/busy_segments.hpp"

#include <cstddef>

#include "src/parallel/mpi_wait_clock.hpp"

namespace bagnold::solver {

namespace {
std::vector<double> seconds;
std::vector<std::string> system_names;
double mark_cpu = 0.0;
double mark_wait_cpu = 0.0;
}  // namespace

int next_system_segment(const std::string& name) {
  system_names.push_back(name);
  return system_segment_base + static_cast<int>(system_names.size()) - 1;
}

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

std::vector<std::string> busy_segment_names() {
  std::vector<std::string> names(seconds.size());
  const char* fixed[system_segment_base] = {"step end",          "closures stage",
                                            "momentum stage",    "pressure stage",
                                            "fraction stage",    "energy stage", "", ""};
  for (std::size_t k = 0; k < names.size(); ++k)
    names[k] = k < system_segment_base ? fixed[k] : system_names[k - system_segment_base] + " solve";
  return names;
}

}  // namespace bagnold::solver
