#pragma once
// Constants the report tabulates at a few interparticle friction coefficients μ only
// (App. A Tables I–II, App. B Table II, App. D Table I). Between the tabulated μ we interpolate
// piecewise-linearly in μ; outside the table we clamp to its end values (the report gives no
// rule; docs/models.md, "Friction between tabulated values"). For App. A/B that is μ ∈ [0, 1].

#include <initializer_list>
#include <vector>

namespace bagnold::models {

class FrictionTable {
 public:
  // friction: strictly increasing μ; values: the constant at each μ (same length, ≥ 1 entry).
  FrictionTable(std::initializer_list<double> friction, std::initializer_list<double> values);
  double operator()(double friction) const;  // interpolated, clamped to the table's μ range
  double min_friction() const { return m_friction.front(); }
  double max_friction() const { return m_friction.back(); }

 private:
  std::vector<double> m_friction;
  std::vector<double> m_values;
};

// Chialvo, Sun & Sundaresan (2012): App. A Tables I–II, reused by App. B Table II.
namespace chialvo2012 {
double critical_fraction(double friction);         // φ_c(μ) [-], App. A Table I
double yield_stress_ratio(double friction);        // η_s(μ) [-], App. A Table II
double quasi_static_coefficient(double friction);  // α_QS(μ) [-], App. A Table II
}  // namespace chialvo2012

}  // namespace bagnold::models
