// Wen–Yu with Schiller–Naumann C_D: the closed form at air/glass-bead states, the Stokes limit,
// the switch to C_D = 0.44 at Re = 1000.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/drag/wen_yu.hpp"
#include "tests/unit/models/drag/drag_probe.hpp"

namespace bagnold::tests {

namespace {
// β = ¾ C_D ε_s ε_g ρ_g |slip| / d · ε_g^−2.65, Re = ε_g ρ_g |slip| d / μ_g, written as printed
// (C_D itself, not C_D·Re, so the test does not share the law's rearrangement).
double wen_yu_closed_form(const DragProperties& p, double eps_g, double slip) {
  const double re = eps_g * p.gas_density * slip * p.particle_diameter / p.gas_viscosity;
  const double cd = re < 1000.0 ? 24.0 / re * (1.0 + 0.15 * std::pow(re, 0.687)) : 0.44;
  return 0.75 * cd * (1.0 - eps_g) * eps_g * p.gas_density * slip / p.particle_diameter *
         std::pow(eps_g, -2.65);
}
}  // namespace

TEST(WenYu, MatchesTheClosedFormForAirAndGlassBeads) {
  // Air (ρ_g = 1.2 kg/m³, μ_g = 1.8e-5 Pa s), d_p = 1 mm; Re from 3 (ε_g = 0.5, 0.1 m/s) to
  // 1800 (ε_g = 0.9, 30 m/s, Newton regime). Tolerance: rounding of a dozen operations.
  const auto law = make_law("wen-yu");
  const DragProperties p = air_and_glass_beads();
  for (const double eps_g : {0.5, 0.9})
    for (const double slip : {0.1, 1.0, 30.0}) {
      const double expected = wen_yu_closed_form(p, eps_g, slip);
      EXPECT_NEAR(beta_at(*law, p, eps_g, slip), expected, 1e-12 * expected)
          << "ε_g = " << eps_g << ", slip = " << slip;
    }
  // The same four states evaluated independently (Python, double precision), so a slip shared
  // by the law and the closed form above would still show.
  EXPECT_NEAR(beta_at(*law, p, 0.5, 0.1), 1365.602506, 1e-6);
  EXPECT_NEAR(beta_at(*law, p, 0.5, 1.0), 2713.319413, 1e-6);
  EXPECT_NEAR(beta_at(*law, p, 0.9, 0.1), 64.83843654, 1e-7);
  EXPECT_NEAR(beta_at(*law, p, 0.9, 1.0), 149.859933, 1e-6);
}

TEST(WenYu, SlipZeroGivesTheStokesLimit) {
  // At Re → 0, C_D → 24/Re: β → ¾·24 μ_g ε_s ε_g^−2.65/d² = 18 μ_g ε_s ε_g^−2.65/d². (With this
  // Re = ε_g ρ_g |slip| d/μ_g the voidage power is −2.65; it would be −1.65 only if Re left
  // out ε_g.) Slip exactly 0 must give this value, not 0/0.
  const auto law = make_law("wen-yu");
  const DragProperties p = air_and_glass_beads();
  const double d2 = p.particle_diameter * p.particle_diameter;
  for (const double eps_g : {0.3, 0.5, 0.9, 0.999}) {
    const double stokes = 18.0 * p.gas_viscosity * (1.0 - eps_g) * std::pow(eps_g, -2.65) / d2;
    const double at_zero = beta_at(*law, p, eps_g, 0.0);
    EXPECT_NEAR(at_zero, stokes, 1e-14 * stokes) << "ε_g = " << eps_g;
    // Continuous at 0: the Schiller–Naumann correction is 0.15 Re^0.687 (Re = 4e-5 at 1 μm/s).
    const double slip = 1e-6;
    const double re = eps_g * p.gas_density * slip * p.particle_diameter / p.gas_viscosity;
    EXPECT_NEAR(beta_at(*law, p, eps_g, slip) / at_zero - 1.0, 0.15 * std::pow(re, 0.687), 1e-12);
  }
}

TEST(WenYu, DiluteLimitIsStokesDragOnEachParticle) {
  // ε_s → 0 at Re → 0: β → n · 3π μ_g d_p with n = ε_s/(π d³/6) spheres per volume, i.e.
  // 18 μ_g ε_s/d²; the remaining factor ε_g^−2.65 = 1 + 2.65 ε_s + O(ε_s²).
  const auto law = make_law("wen-yu");
  const DragProperties p = air_and_glass_beads();
  const double d = p.particle_diameter;
  for (const double eps_s : {1e-3, 1e-5}) {
    const double number_density = eps_s / (std::numbers::pi * d * d * d / 6.0);
    const double stokes = number_density * 3.0 * std::numbers::pi * p.gas_viscosity * d;
    EXPECT_NEAR(beta_at(*law, p, 1.0 - eps_s, 0.0) / stokes, 1.0, 2.66 * eps_s + 1e-12);
  }
}

TEST(WenYu, SchillerNaumannSwitchesToNewtonDragAtRe1000) {
  // C_D·Re = 24(1 + 0.15 Re^0.687) = 438.29 just below 1000 and 0.44·1000 = 440 at it: the 0.4 %
  // jump of the source.
  EXPECT_NEAR(models::drag::schiller_naumann_drag_times_reynolds(1000.0 - 1e-9), 438.288140, 1e-5);
  EXPECT_DOUBLE_EQ(models::drag::schiller_naumann_drag_times_reynolds(1000.0), 440.0);
  EXPECT_DOUBLE_EQ(models::drag::schiller_naumann_drag_times_reynolds(0.0), 24.0);
}

}  // namespace bagnold::tests
