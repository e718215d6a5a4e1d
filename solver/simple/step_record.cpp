// Residual bookkeeping of the outer iteration (step_record.hpp).
#include "solver/simple/step_record.hpp"

#include <fmt/format.h>

#include <cmath>

namespace bagnold::solver {

const char* equation_name(int equation) {
  static const char* names[equation_count] = {
      "gas x momentum",    "gas y momentum",    "gas z momentum",      "solids x momentum",
      "solids y momentum", "solids z momentum", "mixture continuity", "solids continuity",
      "granular energy"};
  return equation >= 0 && equation < equation_count ? names[equation] : "unknown equation";
}

const char* intervention_name(int intervention) {
  static const char* names[intervention_count] = {
      "limit_compression", "limit_zero_fraction", "limit_negative_stiffness",
      "limit_velocity_scale_cap", "limit_velocity_scale_floor", "limit_anderson_clipped",
      "limit_zero_temperature"};
  return names[intervention];
}

const char* linear_system_name(int kind) {
  static const char* names[linear_system_count] = {
      "linear_iterations_momentum", "linear_iterations_pressure", "linear_iterations_fraction",
      "linear_iterations_energy"};
  return names[kind];
}

double Residuals::largest() const { return value[static_cast<std::size_t>(worst())]; }

int Residuals::worst() const {
  int worst = 0;
  for (int e = 1; e < equation_count; ++e) {
    if (std::isnan(value[static_cast<std::size_t>(worst)])) break;  // NaN stays the worst
    if (!(value[static_cast<std::size_t>(e)] <= value[static_cast<std::size_t>(worst)])) worst = e;
  }
  return worst;
}

bool StepResult::diverged() const {
  const double last = residuals.largest();
  return !std::isfinite(last) || last > first_largest;
}

std::string CellLocation::text() const {
  std::string s = fmt::format("cell ({}, {}, {}) at ({:.4g}, {:.4g}, {:.4g}) m", cell[0], cell[1],
                              cell[2], position[0], position[1], position[2]);
  if (!face.empty()) s += ", its " + face + " face";
  if (!region.empty()) s += " (on boundary region '" + region + "')";
  return s;
}

void IterationSums::reduce(const parallel::Communicator& comm) {
  // One contiguous buffer, one Allreduce: 6 × MomentumResidual::Sums::size momentum sums, 2 × 2
  // continuity sums, 2 energy sums, counters, 2 × 3 wall forces, the stop request.
  constexpr std::size_t count = 6 * MomentumResidual::Sums::size + 4 + 2 + intervention_count + 6 + 1;
  std::array<double, count> buffer{};
  std::size_t k = 0;
  for (auto& m : momentum)
    for (double& v : m.values) buffer[k++] = v;
  for (auto& c : continuity)
    for (double& v : c) buffer[k++] = v;
  for (double& v : energy) buffer[k++] = v;
  for (double& v : interventions) buffer[k++] = v;
  for (auto& w : wall_shear)
    for (double& v : w) buffer[k++] = v;
  buffer[k++] = stop;
  comm.sum_in_place(buffer.data(), count);
  k = 0;
  for (auto& m : momentum)
    for (double& v : m.values) v = buffer[k++];
  for (auto& c : continuity)
    for (double& v : c) v = buffer[k++];
  for (double& v : energy) v = buffer[k++];
  for (double& v : interventions) v = buffer[k++];
  for (auto& w : wall_shear)
    for (double& v : w) v = buffer[k++];
  stop = buffer[k++];
}

void WorstCells::reset(int equation) {
  m_value[static_cast<std::size_t>(equation)] = 0.0;
  m_local[static_cast<std::size_t>(equation)] = -1;
}

bool iteration_converged(double largest, double tolerance, const IterationSums& sums) {
  return largest < tolerance && sums.interventions[compression_damped] == 0.0;
}

void judge_momentum(const IterationSums& sums, StepResult& result) {
  result.force_balance = 0.0;
  result.force_balance_equation = 0;
  for (int e = 0; e < 6; ++e) {
    const auto& momentum = sums.momentum[static_cast<std::size_t>(e)];
    result.residuals.value[static_cast<std::size_t>(e)] = sums.normalization[static_cast<std::size_t>(e)].value(momentum);
    if (const double balance = MomentumResidual::force_balance(momentum); balance > result.force_balance) {
      result.force_balance = balance;
      result.force_balance_equation = e;
    }
  }
}

}  // namespace bagnold::solver
