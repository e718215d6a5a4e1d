#pragma once
// PETSc log stages for the phases of the outer iteration, so that `-log_view` splits the time
// of a run by phase: a ScopedStage pushes its stage for its lifetime, and ends a busy segment
// when it ends (busy_segments.hpp).

#include <petscsys.h>

namespace bagnold::solver {

enum class Stage { closures, momentum, pressure, fraction, energy };

class ScopedStage {
 public:
  // `work_units`: what the stage's rest after its last solve counts (busy_segments.hpp).
  ScopedStage(Stage stage, double work_units);
  ~ScopedStage();
  ScopedStage(const ScopedStage&) = delete;
  ScopedStage& operator=(const ScopedStage&) = delete;

 private:
  Stage m_stage;
  double m_work_units;
};

}  // namespace bagnold::solver
