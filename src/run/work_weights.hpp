#pragma once
// The cost model of the work-weighted partition (numerics.partition_weights = "work"): each
// fluid cell weighs what an outer iteration costs there, relative to a gas-only cell. A cell
// holding solids (ε_s above the solver's threshold) assembles and solves the solids rows and
// evaluates the closures and the drag; measured on the 5 mm bin on 2 ranks, from the per-rank
// counters (src/run/rank_balance.hpp) of the partition by cells, where one rank holds only gas
// and the other the bed: its busy seconds (assembly and solves less MPI waits) per fluid cell,
// docs/benchmarks.md.

#include <string>
#include <vector>

#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

inline constexpr int gas_cell_work = 10;     // a fluid cell without solids
inline constexpr int solids_cell_work = 12;  // a fluid cell holding solids (measured 1.09–1.22)

// Per natural index of the extended box: each fluid cell's work from `state` on `domain`
// (ε_s > `solids_threshold`: solids_cell_work, else gas_cell_work), 0 for other cells. The same
// on every rank. Collective (one sum over the ranks of a vector the size of the box).
std::vector<int> work_weights(const parallel::Domain& domain, const FlowState& state,
                              double solids_threshold);

// "partition by work: fluid cells per rank 5120..7680, work per rank 81920..82560 (imbalance
// 0.4 %)" for `weights` on `domain`. Collective.
std::string work_partition_text(const parallel::Domain& domain, const std::vector<int>& weights);

}  // namespace bagnold::run
