// The solids momentum components in one linear system (coupled_solids_momentum.hpp).
#include "solver/simple/coupled_solids_momentum.hpp"

#include <algorithm>
#include <cstddef>

#include "src/parallel/layout.hpp"

namespace bagnold::solver {

namespace {
// The local cells whose e-faces carry the u_e of row l's cross part on its faces normal to e
// (momentum_assembly.cpp): on the + side the + faces of c = l and of its + neighbour n along d,
// on the − side those of the cells below them along e. −1 where there is no such cell.
template <class Visit>
void for_each_cross_cell(const parallel::Layout& layout, int l, int d, Visit&& visit) {
  const int n = layout.neighbour(l, 2 * d + 1);
  for (int face = 0; face < 6; ++face) {
    const int e = parallel::face_direction(face);
    if (e == d) continue;
    const bool plus = parallel::face_sign(face) > 0;
    visit(e, plus ? l : layout.neighbour(l, face));
    visit(e, plus ? n : (n >= 0 ? layout.neighbour(n, face) : -1));
  }
}
}  // namespace

CoupledSolidsMomentum::CoupledSolidsMomentum(const Discretization& discretization,
                                             const KrylovSettings& krylov)
    : m_discretization(discretization) {
  const auto& layout = discretization.layout();
  const auto& comm = layout.comm();
  const auto ranks = static_cast<std::size_t>(comm.size());
  // Each component's rows are numbered contiguously in rank order (UnknownNumbering), so its
  // first row on a rank is the sum of the earlier ranks' counts.
  for (std::size_t d = 0; d < 3; ++d) {
    m_component_rows[d] = comm.all_gather(discretization.velocity_numbering(static_cast<int>(d)).owned_rows());
    m_component_first[d].assign(ranks, 0);
    for (std::size_t q = 1; q < ranks; ++q)
      m_component_first[d][q] = m_component_first[d][q - 1] + m_component_rows[d][q - 1];
  }
  m_rank_first.assign(ranks, 0);
  for (std::size_t q = 1; q < ranks; ++q)
    for (std::size_t d = 0; d < 3; ++d) m_rank_first[q] += m_component_first[d][q];
  const auto rank = static_cast<std::size_t>(comm.rank());
  for (std::size_t d = 1; d < 3; ++d) m_offset[d] = m_offset[d - 1] + m_component_rows[d - 1][rank];
  // Every stored face's coupled row, once: set_row looks them up per outer iteration.
  for (int e = 0; e < 3; ++e) {
    const auto& global = discretization.velocity_numbering(e).global;
    auto& rows = m_index[static_cast<std::size_t>(e)];
    rows.resize(global.size());
    for (std::size_t l = 0; l < global.size(); ++l) rows[l] = global[l] >= 0 ? coupled(e, global[l]) : -1;
  }

  for (int d = 0; d < 3; ++d) {
    const auto& numbering = discretization.velocity_numbering(d);
    const SparsityPattern own = discretization.momentum_pattern(d);
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      std::vector<std::int64_t> columns;
      for (auto k = own.offsets[r]; k < own.offsets[r + 1]; ++k)
        columns.push_back(coupled(d, own.columns[static_cast<std::size_t>(k)]));
      for_each_cross_cell(layout, numbering.owned_locals[r], d, [&](int e, int cell) {
        const std::int64_t column = coupled_at(e, cell);
        if (column >= 0) columns.push_back(column);
      });
      m_pattern.add_row(columns.data(), static_cast<int>(columns.size()));
    }
  }
  m_system = std::make_unique<LinearSystem>(comm.get(), m_pattern, m_rank_first[rank], "solids_momentum_", krylov);
  m_x.resize(static_cast<std::size_t>(m_pattern.rows()));
}

std::int64_t CoupledSolidsMomentum::coupled(int e, std::int64_t g) const {
  const auto& first = m_component_first[static_cast<std::size_t>(e)];
  const auto q = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), g) - first.begin() - 1);
  std::int64_t row = m_rank_first[q];
  for (std::size_t d = 0; d < static_cast<std::size_t>(e); ++d) row += m_component_rows[d][q];
  return row + (g - first[q]);
}

std::int64_t CoupledSolidsMomentum::coupled_at(int e, int cell) const {
  return cell >= 0 ? m_index[static_cast<std::size_t>(e)][static_cast<std::size_t>(cell)] : -1;
}

void CoupledSolidsMomentum::set_row(int d, std::size_t r, const MomentumRow& row, double diagonal,
                                    double rhs, const std::array<std::vector<double>, 3>& velocity) {
  const auto& numbering = m_discretization.velocity_numbering(d);
  const auto ul = static_cast<std::size_t>(numbering.owned_locals[r]);
  m_columns.clear();
  m_values.clear();
  for (int k = 0; k < row.count; ++k) {
    m_columns.push_back(coupled(d, row.columns[k]));
    m_values.push_back(row.active ? row.values[k] : 0.0);
  }
  m_columns.push_back(coupled_at(d, static_cast<int>(ul)));
  m_values.push_back(diagonal);
  // Every column of the pattern is written each time (set_row keeps what it is not given).
  for_each_cross_cell(m_discretization.layout(), static_cast<int>(ul), d, [&](int e, int cell) {
    const std::int64_t column = coupled_at(e, cell);
    if (column < 0) return;
    m_columns.push_back(column);
    m_values.push_back(0.0);
  });
  if (row.active)
    for (int k = 0; k < row.cross_count; ++k) {
      const int e = row.cross_component[k];
      const std::int64_t column = coupled_at(e, row.cross_cell[k]);
      if (column < 0) continue;  // a given velocity: it stays on the right-hand side
      m_columns.push_back(column);
      m_values.push_back(-row.cross_coefficient[k]);
      rhs -= row.cross_coefficient[k] * velocity[static_cast<std::size_t>(e)][static_cast<std::size_t>(row.cross_cell[k])];
    }
  m_system->set_row(coupled_at(d, static_cast<int>(ul)), m_columns.data(), m_values.data(),
                    static_cast<int>(m_columns.size()), rhs);
  m_x[static_cast<std::size_t>(m_offset[static_cast<std::size_t>(d)]) + r] = row.active ? velocity[static_cast<std::size_t>(d)][ul] : 0.0;
}

SolveReport CoupledSolidsMomentum::solve(std::array<std::vector<double>, 3>& velocity) {
  m_system->set_assembly_units(0.0);  // the rows were assembled, and counted, by each predict
  const SolveReport report = m_system->solve(m_x);
  const auto& layout = m_discretization.layout();
  for (int d = 0; d < 3; ++d) {
    const auto& numbering = m_discretization.velocity_numbering(d);
    auto& u = velocity[static_cast<std::size_t>(d)];
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r)
      u[static_cast<std::size_t>(numbering.owned_locals[r])] = m_x[static_cast<std::size_t>(m_offset[static_cast<std::size_t>(d)]) + r];
    parallel::exchange_halo<double>(layout, u);
  }
  return report;
}

}  // namespace bagnold::solver
