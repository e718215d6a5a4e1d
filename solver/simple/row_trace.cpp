#include "solver/simple/row_trace.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "solver/simple/row_location.hpp"

namespace bagnold::solver {

RowTrace::RowTrace() {
  const char* text = std::getenv("BAGNOLD_TRACE_ROWS");
  if (!text || !*text) return;
  char* end = nullptr;
  const double fraction = std::strtod(text, &end);
  if (end != text && *end == '\0' && fraction > 0.0 && std::isfinite(fraction)) m_fraction = fraction;
}

bool RowTrace::selects(const Row& row) const {
  return m_fraction && std::abs(row.residual) > *m_fraction * scale(row);
}

std::string RowTrace::line(const parallel::Domain& domain, const Row& row) const {
  const CellLocation where = locate_row(domain, momentum_equation(row.phase, row.component), row.owner, row.plus);
  const double against = scale(row);
  char text[512];
  std::snprintf(text, sizeof text,
                "row %s %c (%d, %d, %d) %s: r/w = %.3g, r = %.4g N, F = %.4g N, A = %.4g kg/s, "
                "u = %.6g m/s, b = %.6g N, sum a_nb u_nb = %.6g N, viscous = %.4g N",
                row.phase == 0 ? "gas" : "solids", static_cast<char>('x' + row.component),
                where.cell[0], where.cell[1], where.cell[2], where.face.c_str(),
                against > 0.0 ? row.residual / against : 0.0, row.residual, row.force, row.diagonal,
                row.velocity, row.sources, row.neighbours, row.viscous);
  return text;
}

void RowTrace::report(const parallel::Domain& domain, const parallel::Communicator& comm, const Row& row) const {
  if (!selects(row)) return;
  const std::string text = line(domain, row);
  if (comm.size() > 1)
    std::fprintf(stderr, "    [rank %d] %s\n", comm.rank(), text.c_str());
  else
    std::fprintf(stderr, "    %s\n", text.c_str());
}

}  // namespace bagnold::solver
