#include "solver/simple/row_location.hpp"

#include <utility>

namespace bagnold::solver {

CellLocation locate_row(const parallel::Domain& domain, int equation, std::int64_t owner,
                        std::int64_t plus) {
  auto fluid = [&](std::int64_t n) {
    return n >= 0 && domain.flags.kind[static_cast<std::size_t>(n)] == grid::CellKind::fluid;
  };
  CellLocation where;
  std::int64_t cell = owner, beyond = plus;
  if (equation < mixture_continuity) {
    const char axis = static_cast<char>('x' + equation % 3);
    where.face = std::string("+") + axis;
    if (!fluid(cell) && fluid(beyond)) {
      std::swap(cell, beyond);
      where.face = std::string("-") + axis;
    }
    if (beyond >= 0 && !fluid(beyond)) {
      const int r = domain.flags.region[static_cast<std::size_t>(beyond)];
      if (r >= 0) where.region = domain.regions.regions[static_cast<std::size_t>(r)].name;
    }
  }
  where.cell = domain.grid.index3(cell);
  where.position = domain.grid.centre(where.cell);
  return where;
}

}  // namespace bagnold::solver
