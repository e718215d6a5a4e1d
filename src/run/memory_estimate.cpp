#include "src/run/memory_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace bagnold::run {

MemoryFit measured_memory_fit() {
  // Least-squares fit to the peak resident memory per rank (/usr/bin/time -v) of one step of
  // the 10 mm bin's deck (two-fluid, MKT, hypre) with its grid set to 16 x 16 x 100, 16 x 16 x
  // 400 and 32 x 32 x 400 cells on 1 rank and the last two on 2 ranks: 233, 770, 2973, 420
  // and 1531 MB, each within 2 % of the fit (docs/reliability.md, "Memory estimate").
  return {.base = 45e6, .per_box_cell = 98.0, .per_cell = 7030.0};
}

namespace {
// Bytes as an int64 for gathering; more than 9e18 B is "far too much" either way.
std::int64_t as_count(double bytes) { return static_cast<std::int64_t>(std::min(bytes, 9e18)); }

std::string gigabytes(double bytes) {
  return bytes < 1e9 ? fmt::format("{:.3g} MB", bytes / 1e6) : fmt::format("{:.3g} GB", bytes / 1e9);
}
}  // namespace

MemoryEstimate estimate_memory(const deck::Grid& grid, const parallel::Communicator& comm) {
  const MemoryFit fit = measured_memory_fit();
  const deck::Axis* axes[] = {&grid.x, &grid.y, &grid.z};
  double cells = 1.0, box_cells = 1.0;
  for (int d = 0; d < 3; ++d) {
    cells *= axes[d]->cells;
    box_cells *= axes[d]->cells + (grid.is_periodic(d) ? 0 : 2);
  }
  MemoryEstimate e;
  e.ranks = comm.size();
  e.rank_bytes = fit.base + fit.per_box_cell * box_cells + fit.per_cell * cells / e.ranks;
  e.node_bytes = comm.sum_on_node(e.rank_bytes);
  e.node = machine_memory();
  // The node with the largest estimate against its memory, known to every rank.
  const auto bytes = comm.all_gather(as_count(e.node_bytes));
  const auto physical = comm.all_gather(as_count(e.node.physical));
  const auto available = comm.all_gather(as_count(e.node.available));
  std::size_t worst = 0;
  auto share = [&](std::size_t r) {
    return static_cast<double>(bytes[r]) / std::max(static_cast<double>(physical[r]), 1.0);
  };
  for (std::size_t r = 1; r < bytes.size(); ++r)
    if (share(r) > share(worst)) worst = r;
  e.worst_node_bytes = static_cast<double>(bytes[worst]);
  e.worst_node_physical = static_cast<double>(physical[worst]);
  e.worst_node_available = static_cast<double>(available[worst]);
  return e;
}

std::string memory_text(const MemoryEstimate& e) {
  const double ranks_on_node = std::max(1.0, std::round(e.worst_node_bytes / e.rank_bytes));
  return fmt::format("about {} per rank, {} for the {:.0f} rank(s) on {}, which has {} ({} "
                     "available now)",
                     gigabytes(e.rank_bytes), gigabytes(e.worst_node_bytes), ranks_on_node,
                     e.ranks > ranks_on_node ? "the fullest node" : "this machine",
                     gigabytes(e.worst_node_physical), gigabytes(e.worst_node_available));
}

}  // namespace bagnold::run
