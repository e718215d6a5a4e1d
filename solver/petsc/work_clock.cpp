// This rank's seconds in time steps, linear solves and MPI waits (work_clock.hpp).
#include "solver/petsc/work_clock.hpp"

#include <mpi.h>

#include "solver/petsc/busy_segments.hpp"
#include "src/parallel/mpi_wait_clock.hpp"

namespace bagnold::solver {

namespace {
WorkSeconds totals;
}  // namespace

WorkSeconds work_seconds() { return totals; }

ScopedWorkClock::ScopedWorkClock(Kind kind)
    : m_kind(kind), m_start(MPI_Wtime()), m_wait_start(parallel::mpi_wait_seconds()) {
  if (kind == step) restart_busy_segment();
}

ScopedWorkClock::~ScopedWorkClock() {
  const double elapsed = MPI_Wtime() - m_start;
  if (m_kind == solve) {
    totals.solves += elapsed;
    return;
  }
  totals.steps += elapsed;
  totals.waits += parallel::mpi_wait_seconds() - m_wait_start;
  static const int segment = new_busy_segment("step end");
  end_busy_segment(segment, 1.0);
}

}  // namespace bagnold::solver
