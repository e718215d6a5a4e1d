#pragma once
// Regularization of the viscosity of rate-independent (frictional, quasi-static, cohesive)
// stresses: μ = τ/γ̇ diverges as γ̇ → 0 (DESIGN.md, "Dense regime"). Two deck keys, declared
// once here and shared by every stress model:
//   min_strain_rate  γ̇_min [1/s]:  μ = τ / sqrt(γ̇² + γ̇_min²)   (smooth, exact for γ̇ ≫ γ̇_min)
//   max_viscosity    μ_max [Pa s]: μ ≤ μ_max                    (a hard cap on the total)

#include <vector>

#include "models/coefficients.hpp"

namespace bagnold::models {

struct ViscosityLimits {
  // γ̇_min [1/s]: off by default, so that μ_max alone bounds the viscosity of a packed zone. A
  // positive γ̇_min caps μ_s at η p/γ̇_min, which depends on the load: 10⁻³ 1/s caps the chute's
  // jammed base near 10⁵ Pa s and makes its surface flow 28 % fast (docs/models.md, "Viscosity
  // regularization").
  double min_strain_rate = 0.0;
  // μ_max [Pa s]: high enough that the creep it allows moves no shipped case: the no-slip chute
  // with sidewalls, whose arrested base and walls set its flow, moves by 0.03 % from 10⁹ to 10¹⁰
  // (2.8 % from 10⁷ to 10⁸); the bins and the hourglass by less than 0.1 % from 10⁷ on
  // (docs/models.md, docs/benchmarks.md). mfix-default has MFIX's own cap instead.
  double max_viscosity = 1e9;

  // The two keys with the defaults above, or with another μ_max (mfix-default: MFIX's cap).
  static std::vector<CoefficientSpec> specs();
  static std::vector<CoefficientSpec> specs(double default_max_viscosity);
  static ViscosityLimits read(const Coefficients& c);

  // Viscosity of a stress τ that does not vanish with the shear rate.
  double rate_independent_viscosity(double stress, double shear_rate) const;
  // A kinetic viscosity plus the regularized viscosity of a rate-independent (yield) stress,
  // capped.
  double with_yield_stress(double kinetic_viscosity, double yield_stress, double shear_rate) const {
    return capped(kinetic_viscosity + rate_independent_viscosity(yield_stress, shear_rate));
  }
  double capped(double viscosity) const {
    return viscosity < max_viscosity ? viscosity : max_viscosity;
  }
};

}  // namespace bagnold::models
