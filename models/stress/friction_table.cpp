#include "models/stress/friction_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace bagnold::models {

FrictionTable::FrictionTable(std::initializer_list<double> friction,
                             std::initializer_list<double> values)
    : m_friction(friction), m_values(values) {
  if (m_friction.empty() || m_friction.size() != m_values.size())
    throw std::invalid_argument("FrictionTable: friction and value lists differ in length");
  if (!std::is_sorted(m_friction.begin(), m_friction.end(), std::less_equal<>()))
    throw std::invalid_argument("FrictionTable: friction values must increase strictly");
}

double FrictionTable::operator()(double friction) const {
  if (!(friction > m_friction.front())) return m_values.front();  // also catches NaN
  if (friction >= m_friction.back()) return m_values.back();
  const auto upper = std::upper_bound(m_friction.begin(), m_friction.end(), friction);
  const auto i = static_cast<std::size_t>(upper - m_friction.begin());
  const double weight = (friction - m_friction[i - 1]) / (m_friction[i] - m_friction[i - 1]);
  return m_values[i - 1] + weight * (m_values[i] - m_values[i - 1]);
}

namespace chialvo2012 {
// The five friction coefficients of the DEM data, App. A Tables I and II.
double critical_fraction(double friction) {
  static const FrictionTable table{{0.0, 0.1, 0.3, 0.5, 1.0}, {0.636, 0.613, 0.596, 0.587, 0.581}};
  return table(friction);
}
double yield_stress_ratio(double friction) {
  static const FrictionTable table{{0.0, 0.1, 0.3, 0.5, 1.0}, {0.105, 0.268, 0.357, 0.382, 0.405}};
  return table(friction);
}
double quasi_static_coefficient(double friction) {
  static const FrictionTable table{{0.0, 0.1, 0.3, 0.5, 1.0}, {0.095, 0.083, 0.14, 0.20, 0.25}};
  return table(friction);
}
}  // namespace chialvo2012

}  // namespace bagnold::models
