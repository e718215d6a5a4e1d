// Dense-flow wall slip, report App. C Eqs. 13–15, 19–28, 31, 48. See dense_slip.hpp.
#include "models/wall/dense_slip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "models/stress/friction_table.hpp"
#include "models/wall/wall_coefficient.hpp"
#include "models/wall/wall_law.hpp"

namespace bagnold::models::wall {

namespace chialvo_slip {

double slip_abscissa(double stress_ratio, double yield_stress_ratio, double wall_friction) {
  // f(μ_w) = μ_w + μ_w* − η_s, Eq. 13; x = (η − η_s)/f, Eq. 15.
  return (stress_ratio - yield_stress_ratio) /
         (wall_friction + critical_wall_friction - yield_stress_ratio);
}

double surface_slip(double abscissa) {
  if (!(abscissa > 0.0)) return 0.0;
  return 1.55 * std::pow(abscissa, 2.0 / 3.0) / std::pow(1.0 - abscissa, 5.25);  // Eq. 14
}

double effective_restitution(double restitution, double friction) {
  return restitution - 1.5 * friction * std::exp(-3.0 * friction);  // Eq. 27
}

double rotation_ratio(double friction) {
  const double g = 1.0 - std::exp(-6.0 * friction);  // Eq. 19
  return 1.0 / (g * g);                              // Eq. 22
}

double boundary_layer_slope(double restitution, double friction, double wall_friction,
                            double yield_stress_ratio) {
  const double e_eff = effective_restitution(restitution, friction);
  return 23.4 * (1.0 - e_eff * e_eff) *
         std::atan(6.0 * (wall_friction / yield_stress_ratio - 1.0));  // Eq. 26
}

}  // namespace chialvo_slip

double NearWallState::stress_ratio() const {
  if (!(pressure > 0.0)) return 0.0;
  return viscosity * strain_rate / pressure;
}

DenseSlip::DenseSlip(const Material& material, const DenseSlipWall& wall,
                     double yield_stress_ratio)
    : m_density(material.density),
      m_diameter(material.diameter),
      m_wall_friction(wall.wall_friction),
      m_max_abscissa(wall.max_slip_abscissa),
      m_yield_stress_ratio(yield_stress_ratio) {
  using namespace chialvo_slip;
  if (!(wall.wall_friction >= critical_wall_friction))
    throw std::invalid_argument(
        "dense-flow wall slip: wall friction mu_w = " + std::to_string(wall.wall_friction) +
        " is below the range of the report's data (mu_w >= mu_w* = 0.33, App. C Sec. III.A: "
        "below it the walls do not sustain shear); use a no-slip or Johnson-Jackson wall");
  if (!(material.friction >= min_particle_friction))
    throw std::invalid_argument(
        "dense-flow wall slip: particle friction mu = " + std::to_string(material.friction) +
        " is below 0.1; the rotational slip ratio m = 1/g(mu)^2 (App. C Eq. 22) diverges as "
        "mu -> 0");
  if (!(wall.max_slip_abscissa > 0.0 && wall.max_slip_abscissa < 1.0))
    throw std::invalid_argument("dense-flow wall slip: max_slip_abscissa must be in (0, 1)");
  if (!(yield_stress_ratio > 0.0 &&
        yield_stress_ratio < wall.wall_friction + critical_wall_friction))
    throw std::invalid_argument(
        "dense-flow wall slip: yield stress ratio eta_s must be in (0, mu_w + 0.33)");
  if (!(material.density > 0.0 && material.diameter > 0.0))
    throw std::invalid_argument("dense-flow wall slip: density and diameter must be > 0");
  m_rotation_ratio = rotation_ratio(material.friction);
  m_layer_slope = boundary_layer_slope(material.restitution, material.friction, wall.wall_friction,
                                       yield_stress_ratio);
}

double DenseSlip::scaled_apparent_slip(double stress_ratio) const {
  using namespace chialvo_slip;
  const double excess = stress_ratio - m_yield_stress_ratio;  // η − η_s
  if (!(excess > 0.0)) return 0.0;                            // no surface slip at or below yield
  const double x = std::min(slip_abscissa(stress_ratio, m_yield_stress_ratio, m_wall_friction),
                            m_max_abscissa);
  const double layer = m_layer_slope * excess;                     // I', Eq. 28
  const double apparent = surface_slip(x) + (1.0 + m_rotation_ratio) * layer;  // Eqs. 20, 24, 31
  return std::max(apparent, 0.0);
}

double DenseSlip::apparent_slip_speed(double stress_ratio, double viscosity) const {
  return viscosity / (m_density * m_diameter) * scaled_apparent_slip(stress_ratio);  // Eq. 48
}

double DenseSlip::slip_coefficient(const NearWallState& state) const {
  const double shear_stress = state.viscosity * state.strain_rate;  // τ = μ_s γ̇
  const double speed = apparent_slip_speed(state.stress_ratio(), state.viscosity);
  if (!(shear_stress > 0.0) || !(speed > 0.0)) return std::numeric_limits<double>::infinity();
  return shear_stress / speed;
}

double DenseSlip::wall_coefficient(const NearWallState& state, double wall_distance) const {
  return wall::wall_coefficient(slip_coefficient(state), state.viscosity, wall_distance);
}

namespace {
// The registered law, with η_s(μ) of App. A Table II (the bulk rheology's table, model-notes).
class DenseSlipLaw final : public WallLaw {
 public:
  explicit DenseSlipLaw(const WallLawInput& in)
      : m_slip(in.material, DenseSlipWall{.wall_friction = in.wall.wall_friction},
               chialvo2012::yield_stress_ratio(in.material.friction)) {}
  std::string name() const override { return "dense-slip"; }
  double coefficient(const NearWallSolids& near, double wall_distance) const override {
    return m_slip.wall_coefficient({.pressure = near.pressure,
                                    .viscosity = std::max(near.viscosity, 0.0),
                                    .strain_rate = near.strain_rate},
                                   wall_distance);
  }
  bool slips() const override { return true; }

 private:
  DenseSlip m_slip;
};

[[maybe_unused]] const bool registered = wall_law_registry().add(
    {.name = "dense-slip",
     .summary = "dense-flow wall slip of Chialvo et al. (report App. C): wall_friction",
     .coefficients = {},
     .make = [](const WallLawInput& in) -> std::unique_ptr<WallLaw> {
       return std::make_unique<DenseSlipLaw>(in);
     }});
}  // namespace

}  // namespace bagnold::models::wall
