#pragma once
// PETSc log stages for the phases of the outer iteration, so that `-log_view` splits the time
// of a run by phase: a ScopedStage pushes its stage for its lifetime, and adds that lifetime to
// this rank's stage seconds (work_clock.hpp).

#include <petscsys.h>

#include "solver/petsc/work_clock.hpp"

namespace bagnold::solver {

enum class Stage { closures, momentum, pressure, fraction, energy };

class ScopedStage {
 public:
  explicit ScopedStage(Stage stage);
  ~ScopedStage();
  ScopedStage(const ScopedStage&) = delete;
  ScopedStage& operator=(const ScopedStage&) = delete;

 private:
  ScopedWorkClock m_clock{ScopedWorkClock::stage};
};

}  // namespace bagnold::solver
