#include "models/stress/regularization.hpp"

#include <cmath>

namespace bagnold::models {

std::vector<CoefficientSpec> ViscosityLimits::specs() {
  return specs(ViscosityLimits{}.max_viscosity);
}

std::vector<CoefficientSpec> ViscosityLimits::specs(double default_max_viscosity) {
  return {
      real_spec("min_strain_rate", "1/s", ViscosityLimits{}.min_strain_rate, 0.0, 1e3,
                "γ̇_min [1/s]: rate-independent stresses get the viscosity τ/sqrt(γ̇² + γ̇_min²), "
                "finite as γ̇ → 0 and exact for γ̇ ≫ γ̇_min."),
      real_spec("max_viscosity", "Pa s", default_max_viscosity, 1e-6, 1e12,
                "μ_max [Pa s]: cap on the solids shear viscosity (stagnant, packed regions)."),
  };
}

ViscosityLimits ViscosityLimits::read(const Coefficients& c) {
  return {.min_strain_rate = real_coefficient(c, "min_strain_rate"),
          .max_viscosity = real_coefficient(c, "max_viscosity")};
}

double ViscosityLimits::rate_independent_viscosity(double stress, double shear_rate) const {
  if (stress == 0.0) return 0.0;
  const double rate = std::hypot(shear_rate, min_strain_rate);
  return rate > 0.0 ? capped(stress / rate) : max_viscosity;
}

}  // namespace bagnold::models
