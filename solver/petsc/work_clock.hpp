#pragma once
// Wall seconds this rank has spent advancing time steps (FlowSolver::advance: every outer
// iteration, its residual reduction included) and, within them, in linear solves (KSPSolve) and
// waiting for other ranks in MPI (src/parallel/mpi_wait_clock.hpp), summed since the process
// started. Local: nothing is communicated; src/run/rank_balance.hpp gathers them.

namespace bagnold::solver {

struct WorkSeconds {
  double steps = 0.0;   // in FlowSolver::advance
  double solves = 0.0;  // of which in KSPSolve
  double waits = 0.0;   // of which in MPI waits (in solves or not)
};

WorkSeconds work_seconds();

// Adds its lifetime to WorkSeconds::steps (and the MPI waits within it to ::waits) or ::solves.
// Steps do not nest; a step starts and ends the busy segments (busy_segments.hpp).
class ScopedWorkClock {
 public:
  enum Kind { step, solve };
  explicit ScopedWorkClock(Kind kind);
  ~ScopedWorkClock();
  ScopedWorkClock(const ScopedWorkClock&) = delete;
  ScopedWorkClock& operator=(const ScopedWorkClock&) = delete;

 private:
  Kind m_kind;
  double m_start;
  double m_wait_start;
};

}  // namespace bagnold::solver
