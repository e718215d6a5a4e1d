#pragma once
// Regularization of the viscosity of rate-independent (frictional, quasi-static, cohesive)
// stresses: μ = τ/γ̇ diverges as γ̇ → 0 (DESIGN.md, "Dense regime"). Two deck keys, declared
// once here and shared by every stress model:
//   min_strain_rate  γ̇_min [1/s]:  μ = τ / sqrt(γ̇² + γ̇_min²)   (smooth, exact for γ̇ ≫ γ̇_min)
//   max_viscosity    μ_max [Pa s]: μ ≤ μ_max                    (a hard cap on the total)

#include <vector>

#include "models/coefficients.hpp"

namespace bagnold::models {

// μ_max [Pa s] of the rheologies (steady-shear, steady-shear-cohesive): high enough that the
// yield stress η_s p of a packed bed at the loads of a bin holds down to γ̇ ≈ 10⁻² 1/s, which
// moves the bins' and the hourglass's discharge by no more than 10⁸ would (docs/models.md). The
// kinetic models keep ViscosityLimits' 10⁵ (their plug is set by the dense limit's yield stress
// at 10⁵ as at 10⁶, docs/benchmarks.md).
inline constexpr double rheology_max_viscosity = 1e7;

struct ViscosityLimits {
  double min_strain_rate = 1e-3;  // γ̇_min [1/s]
  double max_viscosity = 1e5;     // μ_max [Pa s]

  // The two keys with the defaults above, or with another μ_max (the rheologies' above,
  // mfix-default: MFIX's cap).
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
