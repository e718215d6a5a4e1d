// The normalized momentum residual of one phase and component (momentum_residual.hpp).
#include "solver/simple/momentum_residual.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bagnold::solver {

double MomentumResidual::add(Sums& sums, double diagonal, double operator_u, double operator_one,
                             double source, double transient, double weight) const {
  auto& [residual, norm, net, total_weight] = sums.values;
  const double row_residual = std::abs(source - operator_u);
  residual += row_residual;
  net += source - operator_u;
  total_weight += weight;
  if (m_kind == ResidualNormalization::deviation) {
    const double uniform = operator_one * m_mean;
    norm += std::abs(operator_u - uniform) + std::abs(source - uniform) + transient * m_least_speed;
  } else {
    norm += diagonal * m_velocity_scale;
  }
  return row_residual;
}

double MomentumResidual::value(const Sums& total) const {
  const auto& [residual, norm, net, weight] = total.values;
  const double normalized = residual <= 1e-300 ? 0.0 : residual / std::max(norm, 1e-300);
  if (!m_net_force) return normalized;
  return weight > 0.0 ? std::max(normalized, std::abs(net) / weight) : normalized;
}

}  // namespace bagnold::solver
