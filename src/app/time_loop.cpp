#include "src/app/time_loop.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "src/app/run_log.hpp"
#include "src/app/time_step_controller.hpp"
#include "solver/petsc/busy_segments.hpp"
#include "solver/petsc/work_clock.hpp"
#include "solver/simple/face_fractions.hpp"
#include "src/io/agree.hpp"
#include "src/run/monitor_columns.hpp"
#include "src/run/pressure_probe.hpp"
#include "src/run/stop_request.hpp"

namespace bagnold::app {

run::RankCounters rank_counters(const parallel::Domain& domain, const run::FlowState& state) {
  const auto work = solver::work_seconds();
  return run::count_rank(domain.layout, state, solver::solids_threshold,
                         {work.steps - work.solves, work.solves, work.waits},
                         solver::busy_segment_seconds(), solver::busy_segment_units());
}

std::vector<std::string> monitor_columns(const deck::Deck& deck, const parallel::Domain& domain) {
  auto columns = run::monitor_columns(domain.regions, deck.pressure_probes);
  for (const char* phase : {"gas", "solids"})
    for (const char* d : {"x", "y", "z"}) columns.push_back(std::string("wall_shear_") + phase + "_" + d + "_N");
  for (int i = 0; i < solver::intervention_count; ++i) columns.push_back(solver::intervention_name(i));
  for (int k = 0; k < solver::linear_system_count; ++k) columns.push_back(solver::linear_system_name(k));
  columns.push_back("courant");
  columns.push_back("force_residual");
  return columns;
}

std::vector<double> monitor_row(const TimeLoopContext& context, const FlowSolver& flow,
                                const run::FlowState& state, double dt, const StepResult& step,
                                double courant) {
  const auto inventory = run::phase_inventory(context.deck, context.domain, state);
  std::vector<double> row = {dt, static_cast<double>(step.iterations), step.residuals.largest(),
                             inventory.gas, inventory.solids};
  const auto gas_flux = flow.boundary_mass_flux(state, solver::gas);
  const auto solids_flux = flow.stepped_solids_flux(state);
  for (std::size_t r = 0; r < gas_flux.size(); ++r) {
    row.push_back(gas_flux[r]);
    row.push_back(solids_flux[r]);
  }
  const auto drops = run::pressure_drops(context.deck, context.domain, state);  // collective
  row.insert(row.end(), drops.begin(), drops.end());
  for (const auto& phase : step.wall_shear) row.insert(row.end(), phase.begin(), phase.end());
  row.insert(row.end(), step.interventions.begin(), step.interventions.end());
  row.insert(row.end(), step.linear_iterations.begin(), step.linear_iterations.end());
  row.push_back(courant);
  row.push_back(step.force_balance);
  return row;
}

RunSummary run_time_loop(const TimeLoopContext& context, FlowSolver& flow, run::FlowState& state,
                         double start_time, long start_step, double dt_start,
                         const std::vector<double>& time_step_memory) {
  const auto& run = context.deck.run;
  RunSummary summary;
  double time = start_time;
  long step = start_step;
  TimeStepController controller(run, context.deck.numerics, dt_start);
  controller.restore(time_step_memory);
  RunLog run_log(context.log, context.verbose, controller.dt());
  run::FlowState old = state;
  run::FlowState failed = state;  // the last iterate of a step that did not converge
  const double limit = context.deck.numerics.repartition_imbalance;
  const double partition_imbalance = context.partition_imbalance;
  const double end = run.end_time;
  const double tiny = 1e-12 * std::max(1.0, end);

  while (time < end - tiny) {
    // Only the last step is shortened, to land on run.end_time; a snapshot is written at the end
    // of the first step that reaches its scheduled time, so the schedule does not change the
    // answer (beyond the outer tolerance when numerics.pressure_preconditioner_steps > 1).
    const double dt_try = std::min(controller.dt(), end - time);
    old = state;
    flow.set_step_start(time);
    const StepResult result = flow.advance(state, old, dt_try, run::signal_received);
    summary.outer_iterations += result.iterations;
    if (result.abandoned) {
      // A signal: the step in progress is dropped and the last completed one written at once.
      state = old;
      if (!context.output.written_at(time))
        run_log.snapshot(time, context.output.write(state, time, step, summary.last_dt,
                                                    controller.dt(), controller.memory()));
      summary.interrupted = true;
      context.log(fmt::format("t = {:.6g} s: stopped by signal {} in outer iteration {} of a step; "
                              "that step was abandoned; final snapshot written at t = {:.6g} s",
                              time, run::stop_signal(), result.iterations, time));
      break;
    }
    if (!result.converged) {
      failed = state;
      state = old;
      ++summary.redone_steps;
      controller.failed(dt_try, step);
      flow.renew_preconditioners();
      const double dt = controller.dt();
      const std::string why =
          result.failure.empty()
              ? fmt::format("{} {:.3g} after {} outer iterations{}",
                            context.deck.numerics.residual_normalization == "mfix" ? "residual sum"
                                                                                    : "largest residual",
                            result.judged, result.iterations,
                            result.stalled ? ", stalled (numerics.detect_stall)" : "")
              : fmt::format("{} in outer iteration {}", result.failure, result.iterations);
      context.log(fmt::format("t = {:.6g} s: step not converged ({}); dt -> {:.3g} s, step redone",
                              time, why, dt));
      if (dt < run.dt_min) {
        // Stop cleanly: the failed iterate goes to diagnostic.h5, the message says where.
        const int worst = result.residuals.worst();
        const auto where = flow.worst_cell(worst);
        const std::string diagnostic = context.output.write_diagnostic(failed, time, step, dt_try);
        const double value = result.residuals.value[static_cast<std::size_t>(worst)];
        const std::string how =
            result.diverged()
                ? fmt::format("the {} equation diverged (normalized residual {:.3g}; the step's "
                              "largest was {:.3g} in its first outer iteration)",
                              solver::equation_name(worst), value, result.first_largest)
                : fmt::format("the outer iteration stalled: the {} equation's normalized residual "
                              "{:.3g} stayed above numerics.tolerance = {:.3g} (the step's largest "
                              "was {:.3g} in its first outer iteration) over {} outer iterations "
                              "({})",
                              solver::equation_name(worst), value, context.deck.numerics.tolerance,
                              result.first_largest, result.iterations,
                              result.stalled ? "numerics.detect_stall: it stopped falling"
                                             : "numerics.max_outer_iterations");
        summary.failure = fmt::format(
            "the time step fell below run.dt_min = {:.3g} s at t = {:.6g} s; {}, worst in {}; the "
            "failed iterate is in {}",
            run.dt_min, time, how, where.text(), diagnostic);
        break;
      }
      continue;
    }
    time += dt_try;
    ++step;
    summary.last_dt = dt_try;
    summary.force_balance.add(result.force_balance, result.force_balance_equation, time,
                              context.deck.numerics.tolerance);
    const double courant = flow.courant_number(state, dt_try);
    const auto row = monitor_row(context, flow, state, dt_try, result, courant);  // collective
    // Rank 0 writes the row; all ranks stop together if it cannot (a full disk).
    io::agree(context.domain.layout.comm(), [&] { context.monitor.append(time, row); });
    const std::string change = controller.converged(dt_try, result.iterations, courant, step);
    run_log.stepped(time, controller.dt(), change);
    // The snapshot records the next dt, so a restart continues exactly as this run would.
    const bool stop = run::stop_requested(context.domain.layout.comm());
    const bool finished = time >= end - tiny;  // the final state is always written
    bool repartition = false;
    if (context.output.snapshot_due(time) || stop || finished) {
      const std::string written = context.output.write(state, time, step, dt_try, controller.dt(),
                                                       controller.memory());
      run_log.snapshot(time, written);
      flow.renew_preconditioners();  // where a restart from this snapshot builds it
      const auto& comm = context.domain.layout.comm();
      if (comm.size() > 1) {
        const auto ranks = run::gather_rank_counters(comm, rank_counters(context.domain, state));
        context.log(fmt::format("t = {:.6g} s: {}", time, run::rank_balance_line(ranks)));
        // numerics.repartition_imbalance: the same counts on every rank, so all agree.
        const double imbalance = run::work_imbalance(ranks);
        if (limit > 0.0 && imbalance > partition_imbalance + limit && !stop && !finished) {
          context.log(fmt::format("t = {:.6g} s: the largest rank's work is {:.1f} % above the "
                                  "mean, {:.1f} % when this partition was made "
                                  "(numerics.repartition_imbalance = {:.3g}): repartitioning from "
                                  "{}",
                                  time, 100.0 * imbalance, 100.0 * partition_imbalance, limit,
                                  written));
          summary.repartition_from = written;
          repartition = true;
        }
      }
    }
    context.progress.update(time, dt_try, result.iterations);
    if (repartition) break;
    if (stop) {
      summary.interrupted = true;
      context.log(fmt::format("t = {:.6g} s: stopped by signal {}; final snapshot written", time,
                              run::stop_signal()));
      break;
    }
  }
  context.progress.finish();
  summary.time = time;
  summary.steps = step - start_step;
  summary.completed = summary.failure.empty() && !summary.interrupted && summary.repartition_from.empty();
  return summary;
}

}  // namespace bagnold::app
