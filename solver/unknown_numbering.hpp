#pragma once
// PETSc's global numbering of one kind of unknown: the owned cells that carry one (by a
// predicate) are numbered contiguously per rank; halo cells learn their owners' numbers.

#include <cstdint>
#include <functional>
#include <vector>

#include "src/parallel/layout.hpp"

namespace bagnold::solver {

struct UnknownNumbering {
  UnknownNumbering(const parallel::Layout& layout, const std::function<bool(int local)>& carries);

  std::vector<std::int64_t> global;  // per local cell, -1 where there is no unknown
  std::vector<int> owned_locals;     // owned cells with an unknown, in row order
  std::int64_t first_row = 0;
  std::int64_t total_rows = 0;  // over all ranks
  std::int64_t owned_rows() const { return static_cast<std::int64_t>(owned_locals.size()); }
};

}  // namespace bagnold::solver
