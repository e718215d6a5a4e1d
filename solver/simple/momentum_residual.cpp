// The normalized momentum residual of one phase and component (momentum_residual.hpp).
#include "solver/simple/momentum_residual.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bagnold::solver {

double MomentumResidual::add(Sums& sums, const Row& row) const {
  auto& [residual, norm, net, total_weight, every_residual, every_force] = sums.values;
  every_residual += std::abs(row.source - row.operator_u);
  every_force += row.force;
  const bool mfix = m_kind == ResidualNormalization::mfix;
  if (mfix && !row.mfix_counted) return 0.0;
  const double judged = row.source + (mfix ? row.mfix_coupling : 0.0) - row.operator_u;
  const double row_residual = std::abs(judged);
  residual += row_residual;
  net += judged;
  total_weight += row.weight;
  switch (m_kind) {
    case ResidualNormalization::force:
      norm += row.force;
      break;
    case ResidualNormalization::deviation: {
      const double uniform = row.operator_one * m_mean;
      norm += std::abs(row.operator_u - uniform) + std::abs(row.source - uniform) + row.transient * m_least_speed;
      break;
    }
    case ResidualNormalization::velocity_scale:
      norm += row.diagonal * m_velocity_scale;
      break;
    case ResidualNormalization::mfix:
      norm += row.mfix_scale;
      break;
  }
  return row_residual;
}

double MomentumResidual::value(const Sums& total) const {
  const auto& [residual, norm, net, weight, every_residual, every_force] = total.values;
  const double normalized = residual <= 1e-300 ? 0.0 : residual / std::max(norm, 1e-300);
  if (!m_net_force) return normalized;
  return weight > 0.0 ? std::max(normalized, std::abs(net) / weight) : normalized;
}

double MomentumResidual::force_balance(const Sums& total) {
  const auto& [residual, norm, net, weight, every_residual, every_force] = total.values;
  return every_residual <= 1e-300 ? 0.0 : every_residual / std::max(every_force, 1e-300);
}

}  // namespace bagnold::solver
