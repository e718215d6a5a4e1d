// The minimal closure: MFIX's plastic pressure and a constant viscosity. See the header.
#include "models/stress/plastic.hpp"

#include <algorithm>
#include <limits>

#include "models/stress/pointwise.hpp"

namespace bagnold::models::plastic {

void Plastic::evaluate(const Material& /*material*/, const SolidsState& in, SolidsStress& out) const {
  const double packed_fraction = m_constants.plastic.packed_fraction();
  evaluate_cells(in, out, [&](double phi, double /*shear_rate*/, double /*divergence*/) {
    PointStress p;
    p.granular_temperature = std::numeric_limits<double>::quiet_NaN();
    const auto plastic = m_constants.plastic.at(phi);
    p.pressure = plastic.pressure;
    p.pressure_derivative = plastic.derivative;
    p.shear_viscosity = m_constants.viscosity * std::clamp(phi / packed_fraction, 0.0, 1.0);
    return p;
  });
}

double Plastic::packing_limit(const Material& /*material*/) const {
  return m_constants.plastic.packed_fraction();
}

namespace {
[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "plastic",
     .summary = "minimal closure: MFIX's plastic pressure and a constant viscosity",
     .coefficients = concatenate(
         {PlasticPressure::specs(),
          {real_spec("viscosity", "Pa s", Constants{}.viscosity, 0.0, 1e5,
                     "μ_0 [Pa s]: solids viscosity in the packed bed, μ_s = μ_0 min(ε_s/ε_s*, 1).")}}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<Plastic>(Constants{.plastic = PlasticPressure::read(c),
                                                  .viscosity = real_coefficient(c, "viscosity")});
     }});
}  // namespace

}  // namespace bagnold::models::plastic
