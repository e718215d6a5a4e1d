// MFIX's default: algebraic kinetic theory, Schaeffer friction, plastic pressure. See the header.
#include "models/stress/mfix_default.hpp"

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"
#include "models/stress/dense_limit.hpp"
#include "models/stress/pointwise.hpp"

namespace bagnold::models::mfix_default {

namespace {
using std::numbers::pi;

// Schaeffer's stress in MFIX is 2 μ D with no second viscosity (FRICTION_SCHAEFFER in
// calc_mu_s.f sets LAMBDA_s_p = 0), so its isotropic part 2μ/3 tr D is a bulk viscosity ⅔ μ in
// Bagnold's σ = 2μ S + λ (tr D) I.
double schaeffer_bulk_viscosity(double friction_viscosity) { return 2.0 / 3.0 * friction_viscosity; }

// The algebraic kinetic theory's coefficients per power of T: P = pressure·T, μ = shear·√T,
// λ = bulk·√T (the bulk viscosity: MFIX's second viscosity LAMBDA_s plus ⅔μ), and the
// collisional dissipation Γ = dissipation·T^{3/2}. Both theories share Γ and the collisional
// pressure; Lun et al. add the streaming pressure ρ_s φ T and their own viscosities.
template <class Real>
struct KineticCoefficients {
  Real pressure, shear, bulk, dissipation;
};

// Γ = 12(1 − e²) ρ_s φ² g0 T^{3/2}/(√π d): MFIX's K_4m φ² (Syamlal 1987; Lun et al. 1984).
template <class Real>
Real dissipation_coefficient(Real phi, Real g0, const Material& m) {
  return 12.0 * (1.0 - m.restitution * m.restitution) * m.density * phi * phi * g0 /
         (std::sqrt(pi) * m.diameter);
}

// Syamlal's algebraic theory, as MFIX's GT_ALGEBRAIC (calc_mu_s.f) computes it whenever the
// granular energy is algebraic (Syamlal 1987, "A review of granular stress constitutive
// relations", topical report DOE/MC/21353-2372, the reference GT_ALGEBRAIC gives): with
// K_1 = 2(1 + e) ρ_s g0,
// K_3 = (d ρ_s/2)[√π/(3(3 − e)) (½(3e + 1) + ⅖(1 + e)(3e − 1) φ g0) + 8 φ g0 (1 + e)/(5√π)],
// K_2 = 4 d ρ_s (1 + e) φ g0/(3√π) − ⅔ K_3:  P = K_1 φ² T, μ = K_3 φ √T, MFIX's second viscosity
// K_2 φ √T, so the bulk viscosity is (K_2 + ⅔ K_3) φ √T. No streaming pressure.
template <class Real>
KineticCoefficients<Real> syamlal_coefficients(Real phi, const Material& m) {
  const double e = m.restitution;
  const Real g0 = rdf::carnahan_starling(phi);
  const double sqrt_pi = std::sqrt(pi);
  KineticCoefficients<Real> c;
  c.pressure = 2.0 * (1.0 + e) * m.density * g0 * phi * phi;
  const Real k3 = 0.5 * m.diameter * m.density *
                  (sqrt_pi / (3.0 * (3.0 - e)) *
                       (0.5 * (3.0 * e + 1.0) + 0.4 * (1.0 + e) * (3.0 * e - 1.0) * phi * g0) +
                   8.0 * phi * g0 * (1.0 + e) / (5.0 * sqrt_pi));
  c.shear = k3 * phi;
  c.bulk = 4.0 * m.diameter * m.density * (1.0 + e) * phi * phi * g0 / (3.0 * sqrt_pi);
  c.dissipation = dissipation_coefficient(phi, g0, m);
  return c;
}

// Lun et al. (1984, J. Fluid Mech. 140, Eqs. for P, μ and μ_b as MFIX's GT_PDE_LUN uses them),
// η = (1 + e)/2: P = ρ_s φ T (1 + 4ηφ g0),
// μ = μ*/(η(2 − η) g0) (1 + (8/5)ηφ g0)(1 + (8/5)η(3η − 2)φ g0) + (3/5)η μ_b, λ = η μ_b,
// μ* = 5ρ_s d √(πT)/96, μ_b = 256 μ* φ² g0/(5π).
template <class Real>
KineticCoefficients<Real> lun_coefficients(Real phi, const Material& m) {
  const double eta = 0.5 * (1.0 + m.restitution);
  const Real g0 = rdf::carnahan_starling(phi);
  const double dilute_viscosity = 5.0 * m.density * m.diameter * std::sqrt(pi) / 96.0;  // μ*/√T
  const Real bulk = 256.0 * dilute_viscosity * phi * phi * g0 / (5.0 * pi);             // μ_b/√T
  KineticCoefficients<Real> c;
  c.pressure = m.density * phi * (1.0 + 4.0 * eta * phi * g0);
  c.shear = dilute_viscosity / (eta * (2.0 - eta) * g0) * (1.0 + 1.6 * eta * phi * g0) *
                (1.0 + 1.6 * eta * (3.0 * eta - 2.0) * phi * g0) +
            0.6 * eta * bulk;
  c.bulk = eta * bulk;
  c.dissipation = dissipation_coefficient(phi, g0, m);
  return c;
}

// √T from dissipation·x² + pressure·tr D·x − (shear·γ̇_s² + bulk·(tr D)²) = 0, the root ≥ 0,
// written without cancellation for tr D ≥ 0.
template <class Real>
Real algebraic_sqrt_temperature(const KineticCoefficients<Real>& c, double shear_rate,
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
    : m_constants(constants), m_dilute(dilute), m_limits(limits) {
  if (constants.transport) {
    if (constants.theory != KineticTheory::lun)
      throw std::invalid_argument(
          "mfix-default: granular_energy = \"transport\" needs kinetic_theory = \"lun\" "
          "(MFIX transports Θ with LUN_1984; Syamlal's theory is algebraic)");
    m_transport.emplace(constants.plastic.packed_fraction(), constants.slip_temperature_floor);
  }
}

void MfixDefault::evaluate(const Material& material, const SolidsState& in,
                           SolidsStress& out) const {
  require_valid_material(material, name());
  // Without Θ (the rheometer, the deck checks' probes) the algebraic form answers.
  if (m_transport && !in.temperature.empty()) {
    evaluate_at_temperature(material, in, out);
    return;
  }
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
      p.bulk_viscosity = schaeffer_bulk_viscosity(p.shear_viscosity);
      return p;
    }
    const Dual fraction = Dual::variable(phi);
    const auto c = m_constants.theory == KineticTheory::syamlal
                       ? syamlal_coefficients(fraction, material)
                       : lun_coefficients(fraction, material);
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

void MfixDefault::evaluate_at_temperature(const Material& material, const SolidsState& in,
                                          SolidsStress& out) const {
  const std::size_t n = in.solids_fraction.size();
  for (const std::size_t size :
       {in.strain_rate.size(), in.divergence.size(), in.temperature.size(), in.drag.size(),
        out.pressure.size(), out.pressure_derivative.size(), out.shear_viscosity.size(),
        out.bulk_viscosity.size(), out.granular_temperature.size()})
    if (size != n)
      throw std::invalid_argument(
          "mfix-default: a transported Θ needs Θ and β for every cell (arrays differ in length)");
  const double packed_fraction = m_constants.plastic.packed_fraction();
  const double sin_friction_angle = std::sin(m_constants.internal_friction_angle * pi / 180.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = in.solids_fraction[i] > 0.0 ? in.solids_fraction[i] : 0.0;
    const bool plastic = phi > packed_fraction;
    // Θ is held at 0 in the plastic regime (lun1984::GranularEnergy); the kinetic stresses at
    // the iterate's Θ elsewhere, with β for MFIX's drag-modified μ*.
    const double theta = plastic || !(in.temperature[i] > 0.0) ? 0.0 : in.temperature[i];
    const auto k = lun1984::point_terms(phi, theta, in.drag[i], 0.0, 0.0, material);
    double pressure = k.pressure_per_temperature.value * theta;
    double derivative = k.pressure_per_temperature.slope * theta;
    const double viscosity = m_limits.capped(k.shear_viscosity);
    double friction = 0.0;
    if (plastic) {
      const auto star = m_constants.plastic.at(phi);
      pressure += star.pressure;
      derivative += star.derivative;
      const double rate = deviatoric_shear_rate(in.strain_rate[i], in.divergence[i]);
      friction = m_limits.rate_independent_viscosity(star.pressure * sin_friction_angle, rate);
    }
    out.pressure[i] = pressure;
    out.pressure_derivative[i] = derivative;
    out.shear_viscosity[i] = viscosity + friction;
    out.bulk_viscosity[i] = k.bulk_viscosity + schaeffer_bulk_viscosity(friction);
    out.granular_temperature[i] = theta;
  }
}

double MfixDefault::packing_limit(const Material& /*material*/) const {
  return m_constants.plastic.packed_fraction();
}

namespace {
Constants read_constants(const Coefficients& c) {
  return {.plastic = PlasticPressure::read(c),
          .internal_friction_angle = real_coefficient(c, "internal_friction_angle"),
          .theory = string_coefficient(c, "kinetic_theory") == "lun" ? KineticTheory::lun
                                                                     : KineticTheory::syamlal,
          .transport = string_coefficient(c, "granular_energy") == "transport",
          .slip_temperature_floor = real_coefficient(c, "slip_temperature_floor")};
}

[[maybe_unused]] const bool registered = stress_registry().add(
    {.name = "mfix-default",
     .summary = "MFIX default: algebraic kinetic theory, Schaeffer friction, plastic pressure",
     .coefficients = concatenate(
         {PlasticPressure::specs(true),
          {real_spec("internal_friction_angle", "deg", Constants{}.internal_friction_angle, 0.0, 90.0,
                     "φ_f [deg] (MFIX PHI): Schaeffer's frictional viscosity P* sin φ_f/γ̇_s."),
           choice_spec("kinetic_theory", "syamlal", {"syamlal", "lun"},
                       "The algebraic granular temperature's theory [-]: syamlal = MFIX's "
                       "algebraic one (GT_ALGEBRAIC, P = 2(1 + e) ρ_s g0 φ² T, no streaming "
                       "part); lun = Lun et al. (1984) with the streaming pressure ρ_s φ T "
                       "(MFIX's LUN_1984 stresses, here with the algebraic balance)."),
           choice_spec("granular_energy", "algebraic", {"algebraic", "transport"},
                       "How Θ is found [-]: algebraic = the local balance production = "
                       "dissipation (MFIX's GRANULAR_ENERGY = .FALSE.); transport = the granular "
                       "energy equation with convection, conduction and the gas–solids exchange "
                       "(MFIX's KT_TYPE = 'LUN_1984': needs kinetic_theory = \"lun\", and "
                       "initial granular_temperature)."),
           real_spec("slip_temperature_floor", "m^2/s^2", lun1984::default_slip_temperature_floor,
                     1e-30, 1e-6,
                     "A regularization of the transport form: Θ_floor [m^2/s^2] in Koch & Sangani's slip "
                     "production 81 φ (μ_g |u_g − u_s|)² / (g0 d³ ρ_s √π √(Θ + Θ_floor)) "
                     "(MFIX's SMALL_NUMBER), so that the production is finite where Θ = 0. It "
                     "changes the production only where Θ is within a few Θ_floor of 0, i.e. in a "
                     "cell whose Θ is just starting to rise; the bubbling bed's averages move with "
                     "it 10x smaller no more than with a 1 % change of the first dt "
                     "(cases/fluidized-bed/README.md).")},
          DiluteLimit::specs(),
          ViscosityLimits::specs(100.0)}),
     .make = [](const Coefficients& c) -> std::unique_ptr<SolidsStressModel> {
       return std::make_unique<MfixDefault>(read_constants(c), DiluteLimit::read(c),
                                             ViscosityLimits::read(c));
     }});
}  // namespace

}  // namespace bagnold::models::mfix_default
