#pragma once
// The time loop of a run (the program's: solver/ advances one step): advance with an adaptive step from the current time to run.end_time,
// append the monitor every step, write snapshots when due, show progress.
//
// Adaptive time step (time_step_controller.hpp): a step that does not converge within
// numerics.max_outer_iterations (or produces NaN, or has a linear solve that fails) is undone
// and redone with dt / 2; converged steps grow or shrink dt by their outer iterations, their
// recorded cost per simulated second and the Courant limit.
// Only the last step is shortened, to land on end_time; a snapshot is written at the end of the
// first step that reaches its scheduled time, and the state at end_time is always written.
// Every redone step is logged; each snapshot and the dt changes before it as run_log.hpp says,
// then, on more than one rank, the balance of the ranks since the run started
// (src/run/rank_balance.hpp).
// A step that fails at run.dt_min stops the run. On more than one rank with
// numerics.repartition_imbalance set, a snapshot after which the ranks' work is out of balance
// by more than it ends the loop (summary.repartition_from).

#include <functional>
#include <string>

#include "solver/simple/flow_solver.hpp"
#include "src/app/force_balance_record.hpp"
#include "src/io/monitor.hpp"
#include "src/run/output_writer.hpp"
#include "src/run/progress.hpp"
#include "src/run/rank_balance.hpp"

namespace bagnold::app {

using solver::FlowSolver;
using solver::StepResult;

struct RunSummary {
  bool completed = false;
  double time = 0.0;
  long steps = 0;
  long outer_iterations = 0;
  long redone_steps = 0;
  double last_dt = 0.0;
  bool interrupted = false;  // SIGINT/SIGTERM: stopped after writing a final snapshot
  std::string failure;       // why the run stopped early
  // Stopped for numerics.repartition_imbalance after writing this snapshot: the caller
  // partitions anew and continues from it.
  std::string repartition_from;
  ForceBalanceRecord force_balance;

  // The run so far followed by `later`, a segment after it: counts added, its outcome kept.
  void continue_with(const RunSummary& later) {
    steps += later.steps;
    outer_iterations += later.outer_iterations;
    redone_steps += later.redone_steps;
    time = later.time;
    last_dt = later.last_dt;
    completed = later.completed;
    interrupted = later.interrupted;
    failure = later.failure;
    repartition_from = later.repartition_from;
    force_balance.add(later.force_balance);
  }
};

struct TimeLoopContext {
  const deck::Deck& deck;
  const parallel::Domain& domain;
  run::OutputWriter& output;
  io::Monitor& monitor;
  run::ProgressLine& progress;
  std::function<void(const std::string&)> log;  // rank 0 prints
  bool verbose = false;  // --verbose: log every change of dt (run_log.hpp)
  // The work imbalance (run::work_imbalance) a partition by work had when it was made, which
  // numerics.repartition_imbalance counts from (a partition cannot balance better than its
  // cells allow); 0 for a partition by cells.
  double partition_imbalance = 0.0;
};

// From `start_time` (step number `start_step`) with a first step of `dt_start`. A SIGINT or
// SIGTERM stops the loop after the current step with a final snapshot (summary.interrupted).
// `time_step_memory`: the controller's state from the snapshot a restart starts from (empty on a
// fresh start).
RunSummary run_time_loop(const TimeLoopContext& context, FlowSolver& flow, run::FlowState& state,
                         double start_time, long start_step, double dt_start,
                         const std::vector<double>& time_step_memory = {});

// This rank's counters now: its cells, its cells holding solids (ε_s above the solver's
// solids_threshold) and its seconds in time steps since the process started
// (solver/petsc/work_clock.hpp).
run::RankCounters rank_counters(const parallel::Domain& domain, const run::FlowState& state);

// The monitor's columns: run::monitor_columns, then a count per numerical limiter and the linear
// iterations per kind of system, each summed over the step's outer iterations, then the step's
// Courant number.
std::vector<std::string> monitor_columns(const deck::Deck& deck, const parallel::Domain& domain);
// The monitor row after a step.
std::vector<double> monitor_row(const TimeLoopContext& context, const FlowSolver& flow,
                                const run::FlowState& state, double dt, const StepResult& step,
                                double courant);

}  // namespace bagnold::app
