#pragma once
// Over a run's accepted steps, their solver::StepResult::force_balance (monitor column
// `force_residual`): the largest, in which equation and when, and how many exceeded
// numerics.tolerance (none can under numerics.residual_normalization = "force"). The run's closing
// lines report it (run_command.cpp); segments after a repartition are merged with add(record).

namespace bagnold::app {

struct ForceBalanceRecord {
  double largest = -1.0;     // none yet
  double largest_at = 0.0;   // [s], the end of that step
  int largest_equation = 0;  // solver::Equation
  long above_tolerance = 0;
  void add(double value, int equation, double time, double tolerance) {
    add({value, time, equation, value > tolerance ? 1L : 0L});
  }
  void add(const ForceBalanceRecord& later) {
    if (later.largest > largest) {
      largest = later.largest;
      largest_at = later.largest_at;
      largest_equation = later.largest_equation;
    }
    above_tolerance += later.above_tolerance;
  }
};

}  // namespace bagnold::app
