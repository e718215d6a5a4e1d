// Gidaspow: Ergun at and below ε_g = 0.8, Wen–Yu above; Ergun's packed-bed pressure gradient;
// the jump at 0.8 and the arctan blend that removes it.
#include <gtest/gtest.h>

#include <cmath>

#include "models/drag/gidaspow.hpp"
#include "tests/unit/models/drag/drag_probe.hpp"

namespace bagnold::tests {

namespace {
// β_Ergun = 150 ε_s² μ_g/(ε_g d²) + 1.75 ε_s ρ_g |slip|/d.
double ergun_closed_form(const DragProperties& p, double eps_g, double slip) {
  const double eps_s = 1.0 - eps_g, d = p.particle_diameter;
  return 150.0 * eps_s * eps_s * p.gas_viscosity / (eps_g * d * d) +
         1.75 * eps_s * p.gas_density * slip / d;
}
}  // namespace

TEST(Gidaspow, EqualsErgunAtAndBelow08AndWenYuAbove) {
  const auto gidaspow = make_law("gidaspow");
  const auto wen_yu = make_law("wen-yu");
  const DragProperties p = air_and_glass_beads();
  for (const double slip : {0.0, 0.1, 1.0, 10.0}) {
    for (const double eps_g : {0.3, 0.4, 0.5, 0.6, 0.7, 0.8}) {
      const double expected = ergun_closed_form(p, eps_g, slip);
      EXPECT_NEAR(beta_at(*gidaspow, p, eps_g, slip), expected, 1e-13 * expected)
          << "ε_g = " << eps_g << ", slip = " << slip;
    }
    for (const double eps_g : {0.8 + 1e-9, 0.85, 0.9, 0.99, 1.0})
      EXPECT_EQ(beta_at(*gidaspow, p, eps_g, slip), beta_at(*wen_yu, p, eps_g, slip))
          << "ε_g = " << eps_g << ", slip = " << slip;
  }
  // Independent numbers (Python): Ergun 1455 and 2400 at ε_g = 0.5, 0.1 and 1 m/s.
  EXPECT_NEAR(beta_at(*gidaspow, p, 0.5, 0.1), 1455.0, 1e-9);
  EXPECT_NEAR(beta_at(*gidaspow, p, 0.5, 1.0), 2400.0, 1e-9);
}

TEST(Gidaspow, ErgunGivesTheErgunPressureGradientOfAPackedBed) {
  // Steady gas flow up through a fixed bed (u_s = 0), gas inertia and gas weight aside: the gas
  // momentum balance is 0 = −ε_g dP/dz − β (u_g − u_s), so −dP/dz = β u_g/ε_g. With the
  // interstitial speed u_g = U/ε_g (U superficial), ΔP/L = β (u_g − u_s)/ε_g = β U/ε_g², and
  // Ergun's β turns this into Ergun's equation term by term:
  //   ΔP/L = 150 μ U (1 − ε)²/(ε³ d²) + 1.75 ρ U² (1 − ε)/(ε³ d).
  const auto law = make_law("gidaspow");
  const DragProperties p = air_and_glass_beads();
  const double eps = 0.4, mu = p.gas_viscosity, rho = p.gas_density, d = p.particle_diameter;
  for (const double superficial : {0.01, 0.1, 0.5, 1.0}) {
    const double slip = superficial / eps;
    const double gradient = beta_at(*law, p, eps, slip) * slip / eps;
    const double ergun =
        150.0 * mu * superficial * (1 - eps) * (1 - eps) / (eps * eps * eps * d * d) +
        1.75 * rho * superficial * superficial * (1 - eps) / (eps * eps * eps * d);
    EXPECT_NEAR(gradient, ergun, 1e-13 * ergun) << "U = " << superficial;
  }
  // U = 0.1 m/s: 1715.625 Pa/m (Python), 1.7 kPa per metre of bed.
  EXPECT_NEAR(beta_at(*law, p, eps, 0.1 / eps) * (0.1 / eps) / eps, 1715.625, 1e-9);
}

TEST(Gidaspow, StepJumpsAt08) {
  // The source switches with a step; at 1 m/s, air and 1 mm beads: Ergun 555, Wen–Yu 386.78.
  const auto law = make_law("gidaspow");
  const DragProperties p = air_and_glass_beads();
  EXPECT_NEAR(beta_at(*law, p, 0.8, 1.0), 555.0, 1e-9);
  EXPECT_NEAR(beta_at(*law, p, 0.8 + 1e-12, 1.0), 386.78201, 1e-4);
}

TEST(Gidaspow, ArctanBlendIsContinuousAndApproachesBothLaws) {
  const auto blend = make_law("gidaspow", {{"transition", std::string("arctan-blend")}});
  const auto wen_yu = make_law("wen-yu");
  const DragProperties p = air_and_glass_beads();
  for (const double slip : {0.0, 1.0}) {
    // At 0.8 the weight is ½: the mean of the two branches.
    const double mean =
        0.5 * (ergun_closed_form(p, 0.8, slip) + beta_at(*wen_yu, p, 0.8, slip));
    EXPECT_NEAR(beta_at(*blend, p, 0.8, slip), mean, 1e-12 * mean);
    // Continuous across 0.8: a step of 2e-6 in ε_g moves β by 1e-3 relative at most
    // (the switch has slope 262.5/π ≈ 84 per unit ε_g at 0.8, times a 30 % jump).
    const double below = beta_at(*blend, p, 0.8 - 1e-6, slip);
    const double above = beta_at(*blend, p, 0.8 + 1e-6, slip);
    EXPECT_LT(std::abs(above - below), 1e-3 * mean);
    // Far from 0.8 the weight is within 0.25 % of 0 or 1 (arctan tails, see gidaspow.hpp); at
    // 0.3 and 1 m/s Wen–Yu is twice Ergun, so the blend sits 0.25 % above Ergun.
    const double dense = ergun_closed_form(p, 0.3, slip);
    EXPECT_NEAR(beta_at(*blend, p, 0.3, slip), dense, 3e-3 * dense);
    EXPECT_NEAR(models::drag::gidaspow_blend_weight(0.3), 0.0024252, 1e-7);
    EXPECT_NEAR(models::drag::gidaspow_blend_weight(0.9), 0.98788, 1e-5);
  }
}

}  // namespace bagnold::tests
