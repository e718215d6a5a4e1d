// The dilute treatment of the algebraic-temperature kinetic models (models/stress/dilute_limit.hpp):
// with the default ideal-gas treatment P_s never falls as solids are added; below the pressure
// minimum φ_d the stresses are those of φ_d scaled by φ/φ_d at φ_d's temperature; above it they
// are the printed formulas; the printed formulas themselves fall as 1/φ. The steady-shear
// rheology, whose printed P_s stays finite at φ = 0, gets the same linear branch below the point
// where the line through the origin touches P_s (the tangent anchor).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "models/stress/dilute_limit.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace {
// mfix-default with Lun et al.'s stresses: its default, Syamlal's, has no falling branch (below).
const char* const kinetic_models[] = {"skt", "mkt", "mfix-default"};
const models::Coefficients as_printed{{"dilute_stress", std::string("kinetic")}};
constexpr double rate = 10.0;

std::unique_ptr<models::SolidsStressModel> kinetic_model(const std::string& name,
                                                         models::Coefficients given = {}) {
  if (name == "mfix-default") given["kinetic_theory"] = std::string("lun");
  return make_model(name, given);
}

// φ_d of a model: where its printed P_s at fixed γ̇ is smallest.
double pressure_minimum(const models::SolidsStressModel& printed, const Material& m) {
  return models::pressure_minimum_fraction(
      [&](double phi) { return probe(printed, m, phi, 1.0).pressure_derivative; }, 1e-4, 0.5);
}
}  // namespace

TEST(PressureMinimumFraction, FindsTheSignChangeOrAnEnd) {
  EXPECT_NEAR(models::pressure_minimum_fraction([](double x) { return x - 0.3; }, 0.0, 0.5), 0.3,
              1e-9);
  EXPECT_EQ(models::pressure_minimum_fraction([](double) { return 1.0; }, 0.1, 0.5), 0.1);
  EXPECT_EQ(models::pressure_minimum_fraction([](double) { return -1.0; }, 0.1, 0.5), 0.5);
}

TEST(DiluteLimit, PrintedKineticPressureFallsAsSolidsAreAdded) {
  // The instability the treatment removes: P_s(0.01) > P_s(0.1) at the same shear rate.
  Material m;
  for (const char* name : kinetic_models) {
    const auto printed = kinetic_model(name, as_printed);
    EXPECT_GT(probe(*printed, m, 0.01, rate).pressure, 2.0 * probe(*printed, m, 0.1, rate).pressure)
        << name;
    const double minimum = pressure_minimum(*printed, m);
    EXPECT_GT(minimum, 0.1) << name;
    EXPECT_LT(minimum, 0.25) << name;
  }
}

TEST(DiluteLimit, SyamlalsPrintedPressureRisesFromZeroSoTheLimitNeverActs) {
  // MFIX's algebraic theory: P_s = K_1 φ² T with T ~ 1/φ as φ → 0, so P_s ∝ φ and φ_d is the
  // search's lower end; the ideal-gas treatment then equals the printed formulas.
  Material m;
  const auto printed = make_model("mfix-default", as_printed);
  const auto limited = make_model("mfix-default");
  EXPECT_LT(pressure_minimum(*printed, m), 1.001e-4);
  for (const double phi : {1e-3, 0.01, 0.1, 0.3}) {
    EXPECT_GT(probe(*printed, m, 2 * phi, rate).pressure, probe(*printed, m, phi, rate).pressure);
    EXPECT_DOUBLE_EQ(probe(*limited, m, phi, rate).pressure, probe(*printed, m, phi, rate).pressure);
  }
}

TEST(DiluteLimit, IdealGasPressureNeverFallsWithSolidsFraction) {
  for (const char* name : kinetic_models) {
    const auto model = kinetic_model(name);
    for (const double friction : {0.0, 0.5}) {
      Material m;
      m.friction = friction;
      double previous = 0.0;
      for (double phi = 1e-5; phi < 0.55; phi += 1e-3) {
        const auto s = probe(*model, m, phi, rate);
        EXPECT_GE(s.pressure, previous * (1.0 - 1e-12)) << name << " φ = " << phi;
        EXPECT_GE(s.pressure_derivative, 0.0) << name << " φ = " << phi;
        previous = s.pressure;
      }
    }
  }
}

TEST(DiluteLimit, BelowTheMinimumStressesScaleWithFractionAtTheMinimumsTemperature) {
  Material m;
  for (const char* name : kinetic_models) {
    const auto model = kinetic_model(name);
    const auto printed = kinetic_model(name, as_printed);
    const double minimum = pressure_minimum(*printed, m);
    const auto at = probe(*printed, m, minimum, rate);
    for (const double phi : {1e-4, 0.01, 0.5 * minimum, 0.999 * minimum}) {
      const auto s = probe(*model, m, phi, rate);
      const double scale = phi / minimum;
      EXPECT_NEAR(s.pressure, at.pressure * scale, 1e-9 * at.pressure) << name;
      EXPECT_NEAR(s.pressure_derivative, at.pressure / minimum, 1e-9 * at.pressure / minimum);
      EXPECT_NEAR(s.shear_viscosity, at.shear_viscosity * scale, 1e-9 * at.shear_viscosity);
      EXPECT_NEAR(s.bulk_viscosity, at.bulk_viscosity * scale, 1e-9 * at.bulk_viscosity + 1e-300);
      EXPECT_NEAR(s.granular_temperature, at.granular_temperature, 1e-9 * at.granular_temperature);
    }
    // Above the minimum the printed formulas are untouched.
    for (const double phi : {1.001 * minimum, 0.3, 0.5}) {
      EXPECT_EQ(probe(*model, m, phi, rate).pressure, probe(*printed, m, phi, rate).pressure);
      EXPECT_EQ(probe(*model, m, phi, rate).shear_viscosity,
                probe(*printed, m, phi, rate).shear_viscosity);
    }
  }
}

TEST(DiluteLimit, BelowTheCutoffThereIsNoStress) {
  Material m;
  for (const char* name : kinetic_models) {
    const auto s = probe(*make_model(name, {{"dilute_cutoff", 1e-3}}), m, 5e-4, rate);
    EXPECT_EQ(s.pressure, 0.0) << name;
    EXPECT_EQ(s.shear_viscosity, 0.0) << name;
    EXPECT_EQ(s.granular_temperature, 0.0) << name;
  }
}

TEST(DiluteLimit, SteadyShearPressureVanishesInAnEmptyCellAlongTheTangentThroughTheOrigin) {
  Material m;
  m.stiffness = 1e5;
  const auto model = make_model("steady-shear");
  const auto printed = make_model("steady-shear", {{"dilute_stress", std::string("printed")}});
  // As printed, App. A's inertial branch leaves P_s(φ → 0) finite.
  const double empty = probe(*printed, m, 1e-5, rate).pressure;
  EXPECT_GT(empty, 0.5 * probe(*printed, m, 0.1, rate).pressure);
  // The tangent point: where P_s/φ of the printed rheology is smallest.
  const double tangent = models::pressure_minimum_fraction(
      [&](double phi) {
        const auto s = probe(*printed, m, phi, 1.0);
        return s.pressure_derivative * phi - s.pressure;
      },
      1e-4, 0.5);
  EXPECT_GT(tangent, 0.1);
  EXPECT_LT(tangent, 0.3);
  const auto at = probe(*printed, m, tangent, rate);
  // Below it P_s = P_s(φ_d) φ/φ_d; its slope P_s(φ_d)/φ_d is the printed slope at φ_d (tangent),
  // so dP_s/dε_s is continuous.
  EXPECT_NEAR(at.pressure_derivative, at.pressure / tangent, 1e-6 * at.pressure_derivative);
  for (const double phi : {1e-4, 0.01, 0.5 * tangent, 0.999 * tangent}) {
    const auto s = probe(*model, m, phi, rate);
    EXPECT_NEAR(s.pressure, at.pressure * phi / tangent, 1e-9 * at.pressure);
    EXPECT_NEAR(s.shear_viscosity, at.shear_viscosity * phi / tangent, 1e-9 * at.shear_viscosity);
    EXPECT_LT(s.pressure, probe(*printed, m, phi, rate).pressure);
  }
  for (const double phi : {1.001 * tangent, 0.4, 0.58})
    EXPECT_EQ(probe(*model, m, phi, rate).pressure, probe(*printed, m, phi, rate).pressure);
}

}  // namespace bagnold::tests
