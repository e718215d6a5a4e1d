#include "src/parallel/domain_summary.hpp"

#include <cstdio>

namespace bagnold::parallel {

DomainSummary summarize(const Domain& domain) {
  const auto& comm = domain.layout.comm();
  DomainSummary s;
  s.box_cells = domain.grid.domain_cell_count();
  s.fluid_cells = domain.flags.fluid_count;
  s.boundary_cells = domain.flags.boundary_count;
  const std::int64_t mine = domain.layout.owned_fluid_count();
  s.min_owned_fluid = comm.min(mine);
  s.max_owned_fluid = comm.max(mine);
  s.max_local_cells = comm.max(std::int64_t{domain.layout.local_count()});
  const double mean = static_cast<double>(s.fluid_cells) / comm.size();
  s.imbalance = static_cast<double>(s.max_owned_fluid) / mean - 1.0;
  return s;
}

std::string summary_text(const Domain& domain, const DomainSummary& s, int fields_per_cell) {
  std::string out;
  char line[256];
  const auto& g = domain.grid;
  std::snprintf(line, sizeof line, "grid: %d x %d x %d = %lld cells in the box\n", g.cells(0),
                g.cells(1), g.cells(2), static_cast<long long>(s.box_cells));
  out += line;
  std::snprintf(line, sizeof line,
                "cells: %lld fluid (%.1f %% of the box), %lld boundary, the rest blocked and not stored\n",
                static_cast<long long>(s.fluid_cells),
                100.0 * static_cast<double>(s.fluid_cells) / static_cast<double>(s.box_cells),
                static_cast<long long>(s.boundary_cells));
  out += line;
  const int ranks = domain.layout.comm().size();
  std::snprintf(line, sizeof line,
                "partition: %d rank(s), fluid cells per rank %lld..%lld (imbalance %.2f %%)\n",
                ranks, static_cast<long long>(s.min_owned_fluid),
                static_cast<long long>(s.max_owned_fluid), 100.0 * s.imbalance);
  out += line;
  const double field_mb = static_cast<double>(s.max_local_cells) * fields_per_cell * 8.0 / 1e6;
  std::snprintf(line, sizeof line,
                "fields: %d per cell; largest rank stores %lld cells (owned + halo) = %.2f MB\n",
                fields_per_cell, static_cast<long long>(s.max_local_cells), field_mb);
  out += line;
  return out;
}

}  // namespace bagnold::parallel
