#pragma once
// How the work of a run is spread over the ranks, for the user: per rank the cells it owns, its
// owned fluid cells, the owned fluid cells holding solids (ε_s above a threshold), and its wall
// seconds in assembly (the time steps' outer iterations outside linear solves), in linear
// solves, and waiting for other ranks in MPI during the time steps (part of the other two), and
// its busy CPU seconds per segment of the time steps (solver/petsc/busy_segments.hpp), from
// which the part of the waits that the partition causes is told from the part that the
// machine's noise causes. The counts are this rank's alone; gather_rank_counters is the only
// communication (a maximum and an all-gather of a few dozen numbers), made only when the balance
// is shown.

#include <string>
#include <vector>

#include "src/parallel/layout.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

struct RankSeconds {
  double assembly = 0.0;
  double solves = 0.0;
  double waits = 0.0;
};

struct RankCounters {
  double owned_cells = 0.0;   // fluid and boundary
  double fluid_cells = 0.0;
  double solids_cells = 0.0;  // owned fluid cells with ε_s > the threshold
  RankSeconds seconds;
  std::vector<double> busy_segments;  // busy CPU seconds per segment key
  std::vector<double> work_units;     // work units per segment key (the same length)

  // waits / (assembly + solves); 0 before any work.
  double wait_share() const;
};

// This rank's counters: its owned cells in `layout`, its cells with ε_s > `solids_threshold` in
// `state`, and `seconds`, `busy_segments` and `work_units` as given.
RankCounters count_rank(const parallel::Layout& layout, const FlowState& state,
                        double solids_threshold, const RankSeconds& seconds,
                        std::vector<double> busy_segments = {}, std::vector<double> work_units = {});
// Every rank's, in rank order, on every rank. Collective.
std::vector<RankCounters> gather_rank_counters(const parallel::Communicator& comm,
                                               const RankCounters& mine);

// The largest rank's work over the ranks' mean, less 1 (0.1: 10 % above the mean), each rank's
// work its fluid cells weighed as the work-weighted partition weighs them (work_weights.hpp);
// 0 for no ranks or no work.
double work_imbalance(const std::vector<RankCounters>& ranks);

// Per rank and segment, the counted work in seconds: its work units at the segment's cost per
// unit, the ranks' busy seconds over their units (its busy seconds where no rank counted units).
std::vector<std::vector<double>> counted_work(const std::vector<RankCounters>& ranks);
// Per rank, the share of its time it would wait for the others on a machine of its own, with
// ranks equally fast: per segment the largest counted work less its own, summed over the
// segments, over the sum of the largest (0 for every rank without busy seconds).
std::vector<double> imbalance_wait_shares(const std::vector<RankCounters>& ranks);

// The table printed at the end of a run: a row per rank, then the max/min ratio of each column
// ("inf" when the smallest is 0).
std::string rank_balance_table(const std::vector<RankCounters>& ranks);
// The busy seconds and counted work per segment (`names`, one per key) and rank, and the lead of
// the largest counted work over the smallest, largest lead first; segments with no busy seconds
// are left out.
std::string busy_segment_table(const std::vector<RankCounters>& ranks,
                               const std::vector<std::string>& names);
// One line for the run log: the max/min ratios of fluid cells, solids cells, assembly and solve
// seconds, the range of the ranks' wait shares and of their imbalance wait shares, and the work
// imbalance now ("ranks: fluid cells max/min 1.00, solids cells 2.31, assembly 1.85, solves
// 1.10; wait 2.1–22.5 %, from the imbalance 0.3–8.0 %; work max 9.1 % above the mean").
std::string rank_balance_line(const std::vector<RankCounters>& ranks);

}  // namespace bagnold::run
