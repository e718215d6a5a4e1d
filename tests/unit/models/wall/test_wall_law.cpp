// The wall-law registry (models/wall/wall_law.hpp): it lists exactly the shipped laws, each
// law gives the coefficient SolidsWalls::coefficient (solver/simple/solids_wall.cpp at dc6e78f)
// gave, bit for bit, over a grid of near-wall states, and each keeps its limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/friction_table.hpp"
#include "models/stress/solids_stress.hpp"
#include "models/wall/dense_slip.hpp"
#include "models/wall/johnson_jackson.hpp"
#include "models/wall/wall_coefficient.hpp"
#include "models/wall/wall_law.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace wall = models::wall;
using wall::NearWallSolids;

namespace {
models::Material beads() {
  models::Material m;
  m.diameter = 1e-3;
  m.density = 2500.0;
  m.friction = 0.5;
  m.restitution = 0.8;
  return m;
}

// The near-wall states of the grid: dilute to past the packing limit, with and without Θ,
// at rest and sliding, with a zero and a negative (undershooting) iterate.
std::vector<NearWallSolids> near_wall_states() {
  std::vector<NearWallSolids> out;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double phi : {-0.01, 0.0, 0.05, 0.3, 0.55, 0.58, 0.6, 0.65})
    for (const double viscosity : {-1.0, 0.0, 0.3, 40.0})
      for (const double pressure : {0.0, 150.0, 4e3})
        for (const double strain_rate : {0.0, 2.0, 300.0})
          for (const double temperature : {nan, -1e-4, 0.0, 0.02})
            for (const double slip : {0.0, 0.4, 3.0})
              out.push_back({phi, pressure, viscosity, strain_rate, temperature, slip});
  return out;
}
const std::vector<double> wall_distances{1.25e-3, 5e-3};

wall::WallLawInput input_for(const models::SolidsStressModel& model,
                             const wall::WallParameters& parameters) {
  return {
      .material = beads(), .wall = parameters, .closure = wall::closure_at_wall(model, beads())};
}
}  // namespace

TEST(WallLawRegistry, ListsExactlyTheShippedLaws) {
  const std::vector<std::string> shipped{"dense-slip", "free-slip", "johnson-jackson", "no-slip"};
  EXPECT_EQ(wall::wall_law_registry().names(), shipped);
  const auto closure = models::stress_registry().create("mkt");
  const auto in =
      input_for(*closure, {.specularity = 0.5, .wall_restitution = 0.9, .wall_friction = 0.5});
  for (const auto& name : shipped) {
    const auto law = wall::wall_law_registry().create(name, in);
    EXPECT_EQ(law->name(), name);
    EXPECT_EQ(law->slips(), name != "no-slip") << name;
  }
}

TEST(WallLawRegistry, UnknownNameListsAlternatives) {
  try {
    wall::wall_law_registry().create("johnson_jackson", {});
    FAIL() << "expected UnknownModel";
  } catch (const models::UnknownModel& e) {
    const std::string message = e.what();
    for (const auto& name : wall::wall_law_registry().names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(WallLaw, ClosureAtWallIsWhatTheClosureReports) {
  for (const auto& name : models::stress_registry().names()) {
    const auto model = make_model(name);
    const auto closure = wall::closure_at_wall(*model, beads());
    EXPECT_EQ(closure.defines_temperature, model->defines_temperature()) << name;
    EXPECT_EQ(closure.packing_limit, model->packing_limit(beads())) << name;
    for (const double phi : {0.0, 0.4, 0.59, 0.7})
      EXPECT_EQ(closure.radial_distribution(phi), model->wall_radial_distribution(beads(), phi))
          << name;
  }
}

TEST(WallLaw, NoSlipIsTheBulkCoefficient) {
  const auto law = wall::wall_law_registry().create("no-slip", {});
  for (const auto& near : near_wall_states())
    for (const double delta : wall_distances)
      EXPECT_EQ(law->coefficient(near, delta), std::max(near.viscosity, 0.0) / delta);
  // μ_s = 0.3 Pa s, δ = 5 mm: 60 Pa s/m.
  EXPECT_DOUBLE_EQ(law->coefficient({.fraction = 0.5, .viscosity = 0.3}, 5e-3), 60.0);
}

TEST(WallLaw, FreeSlipHasNoWallStress) {
  const auto law = wall::wall_law_registry().create("free-slip", {});
  for (const auto& near : near_wall_states())
    for (const double delta : wall_distances) EXPECT_EQ(law->coefficient(near, delta), 0.0);
}

TEST(WallLaw, JohnsonJacksonIsTheSolversFormula) {
  const wall::WallParameters parameters{.specularity = 0.5, .wall_restitution = 0.9};
  // A closure with Θ (mkt, φ_max = φ_c) and one without (plastic, φ_max = 1 − ε_g*).
  for (const std::string closure_name : {"mkt", "plastic", "steady-shear"}) {
    const auto closure = models::stress_registry().create(closure_name);
    const auto law =
        wall::wall_law_registry().create("johnson-jackson", input_for(*closure, parameters));
    const bool has_temperature = closure->defines_temperature();
    const double limit = closure->packing_limit(beads());
    const wall::JohnsonJacksonWall jj{0.5, 0.9, limit};
    for (const auto& near : near_wall_states()) {
      for (const double delta : wall_distances) {
        // SolidsWalls::coefficient, case johnson_jackson, with capped_carnahan_starling.
        const double mu = std::max(near.viscosity, 0.0);
        const double phi = std::max(near.fraction, 0.0);
        const double g0 =
            models::rdf::carnahan_starling(std::clamp(phi, 0.0, std::max(limit - 0.01, 0.0)));
        const double theta = has_temperature && std::isfinite(near.temperature)
                                 ? std::max(near.temperature, 0.0)
                                 : wall::johnson_jackson_wall_temperature(jj, near.slip_speed);
        const double c_slip =
            wall::johnson_jackson_slip_coefficient(jj, beads(), std::min(phi, limit), g0, theta);
        EXPECT_EQ(law->coefficient(near, delta), wall::wall_coefficient(c_slip, mu, delta))
            << closure_name << " φ = " << near.fraction << " Θ = " << near.temperature;
      }
    }
  }
  // Hand value (mkt, Θ given): φ = 0.3, Θ = 0.04, μ_s = 1 Pa s, δ = 5 mm, φ_max = 0.587:
  // c_JJ = (π√3/6)·0.5·2500·(0.3/0.587)·g0_CS(0.3)·0.2, g0_CS(0.3) = 0.85/0.343;
  // c_w = 1/(δ/μ_s + 1/c_JJ).
  const auto mkt = models::stress_registry().create("mkt");
  const auto law = wall::wall_law_registry().create("johnson-jackson", input_for(*mkt, parameters));
  const double c_jj = 0.9068996821 * 0.5 * 2500.0 * (0.3 / 0.587) * (0.85 / 0.343) * 0.2;
  EXPECT_NEAR(law->coefficient({.fraction = 0.3, .viscosity = 1.0, .temperature = 0.04}, 5e-3),
              1.0 / (5e-3 + 1.0 / c_jj), 1e-8 * c_jj);
}

TEST(WallLaw, DenseSlipIsTheSolversFormula) {
  const auto closure = models::stress_registry().create("steady-shear");
  const auto law =
      wall::wall_law_registry().create("dense-slip", input_for(*closure, {.wall_friction = 0.5}));
  const wall::DenseSlip reference(beads(), {.wall_friction = 0.5},
                                  models::chialvo2012::yield_stress_ratio(0.5));
  int slipping = 0;
  for (const auto& near : near_wall_states()) {
    for (const double delta : wall_distances) {
      const double mu = std::max(near.viscosity, 0.0);
      const double expected = reference.wall_coefficient(
          {.pressure = near.pressure, .viscosity = mu, .strain_rate = near.strain_rate}, delta);
      EXPECT_EQ(law->coefficient(near, delta), expected);
      if (expected < mu / delta) ++slipping;
    }
  }
  EXPECT_GT(slipping, 0);  // the grid reaches η > η_s, where the wall slips
}

TEST(WallLaw, LawsKeepTheirLimits) {
  const auto mkt = models::stress_registry().create("mkt");
  auto& registry = wall::wall_law_registry();
  // Johnson–Jackson: φ', e_w in [0, 1], φ_max in (0, 1] (require_valid).
  EXPECT_THROW(registry.create("johnson-jackson", input_for(*mkt, {.specularity = 1.5})),
               std::invalid_argument);
  EXPECT_THROW(registry.create("johnson-jackson", input_for(*mkt, {.wall_restitution = -0.1})),
               std::invalid_argument);
  auto no_packing = input_for(*mkt, {.specularity = 0.5});
  no_packing.closure.packing_limit = 0.0;
  EXPECT_THROW(registry.create("johnson-jackson", no_packing), std::invalid_argument);
  auto no_g0 = input_for(*mkt, {.specularity = 0.5});
  no_g0.closure.radial_distribution = nullptr;
  EXPECT_THROW(registry.create("johnson-jackson", no_g0), std::invalid_argument);
  // Without Θ from the closure the wall temperature needs e_w < 1.
  const auto plastic = models::stress_registry().create("plastic");
  const auto elastic = registry.create(
      "johnson-jackson", input_for(*plastic, {.specularity = 0.5, .wall_restitution = 1.0}));
  EXPECT_THROW(elastic->coefficient({.fraction = 0.5, .viscosity = 1.0, .slip_speed = 1.0}, 1e-3),
               std::invalid_argument);
  // Dense slip: μ_w ≥ 0.33 (App. C Sec. III.A), μ ≥ 0.1.
  EXPECT_THROW(registry.create("dense-slip", input_for(*mkt, {.wall_friction = 0.3})),
               std::invalid_argument);
  auto smooth = input_for(*mkt, {.wall_friction = 0.5});
  smooth.material.friction = 0.05;
  EXPECT_THROW(registry.create("dense-slip", smooth), std::invalid_argument);
}

}  // namespace bagnold::tests
