// The normalized momentum residual of one phase and component (momentum_residual.hpp).
#include "solver/simple/momentum_residual.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bagnold::solver {

ResidualNormalization residual_normalization_from_name(const std::string& name) {
  if (name == "deviation") return ResidualNormalization::deviation;
  if (name == "velocity-scale") return ResidualNormalization::velocity_scale;
  throw std::invalid_argument("unknown residual normalization '" + name + "'");
}

double MomentumResidual::add(double diagonal, double operator_u, double operator_one, double source,
                             double transient, double weight) {
  const double row_residual = std::abs(source - operator_u);
  m_residual += row_residual;
  m_net += source - operator_u;
  m_weight += weight;
  if (m_kind == ResidualNormalization::deviation) {
    const double uniform = operator_one * m_mean;
    m_norm += std::abs(operator_u - uniform) + std::abs(source - uniform) + transient * m_least_speed;
  } else {
    m_norm += diagonal * m_velocity_scale;
  }
  return row_residual;
}

double MomentumResidual::value(const parallel::Communicator& comm) const {
  const double residual = comm.sum(m_residual);
  const double norm = comm.sum(m_norm);
  const double normalized = residual <= 1e-300 ? 0.0 : residual / std::max(norm, 1e-300);
  if (!m_net_force) return normalized;
  const double net = std::abs(comm.sum(m_net));
  const double weight = comm.sum(m_weight);
  return weight > 0.0 ? std::max(normalized, net / weight) : normalized;
}

}  // namespace bagnold::solver
