// The limiter on a compressing volume fraction correction (compression_limit.hpp).
#include "solver/simple/compression_limit.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

CompressionLimit::CompressionLimit(const Discretization& discretization,
                                   const SolverSettings& settings, const Closures& closures)
    : m_discretization(discretization),
      m_closures(closures),
      m_floor(std::max(settings.density[solids] * settings.gravity_magnitude *
                           discretization.smallest_width() * floor_fraction,
                       least_floor)) {
  const auto cells = static_cast<std::size_t>(discretization.layout().owned_fluid_count());
  m_cells.reserve(cells);
  for (auto* v : {&m_lambda, &m_candidate, &m_rate, &m_divergence, &m_pressure, &m_derivative,
                  &m_shear, &m_bulk, &m_temperature})
    v->resize(cells);
}

void CompressionLimit::apply(const run::FlowState& state, const ClosureFields& fields,
                             std::vector<double>& correction, IterationSums& sums) {
  const auto& eps = state.solids_fraction;
  m_cells.clear();
  for (const int l : m_discretization.cell_numbering().owned_locals) {
    auto& c = correction[static_cast<std::size_t>(l)];
    const double current = eps[static_cast<std::size_t>(l)];
    if (current + c < 0.0) {  // never below zero
      c = -current;
      sums.interventions[fraction_clamped_at_zero] += 1.0;
    }
    if (c > 0.0) m_cells.push_back(l);
  }
  if (m_cells.empty()) return;
  const std::size_t n = m_cells.size();
  auto part = [n](std::vector<double>& v) { return std::span<double>(v.data(), n); };
  auto input = [n](const std::vector<double>& v) { return std::span<const double>(v.data(), n); };
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(m_cells[k]);
    m_lambda[k] = 1.0;
    m_rate[k] = state.pressure_shear_rate[i];  // the rate P_s was evaluated at
    m_divergence[k] = fields.divergence[solids][i];
  }
  const auto& stress = *m_closures.stress();
  for (int halving = 0; halving < max_halvings; ++halving) {
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(m_cells[k]);
      m_candidate[k] = eps[i] + m_lambda[k] * correction[i];
    }
    models::SolidsStress out{part(m_pressure), part(m_derivative), part(m_shear), part(m_bulk),
                             part(m_temperature)};
    stress.evaluate(m_closures.material(), {input(m_candidate), input(m_rate), input(m_divergence)}, out);
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(m_cells[k]);
      const double predicted = state.solids_pressure[i] +
                               std::max(fields.pressure_derivative[i], 0.0) * m_lambda[k] * correction[i];
      if (!(m_pressure[k] <= overshoot_ratio * predicted + m_floor)) {  // NaN fails too
        m_lambda[k] *= 0.5;
        any = true;
      }
    }
    if (!any) break;
  }
  for (std::size_t k = 0; k < n; ++k) {
    correction[static_cast<std::size_t>(m_cells[k])] *= m_lambda[k];
    if (m_lambda[k] < 1.0) sums.interventions[compression_damped] += 1.0;
  }
}

}  // namespace bagnold::solver
