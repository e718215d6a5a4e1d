#pragma once
// What a domain holds, for `bagnold check` and the start of a run: cell counts, the partition's
// balance and the memory the fields take (each region's cells: src/run/region_census.hpp).
// Collective; the text is for rank 0.

#include <string>

#include "src/parallel/domain.hpp"

namespace bagnold::parallel {

struct DomainSummary {
  std::int64_t box_cells = 0;       // nx * ny * nz
  std::int64_t fluid_cells = 0;
  std::int64_t boundary_cells = 0;
  std::int64_t min_owned_fluid = 0, max_owned_fluid = 0;  // over ranks
  std::int64_t max_local_cells = 0;                       // owned + halo, largest rank
  double imbalance = 0.0;  // max owned fluid / mean − 1
};

DomainSummary summarize(const Domain& domain);
std::string summary_text(const Domain& domain, const DomainSummary& s, int fields_per_cell);

}  // namespace bagnold::parallel
