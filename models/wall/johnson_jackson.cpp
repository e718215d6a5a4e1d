// Johnson–Jackson partial slip (Johnson & Jackson 1987). See johnson_jackson.hpp.
#include "models/wall/johnson_jackson.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "models/wall/wall_coefficient.hpp"
#include "models/wall/wall_law.hpp"

namespace bagnold::models::wall {

void require_valid(const JohnsonJacksonWall& wall) {
  if (!(wall.specularity >= 0.0 && wall.specularity <= 1.0))
    throw std::invalid_argument("Johnson-Jackson wall: specularity coefficient must be in [0, 1]");
  if (!(wall.wall_restitution >= 0.0 && wall.wall_restitution <= 1.0))
    throw std::invalid_argument("Johnson-Jackson wall: wall restitution must be in [0, 1]");
  if (!(wall.max_packing > 0.0 && wall.max_packing <= 1.0))
    throw std::invalid_argument("Johnson-Jackson wall: maximum packing must be in (0, 1]");
}

namespace {
// ρ_s (φ/φ_max) g0: the collision-frequency factor both terms share.
double collision_factor(const JohnsonJacksonWall& wall, const Material& material,
                        double solids_fraction, double radial_distribution) {
  require_valid(wall);
  if (!(solids_fraction >= 0.0) || !(radial_distribution >= 0.0))
    throw std::invalid_argument("Johnson-Jackson wall: φ and g0 must be >= 0");
  return material.density * solids_fraction / wall.max_packing * radial_distribution;
}
}  // namespace

double johnson_jackson_slip_coefficient(const JohnsonJacksonWall& wall, const Material& material,
                                        double solids_fraction, double radial_distribution,
                                        double granular_temperature) {
  const double factor = collision_factor(wall, material, solids_fraction, radial_distribution);
  if (!(granular_temperature >= 0.0))
    throw std::invalid_argument("Johnson-Jackson wall: granular temperature must be >= 0");
  return std::numbers::pi * std::sqrt(3.0) / 6.0 * wall.specularity * factor *
         std::sqrt(granular_temperature);
}

double johnson_jackson_energy_flux(const JohnsonJacksonWall& wall, const Material& material,
                                   double solids_fraction, double radial_distribution,
                                   double granular_temperature, double slip_speed) {
  const double generation =
      johnson_jackson_slip_coefficient(wall, material, solids_fraction, radial_distribution,
                                       granular_temperature) *
      slip_speed * slip_speed;
  const double loss = std::sqrt(3.0) * std::numbers::pi / 4.0 *
                      (1.0 - wall.wall_restitution * wall.wall_restitution) *
                      collision_factor(wall, material, solids_fraction, radial_distribution) *
                      std::pow(granular_temperature, 1.5);
  return generation - loss;
}

double johnson_jackson_wall_temperature(const JohnsonJacksonWall& wall, double slip_speed) {
  require_valid(wall);
  if (!(wall.wall_restitution < 1.0))
    throw std::invalid_argument(
        "Johnson-Jackson wall temperature: needs wall restitution < 1 (an elastic wall never "
        "drains the energy slip generates)");
  return 2.0 / 3.0 * wall.specularity * slip_speed * slip_speed /
         (1.0 - wall.wall_restitution * wall.wall_restitution);
}

namespace {
// The registered law: c_w of c_JJ in series with the half cell (wall_coefficient.hpp). g0 is the
// closure's wall g0 at φ (SolidsStressModel::wall_radial_distribution), the collision factor
// takes min(φ, φ_max), and Θ is the cell's where the closure defines one.
class JohnsonJacksonLaw final : public WallLaw {
 public:
  explicit JohnsonJacksonLaw(const WallLawInput& in)
      : m_wall{in.wall.specularity, in.wall.wall_restitution, in.closure.packing_limit},
        m_material(in.material),
        m_defines_temperature(in.closure.defines_temperature),
        m_radial_distribution(in.closure.radial_distribution) {
    require_valid(m_wall);
    if (!m_radial_distribution)
      throw std::invalid_argument("Johnson-Jackson wall: needs the closure's g0");
  }
  std::string name() const override { return "johnson-jackson"; }
  double coefficient(const NearWallSolids& near, double wall_distance) const override {
    const double viscosity = std::max(near.viscosity, 0.0);
    const double phi = std::max(near.fraction, 0.0);
    const double g0 = m_radial_distribution(phi);
    const double theta = m_defines_temperature && std::isfinite(near.temperature)
                             ? std::max(near.temperature, 0.0)
                             : johnson_jackson_wall_temperature(m_wall, near.slip_speed);
    const double slip = johnson_jackson_slip_coefficient(
        m_wall, m_material, std::min(phi, m_wall.max_packing), g0, theta);
    return wall_coefficient(slip, viscosity, wall_distance);
  }
  bool slips() const override { return true; }

 private:
  JohnsonJacksonWall m_wall;
  Material m_material;
  bool m_defines_temperature;
  std::function<double(double)> m_radial_distribution;
};

[[maybe_unused]] const bool registered = wall_law_registry().add(
    {.name = "johnson-jackson",
     .summary = "Johnson-Jackson partial slip (Johnson & Jackson 1987): specularity, "
                "wall_restitution",
     .coefficients = {},
     .make = [](const WallLawInput& in) -> std::unique_ptr<WallLaw> {
       return std::make_unique<JohnsonJacksonLaw>(in);
     }});
}  // namespace

}  // namespace bagnold::models::wall
