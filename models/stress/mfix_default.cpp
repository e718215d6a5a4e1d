// MFIX's default: Lun et al. kinetic theory, Schaeffer friction, plastic pressure. See the header.
#include "models/stress/mfix_default.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"
#include "models/stress/dense_limit.hpp"
#include "models/stress/pointwise.hpp"

namespace bagnold::models::mfix_default {

namespace {
using std::numbers::pi;

// Lun et al. coefficients per power of T: P = pressure·T, μ = shear·√T, λ = bulk·√T,
// Γ = dissipation·T^{3/2}.
template <class Real>
struct LunCoefficients {
  Real pressure, shear, bulk, dissipation;
};

template <class Real>
LunCoefficients<Real> lun_coefficients(Real phi, const Material& m) {
  const double eta = 0.5 * (1.0 + m.restitution);
  const Real g0 = rdf::carnahan_starling(phi);
  const double dilute_viscosity = 5.0 * m.density * m.diameter * std::sqrt(pi) / 96.0;  // μ*/√T
  const Real bulk = 256.0 * dilute_viscosity * phi * phi * g0 / (5.0 * pi);             // μ_b/√T
  LunCoefficients<Real> c;
  c.pressure = m.density * phi * (1.0 + 4.0 * eta * phi * g0);
  c.shear = dilute_viscosity / (eta * (2.0 - eta) * g0) * (1.0 + 1.6 * eta * phi * g0) *
                (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * phi * g0) +
            0.6 * eta * bulk;
  c.bulk = eta * bulk;
  c.dissipation = 12.0 * (1.0 - m.restitution * m.restitution) * m.density * phi * phi * g0 /
                  (std::sqrt(pi) * m.diameter);
  return c;
}

// √T from dissipation·x² + pressure·tr D·x − (shear·γ̇_s² + bulk·(tr D)²) = 0, the root ≥ 0,
// written without cancellation for tr D ≥ 0.
template <class Real>
Real algebraic_sqrt_temperature(const LunCoefficients<Real>& c, double shear_rate,
                                double divergence) {
  using std::sqrt;
  const Real production = c.shear * shear_rate * shear_rate + c.bulk * divergence * divergence;
  const Real work = c.pressure * divergence;
  const Real root = sqrt(work * work + 4.0 * c.dissipation * production);
  if (divergence >= 0.0) {
    const Real denominator = work + root;
    return value_of(denominator) > 0.0 ? 2.0 * production / denominator : Real(0.0);
  }
  return (root - work) / (2.0 * c.dissipation);
}
}  // namespace

MfixDefault::MfixDefault(const Constants& constants, const DiluteLimit& dilute,
                         const ViscosityLimits& limits)
    : m_constants(constants), m_dilute(dilute), m_limits(limits) {}

void MfixDefault::evaluate(const Material& material, const SolidsState& in,
                           SolidsStress& out) const {
  require_valid_material(material, name());
  const double packed_fraction = m_constants.plastic.packed_fraction();
  const double sin_friction_angle = std::sin(m_constants.internal_friction_angle * pi / 180.0);
  evaluate_cells_dilute_limited(m_dilute, material, in, out,
                                [&](double phi, double shear_rate, double divergence) {
    PointStress p;
    p.granular_temperature = 0.0;
    if (phi > packed_fraction) {
      // Plastic regime: P* = A (ε_g* − ε_g)^n.
      const auto plastic = m_constants.plastic.at(phi);
      p.pressure = plastic.pressure;
      p.pressure_derivative = plastic.derivative;
      p.shear_viscosity =
          m_limits.rate_independent_viscosity(p.pressure * sin_friction_angle, shear_rate);
      return p;
    }
    const auto c = lun_coefficients(Dual::variable(phi), material);
    const Dual sqrt_temperature = algebraic_sqrt_temperature(c, shear_rate, divergence);
    const Dual pressure = c.pressure * sqrt_temperature * sqrt_temperature;
    p.pressure = pressure.value;
    p.pressure_derivative = pressure.slope;
    p.granular_temperature = sqrt_temperature.value * sqrt_temperature.value;
    p.shear_viscosity = m_limits.capped(c.shear.value * sqrt_temperature.value);
    p.bulk_viscosity = c.bulk.value * sqrt_temperature.value;
    return p;
  });
}

double MfixDefault::packing_limit(const Material& /*material*/) const {
  return m_constants.plastic.packed_fraction();
}

namespace {
Constants read_constants(const Coefficients& c) {
  return {.plastic = PlasticPressure::read(c),
          .internal_friction_angle = real_coefficient(c, "internal_friction_angle")};
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "mfix-default",
     .summary = "MFIX default: Lun et al. kinetic theory, Schaeffer friction, plastic pressure",
     .coefficients = concatenate(
         {PlasticPressure::specs(true),
          {real_spec("internal_friction_angle", "deg", Constants{}.internal_friction_angle, 0.0, 90.0,
                     "φ_f [deg] (MFIX PHI): Schaeffer's frictional viscosity P* sin φ_f/γ̇_s.")},
          DiluteLimit::specs(),
          ViscosityLimits::specs(100.0)}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<MfixDefault>(read_constants(c), DiluteLimit::read(c),
                                             ViscosityLimits::read(c));
     }});
}  // namespace

}  // namespace bagnold::models::mfix_default
