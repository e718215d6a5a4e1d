// bagnold run DECK: choose and claim the output directory (output_directory.hpp), set up the
// domain and the initial state (or a restart's), record the run (run.toml, provenance.toml and
// every snapshot's attributes), write the initial state, and advance to run.end_time with the
// two-fluid solver (gas alone, gas and solids, or solids in vacuum).
#include <fmt/format.h>
#include <unistd.h>  // isatty

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <utility>

#include "src/run/progress.hpp"
#include "src/run/stop_request.hpp"
#include "src/app/commands.hpp"
#include "src/app/exit_codes.hpp"
#include "src/app/output_directory.hpp"
#include "src/app/preflight.hpp"
#include "src/app/run_banner.hpp"
#include "src/app/run_log.hpp"
#include "src/app/time_loop.hpp"
#include "src/deck/load.hpp"
#include "src/io/agree.hpp"
#include "src/io/monitor.hpp"
#include "src/run/initial_state.hpp"
#include "src/run/monitor_columns.hpp"
#include "src/run/output_writer.hpp"
#include "src/run/provenance.hpp"
#include "src/run/restart_snapshot.hpp"
#include "src/run/run_directory.hpp"
#include "src/run/work_weights.hpp"
#include "solver/petsc/busy_segments.hpp"
#include "solver/simple/face_fractions.hpp"

namespace bagnold::app {

namespace {

struct StartPoint {
  double time = 0.0;
  long step = 0;
  double dt = 0.0;       // the first step to try
  std::string snapshot;  // empty: a fresh start
  std::vector<double> time_step_memory;  // the time-step controller's, from the snapshot
};

// Reads every field of `snapshot` into `state` (any number of ranks); throws io::Hdf5Error
// when the snapshot does not fit this deck's grid or geometry. Snapshots written before
// pressure_shear_rate existed restart with it unset (the closure starts it at the current rate).
StartPoint restore_state(const std::string& snapshot, const parallel::Domain& domain,
                         run::FlowState& state) {
  StartPoint start;
  start.snapshot = snapshot;
  std::vector<std::vector<double>> fields;
  const auto contents =
      io::read_snapshot(start.snapshot, domain.layout, run::FlowState::field_names(), fields,
                        run::FlowState::optional_field_names());
  const auto targets = state.fields();
  for (std::size_t f = 0; f < targets.size(); ++f) *targets[f] = std::move(fields[f]);
  start.time = contents.info.time;
  start.step = contents.info.step;
  start.dt = contents.info.dt_next;
  start.time_step_memory = contents.info.time_step_memory;
  return start;
}

}  // namespace

int run_command(const DeckArguments& args) {
  deck::Deck deck;
  try {
    deck = deck::load_deck(args.deck, args.overrides);
  } catch (const deck::DeckError& e) {
    say(std::string(e.what()) + "bagnold run: " + args.deck + " is not valid; nothing was run",
        true);
    return bad_input;
  }
  const parallel::Communicator comm;
  // Where the run writes, and whether it may (output_directory.hpp).
  std::string snapshot;
  if (!args.restart.empty()) {
    // The newest snapshot that passes its checksums and ranges (restart_snapshot.hpp).
    const auto choice = run::choose_restart_snapshot(args.restart, comm);
    for (const auto& note : choice.notes) say("bagnold run: " + note + "; trying the one before", true);
    if (choice.snapshot.empty()) {
      say("bagnold run: cannot restart: " + choice.problem, true);
      return bad_input;
    }
    if (!choice.notes.empty())
      say("bagnold run: falling back to " + choice.snapshot + ", the newest good snapshot", true);
    snapshot = choice.snapshot;
    if (const int code = continue_run_directory(args, snapshot, deck, comm); code != success)
      return code;
  }
  const auto claim = claim_output_directory(args, snapshot, deck, comm);
  if (claim.code != success) return claim.code;
  try {
    auto prepared = preflight(deck, comm);
    const auto provenance =
        run::describe_run(args.command_line, comm.size(), args.petsc_options, snapshot);
    say("bagnold run: " + args.deck + "\n" + prepared.text +
        (prepared.errors.ok() ? run_banner(deck, prepared.domain->regions, provenance) : std::string()));
    if (!prepared.errors.ok()) {
      say(prepared.errors.report() + "bagnold run: " + args.deck + " is not valid; nothing was run",
          true);
      return bad_input;
    }
    solver::PetscSession petsc(nullptr, nullptr);
    solver::PetscSession::add_options(args.petsc_options);
    std::optional<run::ProgressLine> progress;
    const auto started = std::chrono::steady_clock::now();
    RunSummary result;
    std::string rank_table;    // the ranks' balance at the end, on more than one rank
    std::string directory;     // where the run writes
    // What a partition by the state weighs: the deck's choice, or work when a partition by cells
    // is redone (numerics.repartition_imbalance).
    const std::string weighing =
        deck.numerics.partition_weights == "cells" ? "work" : deck.numerics.partition_weights;
    // "work" and "phases" weigh the partition by the state; "cells" and "layers" by the geometry.
    const bool weighed_by_state =
        deck.numerics.partition_weights == "work" || deck.numerics.partition_weights == "phases";
    parallel::PartitionWeights weights;      // of a partition by the state, else empty
    parallel::PartitionWeights repartition;  // the next segment's (numerics.repartition_imbalance)
    const auto partition_by_state = [&](parallel::PartitionWeights by) {
      weights = std::move(by);
      prepared.domain = std::make_unique<parallel::Domain>(deck, comm, weights);
      say(run::partition_text(weighing, *prepared.domain, weights));
    };
    // One segment per partition: the run's start, then one after each repartition, which
    // continues from the snapshot the last segment ended with.
    for (bool first_segment = true;; first_segment = false) {
      // The state on the partition by fluid cells or by layers; with numerics.partition_weights = "work" or
      // "phases" on more than one rank (or after a repartition), the partition weighted by that
      // state (work_weights.hpp), and the state again on it.
      if (!repartition.empty()) partition_by_state(std::exchange(repartition, {}));
      run::FlowState state(0);
      StartPoint start;
      for (bool weighted = !weights.empty();; weighted = true) {
        state = run::FlowState(prepared.domain->layout.local_count());
        run::set_initial_state(deck, *prepared.domain, state);
        start = StartPoint{0.0, 0, deck.run.dt_initial, "", {}};
        if (!snapshot.empty()) {
          try {
            start = restore_state(snapshot, *prepared.domain, state);
          } catch (const io::Hdf5Error& e) {
            say(std::string("bagnold run: cannot restart: ") + e.what(), true);
            return first_segment ? bad_input : run_failed;
          }
        }
        if (weighted || !weighed_by_state || comm.size() == 1) break;
        partition_by_state(run::partition_weights(weighing, *prepared.domain, state, solver::solids_threshold));
      }
      const parallel::Domain& domain = *prepared.domain;
      if (first_segment && deck.numerics.partition_weights == "layers" && comm.size() > 1)
        say(run::partition_text(std::string("layers across ") + "xyz"[deck.physics.gravity_axis()], domain, {}));
      if (first_segment && !snapshot.empty()) {
        // The snapshot's next dt, kept within the deck's limits: a restart with a new dt_max or
        // dt_min obeys them from its first step.
        const double snapshot_dt = start.dt;
        start.dt = std::clamp(start.dt, deck.run.dt_min, deck.run.dt_max);
        say(fmt::format("restart from {} at t = {:.6g} s, step {}", start.snapshot, start.time, start.step));
        if (start.dt != snapshot_dt)
          say(fmt::format("restart: the snapshot's next dt {:.3g} s is outside [run.dt_min, run.dt_max] = "
                          "[{:.3g}, {:.3g}] s; the first step takes {:.3g} s",
                          snapshot_dt, deck.run.dt_min, deck.run.dt_max, start.dt));
      }
      if (first_segment && claim.replace) remove_earlier_run(deck, comm);
      run::OutputWriter output(deck, domain, run::snapshot_record(provenance, deck::resolved_text(deck)));
      if (!start.snapshot.empty()) {
        try {
          output.resume(start.time);
        } catch (const io::Hdf5Error& e) {
          say(std::string("bagnold run: cannot restart: ") + e.what(), true);
          return first_segment ? bad_input : run_failed;
        }
      }
      if (first_segment) record_run(deck, provenance, comm);
      directory = output.directory();
      // Rank 0 alone writes the monitor: every rank learns if it could not (io::agree).
      std::optional<io::Monitor> opened_monitor;
      io::agree(comm, [&] {
        opened_monitor.emplace(output.directory() + "/monitor.csv", monitor_columns(deck, domain),
                               comm.is_root(), start.snapshot.empty() ? nullptr : &start.time);
      });
      io::Monitor& monitor = *opened_monitor;
      solver::FlowSolver flow(deck, domain);
      if (start.snapshot.empty()) {
        flow.apply_boundary_values(state);
        say(snapshot_line(0.0, output.write(state, 0.0, 0, deck.run.dt_initial, deck.run.dt_initial)));
      }
      if (first_segment) {
        run::install_stop_handlers();
        progress.emplace(
            run::progress_style(deck.output.progress, comm.is_root(), isatty(STDERR_FILENO)),
            deck.output.progress_interval, deck.run.end_time, start.time);
      }
      const double partition_imbalance =
          !weights.empty() && deck.numerics.repartition_imbalance > 0.0
              ? run::work_imbalance(run::gather_rank_counters(comm, rank_counters(domain, state)))
              : 0.0;
      const TimeLoopContext context{deck, domain, output, monitor, *progress,
                                    [](const std::string& line) { say(line); }, args.verbose,
                                    partition_imbalance};
      const auto segment = run_time_loop(context, flow, state, start.time, start.step, start.dt,
                                         start.time_step_memory);
      result.continue_with(segment);
      if (segment.repartition_from.empty()) {
        if (comm.size() > 1) {
          const auto ranks = run::gather_rank_counters(comm, rank_counters(domain, state));
          rank_table = run::rank_balance_table(ranks);
          // --verbose: where the busy seconds differ (rank_balance.hpp).
          if (args.verbose)
            rank_table += "\nbagnold run: per segment (between the points where the ranks meet), each "
                          "rank's busy CPU seconds and counted work, largest lead first\n" +
                          run::busy_segment_table(ranks, solver::busy_segment_names());
        }
        break;
      }
      // Partition anew by the state (by work, or by phases); the next segment reads the state back from the
      // snapshot just written, each rank its new cells (the flow solver, output writer and
      // monitor of this segment, which hold the old partition, go out of scope first).
      repartition = run::partition_weights(weighing, domain, state, solver::solids_threshold);
      snapshot = segment.repartition_from;
    }
    for (const auto& option : solver::PetscSession::unused_options())
      say("bagnold run: warning: the PETSc option " + option +
              " was never used (misspelled, or for a solver this run does not have?)",
          true);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const double per_step = result.steps ? static_cast<double>(result.outer_iterations) /
                                               static_cast<double>(result.steps)
                                         : 0.0;
    // Before the summary, which stays the last line of a completed run (tools read it).
    if (const auto& balance = result.force_balance; balance.largest >= 0.0)  // a step was taken
      say(fmt::format("bagnold run: momentum residual against the acting forces (monitor column "
                      "force_residual): largest {:.3g}{}, above numerics.tolerance in {} of {} "
                      "steps",
                      balance.largest,
                      balance.largest > 0.0
                          ? fmt::format(" ({}, step ending at t = {:.6g} s)",
                                        solver::equation_name(balance.largest_equation), balance.largest_at)
                          : std::string(),
                      balance.above_tolerance, result.steps));
    say(fmt::format("bagnold run: t = {:.6g} s after {} steps ({} redone), {:.2f} outer iterations "
                    "per step, {:.1f} s wall",
                    result.time, result.steps, result.redone_steps, per_step, wall));
    if (!rank_table.empty())
      say("bagnold run: per rank, over the run (wait: in MPI, during assembly and solves)\n" + rank_table);
    if (result.interrupted) {
      say("bagnold run: interrupted; continue with --restart " + directory, true);
      return interrupted;
    }
    if (!result.completed) {
      say("bagnold run: failed: " + result.failure, true);
      return run_failed;
    }
  } catch (const grid::GeometryError& e) {
    say(std::string("bagnold run: ") + args.deck + ": " + e.what(), true);
    return bad_input;
  } catch (const std::exception& e) {
    say(std::string("bagnold run: failed: ") + e.what(), true);
    return run_failed;
  }
  return success;
}

}  // namespace bagnold::app
