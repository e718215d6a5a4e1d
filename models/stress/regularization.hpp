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
  double min_strain_rate = 1e-3;  // γ̇_min [1/s]
  // μ_max [Pa s]: high enough that the yield stress of a packed bed at the loads of a bin holds
  // down to γ̇ ≈ 10⁻² 1/s; at 10⁸ the bins' and the hourglass's discharge is the same
  // (docs/models.md, docs/benchmarks.md). mfix-default has MFIX's own cap instead.
  double max_viscosity = 1e7;

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
