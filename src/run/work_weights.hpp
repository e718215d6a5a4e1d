#pragma once
// The vertex weights of a partition by the state (numerics.partition_weights):
// - "work": one constraint, each fluid cell weighs what an outer iteration costs there, relative
//   to a gas-only cell. A cell holding solids (ε_s above the solver's threshold) assembles and
//   solves the solids rows and evaluates the closures and the drag; measured on the 2.5 mm bin on
//   2 ranks in steady discharge, from the per-rank counters (src/run/rank_balance.hpp) of the
//   partition by cells, where one rank holds only gas and the other the bed: its busy seconds
//   (assembly and solves less MPI waits) per fluid cell, docs/benchmarks.md.
// - "phases": two constraints, fluid cells and fluid cells holding solids, so that every rank
//   holds its share of each: the outer iteration's gas steps (gas momentum, pressure) cost by
//   fluid cells and its solids steps (closures, solids momentum and volume fraction, whose rows
//   without solids leave the Krylov solves) by solids cells, and each step waits at its own
//   collectives for the rank with the most of its work. Without solids anywhere, fluid cells alone.

#include <string>

#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

inline constexpr int gas_cell_work = 10;     // a fluid cell without solids
inline constexpr int solids_cell_work = 20;  // a fluid cell holding solids (measured 1.95)

// The weights of numerics.partition_weights = `kind` ("work" or "phases") from `state` on
// `domain` (a cell holds solids where ε_s > `solids_threshold`). The same on every rank.
// Collective (one sum over the ranks of a vector the size of the box per constraint).
parallel::PartitionWeights partition_weights(const std::string& kind, const parallel::Domain& domain,
                                             const FlowState& state, double solids_threshold);

// "partition by work: fluid cells per rank 5120..7680, work per rank 81920..82560 (imbalance
// 0.4 %)" for `weights` (of `kind`) on `domain`; by phases, each constraint's range; without
// weights (a partition by layers), the fluid cells' range alone. Collective.
std::string partition_text(const std::string& kind, const parallel::Domain& domain,
                           const parallel::PartitionWeights& weights);

}  // namespace bagnold::run
