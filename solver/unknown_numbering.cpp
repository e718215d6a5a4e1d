#include "solver/unknown_numbering.hpp"

namespace bagnold::solver {

UnknownNumbering::UnknownNumbering(const parallel::Layout& layout,
                                   const std::function<bool(int local)>& carries) {
  for (int l = 0; l < layout.owned_count(); ++l)
    if (carries(l)) owned_locals.push_back(l);
  first_row = layout.comm().exclusive_scan(owned_rows());
  total_rows = layout.comm().sum(owned_rows());
  global.assign(static_cast<std::size_t>(layout.local_count()), -1);
  for (std::size_t r = 0; r < owned_locals.size(); ++r)
    global[static_cast<std::size_t>(owned_locals[r])] = first_row + static_cast<std::int64_t>(r);
  parallel::exchange_halo<std::int64_t>(layout, global);
}

}  // namespace bagnold::solver
