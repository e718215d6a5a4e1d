// The minimal closure: MFIX's plastic pressure and a constant viscosity. See the header.
#include "models/stress/plastic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/stress/pointwise.hpp"

namespace bagnold::models::plastic {

void Plastic::evaluate(const Material& /*material*/, const SolidsState& in, SolidsStress& out) const {
  const double packed_fraction = 1.0 - m_constants.packed_gas_fraction;
  const double a = m_constants.plastic_coefficient, n = m_constants.plastic_exponent;
  evaluate_cells(in, out, [&](double phi, double /*shear_rate*/, double /*divergence*/) {
    PointStress p;
    p.granular_temperature = std::numeric_limits<double>::quiet_NaN();
    const double excess = phi - packed_fraction;  // ε_g* − ε_g
    if (excess > 0.0) {
      p.pressure = a * std::pow(excess, n);
      p.pressure_derivative = a * n * std::pow(excess, n - 1.0);
    }
    p.shear_viscosity = m_constants.viscosity * std::clamp(phi / packed_fraction, 0.0, 1.0);
    return p;
  });
}

double Plastic::packing_limit(const Material& /*material*/) const { return 1.0 - m_constants.packed_gas_fraction; }

namespace {
[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "plastic",
     .summary = "minimal closure: MFIX's plastic pressure and a constant viscosity (issue 4)",
     .coefficients =
         {real_spec("packed_gas_fraction", "-", 0.4, 0.2, 0.6,
                    "ε_g* [-] (MFIX EP_STAR): below this gas fraction the plastic pressure acts."),
          real_spec("plastic_coefficient", "Pa", 1e24, 0.0, 1e30,
                    "A [Pa]: plastic pressure P* = A (ε_g* − ε_g)^n (MFIX: 10²⁵ dyn/cm²)."),
          real_spec("plastic_exponent", "-", 10.0, 1.0, 20.0,
                    "n [-]: exponent of the plastic pressure (MFIX: 10)."),
          real_spec("viscosity", "Pa s", 1.0, 0.0, 1e5,
                    "μ_0 [Pa s]: solids viscosity in the packed bed, μ_s = μ_0 min(ε_s/ε_s*, 1).")},
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<Plastic>(Constants{
           .packed_gas_fraction = real_coefficient(c, "packed_gas_fraction"),
           .plastic_coefficient = real_coefficient(c, "plastic_coefficient"),
           .plastic_exponent = real_coefficient(c, "plastic_exponent"),
           .viscosity = real_coefficient(c, "viscosity")});
     }});
}  // namespace

}  // namespace bagnold::models::plastic
