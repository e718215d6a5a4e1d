// Johnson–Jackson partial slip (Johnson & Jackson 1987): coefficient, energy flux and the
// wall temperature at which the two balance.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "models/wall/johnson_jackson.hpp"

namespace bagnold::tests {
namespace wall = models::wall;

namespace {
models::Material glass() {
  models::Material m;
  m.density = 2500.0;
  return m;
}
const wall::JohnsonJacksonWall jj{.specularity = 0.5, .wall_restitution = 0.9, .max_packing = 0.6};
}  // namespace

TEST(JohnsonJackson, CoefficientMatchesHandValue) {
  // φ = 0.3, g0 = 2, Θ = 0.04 m²/s²: (π√3/6)·0.5·2500·(0.3/0.6)·2·0.2
  //   = 0.906900 · 0.5 · 2500 · 0.5 · 2 · 0.2 = 226.725 Pa s/m (π√3/6 = 0.9068997).
  EXPECT_NEAR(wall::johnson_jackson_slip_coefficient(jj, glass(), 0.3, 2.0, 0.04), 226.725, 1e-3);
  // Free slip for a perfectly specular wall, and none without fluctuations.
  auto specular = jj;
  specular.specularity = 0.0;
  EXPECT_EQ(wall::johnson_jackson_slip_coefficient(specular, glass(), 0.3, 2.0, 0.04), 0.0);
  EXPECT_EQ(wall::johnson_jackson_slip_coefficient(jj, glass(), 0.3, 2.0, 0.0), 0.0);
}

TEST(JohnsonJackson, EnergyFluxVanishesAtTheWallTemperature) {
  // Θ_w = (2/3) φ' u²/(1 − e_w²): u = 1 m/s → (2/3)·0.5/0.19 = 1.754386 m²/s².
  const double theta = wall::johnson_jackson_wall_temperature(jj, 1.0);
  EXPECT_NEAR(theta, 1.0 / 0.57, 1e-12);
  EXPECT_NEAR(wall::johnson_jackson_energy_flux(jj, glass(), 0.3, 2.0, theta, 1.0), 0.0, 1e-9);
  // Colder than that, slip heats the flow; hotter, the wall drains it.
  EXPECT_GT(wall::johnson_jackson_energy_flux(jj, glass(), 0.3, 2.0, 0.5 * theta, 1.0), 0.0);
  EXPECT_LT(wall::johnson_jackson_energy_flux(jj, glass(), 0.3, 2.0, 2.0 * theta, 1.0), 0.0);
}

TEST(JohnsonJackson, EnergyFluxMatchesHandValue) {
  // u = 0 leaves only the loss: (√3π/4)(1 − 0.81)·2500·0.5·2·0.04^1.5
  //   = 1.360350·0.19·2500·1·0.008 = 5.16933 W/m² drained.
  EXPECT_NEAR(wall::johnson_jackson_energy_flux(jj, glass(), 0.3, 2.0, 0.04, 0.0), -5.16933,
              1e-4);
}

TEST(JohnsonJackson, RejectsPropertiesOutOfRange) {
  auto bad = jj;
  bad.specularity = 1.5;
  EXPECT_THROW(wall::johnson_jackson_slip_coefficient(bad, glass(), 0.3, 2.0, 0.04),
               std::invalid_argument);
  bad = jj;
  bad.max_packing = 0.0;
  EXPECT_THROW(wall::johnson_jackson_slip_coefficient(bad, glass(), 0.3, 2.0, 0.04),
               std::invalid_argument);
  bad = jj;
  bad.wall_restitution = 1.0;
  EXPECT_THROW(wall::johnson_jackson_wall_temperature(bad, 1.0), std::invalid_argument);
  EXPECT_THROW(wall::johnson_jackson_slip_coefficient(jj, glass(), 0.3, 2.0, -1.0),
               std::invalid_argument);
}

}  // namespace bagnold::tests
