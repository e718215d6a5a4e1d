// Each fluid cell's work for the partition (work_weights.hpp).
#include "src/run/work_weights.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace bagnold::run {

std::vector<int> work_weights(const parallel::Domain& domain, const FlowState& state,
                              double solids_threshold) {
  const auto& layout = domain.layout;
  std::vector<std::int64_t> summed(static_cast<std::size_t>(domain.grid.extended_cell_count()), 0);
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    summed[static_cast<std::size_t>(layout.natural(l))] =
        state.solids_fraction[static_cast<std::size_t>(l)] > solids_threshold ? solids_cell_work
                                                                              : gas_cell_work;
  layout.comm().sum_in_place(summed);
  return {summed.begin(), summed.end()};
}

std::string work_partition_text(const parallel::Domain& domain, const std::vector<int>& weights) {
  const auto& layout = domain.layout;
  const auto& comm = layout.comm();
  std::int64_t work = 0;
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    work += weights[static_cast<std::size_t>(layout.natural(l))];
  const std::int64_t fluid = layout.owned_fluid_count();
  const std::int64_t total = comm.sum(work);
  const std::int64_t largest = comm.max(work);
  const double mean = static_cast<double>(total) / comm.size();
  return fmt::format("partition by work: fluid cells per rank {}..{}, work per rank {}..{} "
                     "(imbalance {:.2f} %)",
                     comm.min(fluid), comm.max(fluid), comm.min(work), largest,
                     100.0 * (static_cast<double>(largest) / mean - 1.0));
}

}  // namespace bagnold::run
