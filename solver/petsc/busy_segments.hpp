#pragma once
// This rank's busy CPU seconds in the time steps, split at the points where the ranks wait for
// each other, so that the ranks' imbalance can be told from the machine's noise
// (src/run/rank_balance.hpp).
//
// A segment runs from one mark to the next; every rank passes the marks in the same order
// (the end of each linear solve, of each outer-iteration stage, of each step), so the segments
// with the same key hold the same part of the computation on every rank. A segment's busy
// seconds are the thread's CPU seconds in it less those it spent waiting in MPI
// (src/parallel/mpi_wait_clock.hpp) on the processor: the waits' wall seconds less their share
// of the time the thread was off the processor (wall less CPU seconds), taken as spread evenly
// over the segment. So a rank that the operating system takes off its core adds nothing, and
// the CPU clock (a system call) is read once per segment, not twice per MPI call. On
// a machine of their own the ranks would wait, per segment, for the busiest one; the sum over
// the segments of that difference is the part of a rank's wait that its share of the work
// causes (a lower bound: the collectives within a segment can wait more).
//
// Each segment also counts its work in units that do not depend on the machine: a linear
// system's assembly its rows, its solve the rows of its Krylov system times (iterations + 1), a
// stage's rest its owned fluid cells (closures: and its solids cells), a step's end 1. Busy
// seconds over units, pooled over the ranks, is a segment's cost per unit; each rank's units at
// that cost are its counted work (src/run/rank_balance.hpp), which a slower core does not
// inflate.
//
// Local: nothing is communicated. Keys are small integers, made in the order the segments are
// first named (the linear systems' at their construction, a stage's at its first use, the step's
// end at the first step's), which is the same on every rank.

#include <string>
#include <vector>

namespace bagnold::solver {

// A new segment named `name` ("step end", "closures stage", "pressure assembly", "pressure
// solve", …), and its key.
int new_busy_segment(const std::string& name);

// Starts counting: the time since the last mark (outside the time steps) is not counted.
void restart_busy_segment();
// Adds the busy seconds since the last mark, and `work_units`, to the segment `key`, and marks now.
void end_busy_segment(int key, double work_units);

// Busy seconds and work units per key, summed since the process started (a key never marked
// holds 0).
std::vector<double> busy_segment_seconds();
std::vector<double> busy_segment_units();
// The name of each key: a stage's segment holds what the stage does after its last solve, a
// linear system's assembly segment what precedes its solve since the last mark.
std::vector<std::string> busy_segment_names();

}  // namespace bagnold::solver
