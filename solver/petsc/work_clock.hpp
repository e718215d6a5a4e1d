#pragma once
// Wall seconds this rank has spent in the outer iteration's phases (every ScopedStage of
// log_stage.hpp) and, within them, in linear solves (KSPSolve) and waiting for other ranks in
// MPI (src/parallel/mpi_wait_clock.hpp), summed since the process started. Local: nothing is
// communicated; src/run/rank_balance.hpp gathers them.

namespace bagnold::solver {

struct WorkSeconds {
  double stages = 0.0;  // closures, momentum, pressure, volume fraction, granular energy
  double solves = 0.0;  // of which in KSPSolve
  double waits = 0.0;   // of which in MPI waits (in solves or not)
};

WorkSeconds work_seconds();

// Adds its lifetime to WorkSeconds::stages or ::solves.
class ScopedWorkClock {
 public:
  enum Kind { stage, solve };
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
