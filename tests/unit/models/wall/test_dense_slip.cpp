// Dense-flow wall slip (report App. C Eqs. 13–15, 19–28, 31, 48): values against the printed
// formulas, the limits (η ≤ η_s, x → 1, μ_w and μ below the data), sign and continuity.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "models/wall/dense_slip.hpp"

namespace bagnold::tests {
namespace wall = models::wall;
namespace slip = models::wall::chialvo_slip;

namespace {
models::Material beads(double friction, double restitution) {
  models::Material m;
  m.diameter = 1e-3;
  m.density = 2500.0;
  m.friction = friction;
  m.restitution = restitution;
  return m;
}

// Reference values: the printed equations evaluated term by term, independently of this code,
// with Python's math module (x = (η−η_s)/(μ_w+0.33−η_s); I_surf = 1.55 x^(2/3)/(1−x)^5.25;
// e_eff = e − 1.5 μ e^(−3μ); m' = 23.4 (1−e_eff²) atan(6(μ_w/η_s − 1)); m = (1 − e^(−6μ))^(−2);
// F = I_surf + (1+m) m'(η−η_s)), printed to 10 significant digits.
struct Reference {
  double friction, restitution, wall_friction, yield_ratio, stress_ratio;
  double abscissa, surface, effective_restitution, layer_slope, rotation, apparent;
};
// η_s: App. A Table II at μ = 0.5, 0.3, 1 (0.382, 0.357, 0.405).
const Reference cases[] = {
    {0.5, 0.8, 0.5, 0.382, 0.45, 0.1517857143, 1.046721927, 0.6326523799, 15.10095309,
     1.107536702, 3.210877202},
    {0.3, 0.7, 0.8, 0.357, 0.5, 0.1849935317, 1.472902001, 0.5170436531, 24.6413417,
     1.43528457, 10.05414313},
    // μ_w < η_s: m' < 0 as printed (Eq. 26), F still positive.
    {1.0, 0.9, 0.35, 0.405, 0.45, 0.1636363636, 1.184887401, 0.8253193974, -5.101182986,
     1.004975998, 0.7246386759},
};
constexpr double digits = 1e-9;  // relative: the references carry 10 significant digits
}  // namespace

TEST(DenseSlip, TermsMatchAppendixCFormulas) {
  for (const Reference& r : cases) {
    SCOPED_TRACE("mu = " + std::to_string(r.friction));
    EXPECT_NEAR(slip::slip_abscissa(r.stress_ratio, r.yield_ratio, r.wall_friction), r.abscissa,
                digits * r.abscissa);
    EXPECT_NEAR(slip::surface_slip(r.abscissa), r.surface, digits * r.surface);
    EXPECT_NEAR(slip::effective_restitution(r.restitution, r.friction), r.effective_restitution,
                digits);
    EXPECT_NEAR(slip::boundary_layer_slope(r.restitution, r.friction, r.wall_friction,
                                           r.yield_ratio),
                r.layer_slope, digits * std::abs(r.layer_slope));
    EXPECT_NEAR(slip::rotation_ratio(r.friction), r.rotation, digits * r.rotation);
    const wall::DenseSlip model(beads(r.friction, r.restitution), {.wall_friction = r.wall_friction},
                                r.yield_ratio);
    EXPECT_NEAR(model.scaled_apparent_slip(r.stress_ratio), r.apparent, digits * r.apparent);
  }
}

TEST(DenseSlip, Eq14MatchesHandValueAtOneHalf) {
  // x = 1/2: 1.55 · 0.5^(2/3) / 0.5^5.25 = 1.55 · 2^(5.25 − 2/3) = 1.55 · 2^(55/12)
  //        = 1.55 · 16 · 2^(7/12) = 1.55 · 16 · 1.498307 = 37.158.
  EXPECT_NEAR(slip::surface_slip(0.5), 37.158, 1e-3);
}

TEST(DenseSlip, SlipVelocityIsViscosityScaleTimesF) {
  // Eq. 48: v = ν/(ρ_s d) F. ν = 2 Pa s, ρ_s d = 2.5 kg/m² → 0.8 m/s per unit of F.
  const Reference& r = cases[0];
  const wall::DenseSlip model(beads(r.friction, r.restitution), {.wall_friction = r.wall_friction},
                              r.yield_ratio);
  EXPECT_NEAR(model.apparent_slip_speed(r.stress_ratio, 2.0), 0.8 * r.apparent, 1e-9);
}

TEST(DenseSlip, NoSlipAtAndBelowYield) {
  // η ≤ η_s: no surface slip (x ≤ 0), F = 0, an infinite slip coefficient, c_w = μ_s/δ.
  const wall::DenseSlip model(beads(0.5, 0.8), {.wall_friction = 0.5}, 0.382);
  for (const double eta : {0.0, 0.2, 0.382}) {
    EXPECT_EQ(model.scaled_apparent_slip(eta), 0.0);
    EXPECT_EQ(model.apparent_slip_speed(eta, 3.0), 0.0);
  }
  // η = μ_s γ̇/p = 10 · 1/30 = 0.333 < η_s.
  const wall::NearWallState state{.pressure = 30.0, .viscosity = 10.0, .strain_rate = 1.0};
  EXPECT_TRUE(std::isinf(model.slip_coefficient(state)));
  EXPECT_DOUBLE_EQ(model.wall_coefficient(state, 0.005), 10.0 / 0.005);
  // No stress at all (γ̇ = 0, or p = 0): no slip either.
  EXPECT_TRUE(std::isinf(model.slip_coefficient({.pressure = 30.0, .viscosity = 10.0, .strain_rate = 0.0})));
  EXPECT_TRUE(std::isinf(model.slip_coefficient({.pressure = 0.0, .viscosity = 10.0, .strain_rate = 1.0})));
}

TEST(DenseSlip, ContinuousAtYield) {
  // F → 0 as η → η_s⁺ (x^(2/3) and the linear terms vanish), so c_w → μ_s/δ: no jump at yield.
  const wall::DenseSlip model(beads(0.5, 0.8), {.wall_friction = 0.5}, 0.382);
  EXPECT_LT(model.scaled_apparent_slip(0.382 + 1e-9), 1e-4);
  const double viscosity = 10.0, delta = 0.005;
  const double no_slip = viscosity / delta;
  const double pressure = 100.0;
  // γ̇ so that η = μ_s γ̇/p = η_s + 1e-9.
  const wall::NearWallState near{.pressure = pressure, .viscosity = viscosity,
                                 .strain_rate = (0.382 + 1e-9) * pressure / viscosity};
  EXPECT_NEAR(model.wall_coefficient(near, delta), no_slip, 1e-3 * no_slip);
  EXPECT_LT(model.wall_coefficient(near, delta), no_slip);
}

TEST(DenseSlip, SlipGrowsWithStressRatioAndSurfaceSlipFallsWithWallFriction) {
  // Monotone in η over the data range (Fig. 7). Rougher walls give less *surface* slip (Fig. 5,
  // Eq. 14 through f(μ_w)), but a larger boundary-layer term (m' grows with μ_w, Eq. 26), so the
  // *apparent* slip F grows with μ_w here: 2.188 at μ_w = 0.4 against 3.348 at μ_w = 1.0
  // (η = 0.45, μ = 0.5, e = 0.8; Python as cases[]). That is the printed model, not a bug.
  const models::Material m = beads(0.5, 0.8);
  const wall::DenseSlip smooth(m, {.wall_friction = 0.4}, 0.382);
  const wall::DenseSlip rough(m, {.wall_friction = 1.0}, 0.382);
  double previous = 0.0;
  for (double eta = 0.39; eta < 0.7; eta += 0.01) {
    const double f = smooth.scaled_apparent_slip(eta);
    EXPECT_GT(f, previous) << "eta = " << eta;
    previous = f;
  }
  EXPECT_GT(slip::surface_slip(slip::slip_abscissa(0.45, 0.382, 0.4)),
            slip::surface_slip(slip::slip_abscissa(0.45, 0.382, 1.0)));
  EXPECT_NEAR(smooth.scaled_apparent_slip(0.45), 2.188, 1e-3);
  EXPECT_NEAR(rough.scaled_apparent_slip(0.45), 3.348, 1e-3);
}

TEST(DenseSlip, AbscissaIsCappedNearOne) {
  // μ_w = 0.5, η_s = 0.382: f = 0.448, x = 1 at η = 0.83. With the cap x_max = 0.9 Eq. 14 is
  // frozen at I_surf(0.9) = 1.55 · 0.9^(2/3) / 0.1^5.25 ≈ 2.57e5, F stays finite and positive
  // past x = 1 and the coefficient stays > 0 (nearly free slip, not NaN).
  const wall::DenseSlip model(beads(0.5, 0.8), {.wall_friction = 0.5}, 0.382);
  const double layer = 15.10095309 * (1.0 + 1.107536702);  // (1 + m) m', cases[0]
  for (const double eta : {0.8352, 1.5}) {
    const double f = model.scaled_apparent_slip(eta);
    EXPECT_TRUE(std::isfinite(f));
    EXPECT_NEAR(f, slip::surface_slip(0.9) + layer * (eta - 0.382), 1e-6 * f);
  }
  EXPECT_NEAR(slip::surface_slip(0.9), 256937.0328, 1e-3);  // Python, as cases[]
  const wall::NearWallState fast{.pressure = 10.0, .viscosity = 1.0, .strain_rate = 15.0};
  EXPECT_GT(model.slip_coefficient(fast), 0.0);
  EXPECT_TRUE(std::isfinite(model.slip_coefficient(fast)));
}

TEST(DenseSlip, CoefficientReproducesEq48AndOpposesTheFlow) {
  // τ_w = −c_slip v: with the first cell's τ = μ_s γ̇ as the wall stress, the slip speed the
  // coefficient implies is exactly Eq. 48's ν F(η)/(ρ_s d); c_slip > 0, so the wall stress
  // points against the tangential velocity whatever its sign (the law is isotropic in the
  // tangential plane).
  const Reference& r = cases[0];
  const wall::DenseSlip model(beads(r.friction, r.restitution), {.wall_friction = r.wall_friction},
                              r.yield_ratio);
  const wall::NearWallState state{.pressure = 200.0, .viscosity = 4.0,
                                  .strain_rate = r.stress_ratio * 200.0 / 4.0};
  EXPECT_NEAR(state.stress_ratio(), r.stress_ratio, 1e-15);
  const double c = model.slip_coefficient(state);
  ASSERT_GT(c, 0.0);
  const double tau = 4.0 * state.strain_rate;
  EXPECT_NEAR(tau / c, 4.0 / 2.5 * r.apparent, 1e-9);
  for (const double u : {-0.3, 0.3}) EXPECT_LT(-c * u * u, 0.0);  // wall power −c u² < 0
  // Series with the half cell: 1/c_w = δ/μ_s + 1/c_slip.
  const double delta = 0.0025;
  EXPECT_NEAR(model.wall_coefficient(state, delta), 1.0 / (delta / 4.0 + 1.0 / c), 1e-9);
}

TEST(DenseSlip, RefusesWallFrictionBelowTheData) {
  const models::Material m = beads(0.5, 0.8);
  for (const double mu_w : {0.0, 0.2, 0.329}) {
    try {
      const wall::DenseSlip model(m, {.wall_friction = mu_w}, 0.382);
      FAIL() << "accepted mu_w = " << mu_w;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("0.33"), std::string::npos) << error.what();
    }
  }
  EXPECT_NO_THROW(wall::DenseSlip(m, {.wall_friction = 0.33}, 0.382));
  EXPECT_THROW(wall::DenseSlip(m, {.wall_friction = std::nan("")}, 0.382), std::invalid_argument);
}

TEST(DenseSlip, RefusesNearlyFrictionlessParticlesAndBadCaps) {
  EXPECT_THROW(wall::DenseSlip(beads(0.0, 0.8), {.wall_friction = 0.5}, 0.105),
               std::invalid_argument);
  EXPECT_THROW(wall::DenseSlip(beads(0.05, 0.8), {.wall_friction = 0.5}, 0.2),
               std::invalid_argument);
  EXPECT_THROW(wall::DenseSlip(beads(0.5, 0.8), {.wall_friction = 0.5, .max_slip_abscissa = 1.0},
                               0.382),
               std::invalid_argument);
  EXPECT_THROW(wall::DenseSlip(beads(0.5, 0.8), {.wall_friction = 0.5}, 0.0),
               std::invalid_argument);
}

}  // namespace bagnold::tests
