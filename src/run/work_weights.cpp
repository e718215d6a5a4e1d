// The partition's weights from the state (work_weights.hpp).
#include "src/run/work_weights.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdint>
#include <vector>

namespace bagnold::run {

parallel::PartitionWeights partition_weights(const std::string& kind, const parallel::Domain& domain,
                                             const FlowState& state, double solids_threshold) {
  const auto& layout = domain.layout;
  const bool by_phase = kind == "phases";
  const int constraints = by_phase ? 2 : 1;
  std::vector<std::int64_t> summed(
      static_cast<std::size_t>(constraints * domain.grid.extended_cell_count()), 0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const bool solids = state.solids_fraction[static_cast<std::size_t>(l)] > solids_threshold;
    const auto at = static_cast<std::size_t>(constraints * layout.natural(l));
    if (by_phase) {
      summed[at] = 1;
      summed[at + 1] = solids ? 1 : 0;
    } else {
      summed[at] = solids ? solids_cell_work : gas_cell_work;
    }
  }
  layout.comm().sum_in_place(summed);
  parallel::PartitionWeights weights{constraints, {summed.begin(), summed.end()}};
  if (by_phase) {
    std::int64_t solids_cells = 0;
    for (std::size_t i = 1; i < summed.size(); i += 2) solids_cells += summed[i];
    if (solids_cells == 0) weights = {1, std::vector<int>(summed.size() / 2, 1)};  // gas alone
  }
  return weights;
}

std::string partition_text(const std::string& kind, const parallel::Domain& domain,
                           const parallel::PartitionWeights& weights) {
  const auto& layout = domain.layout;
  const auto& comm = layout.comm();
  const std::int64_t fluid = layout.owned_fluid_count();
  std::vector<std::string> parts;
  if (kind != "phases") parts.push_back(fmt::format("fluid cells per rank {}..{}", comm.min(fluid), comm.max(fluid)));
  for (int c = 0; c < (weights.empty() ? 0 : weights.constraints); ++c) {
    std::int64_t sum = 0;
    for (int l = 0; l < layout.owned_fluid_count(); ++l) sum += weights.at(layout.natural(l), c);
    const std::int64_t total = comm.sum(sum);
    const std::int64_t largest = comm.max(sum);
    const double mean = static_cast<double>(total) / comm.size();
    const char* name = kind == "phases" ? (c == 0 ? "fluid cells" : "solids cells") : "work";
    parts.push_back(fmt::format("{} per rank {}..{} (imbalance {:.2f} %)", name, comm.min(sum), largest,
                                mean > 0.0 ? 100.0 * (static_cast<double>(largest) / mean - 1.0) : 0.0));
  }
  return fmt::format("partition by {}: {}", kind, fmt::join(parts, ", "));
}

}  // namespace bagnold::run
