// Syamlal–O'Brien: the closed form at air/glass-bead states, the limits of the terminal velocity
// ratio V_r and the Garside–Al-Dibouni relation it solves, the single-particle limit, c1 and d1.
#include <gtest/gtest.h>

#include <cmath>

#include "models/drag/syamlal_obrien.hpp"
#include "tests/unit/models/drag/drag_probe.hpp"

namespace bagnold::tests {

using models::drag::GarsideAlDibouni;
using models::drag::terminal_velocity_ratio;

namespace {
double a_of(double eps_g) { return std::pow(eps_g, 4.14); }
double b_of(double eps_g, double c1 = 0.8, double d1 = 2.65) {
  return eps_g <= 0.85 ? c1 * std::pow(eps_g, 1.28) : std::pow(eps_g, d1);
}

// As printed: Re = ρ_g |slip| d/μ_g, V_r = ½(A − 0.06Re + sqrt(0.0036Re² + 0.12Re(2B − A) + A²)),
// C_D = (0.63 + 4.8 sqrt(V_r/Re))², β = ¾ ε_s ε_g ρ_g |slip| C_D/(V_r² d). Needs slip > 0.
double syamlal_obrien_closed_form(const DragProperties& p, double eps_g, double slip) {
  const double re = p.gas_density * slip * p.particle_diameter / p.gas_viscosity;
  const double a = a_of(eps_g), b = b_of(eps_g);
  const double vr = 0.5 * (a - 0.06 * re + std::sqrt(0.0036 * re * re + 0.12 * re * (2 * b - a) + a * a));
  const double root = 0.63 + 4.8 * std::sqrt(vr / re);
  return 0.75 * (1.0 - eps_g) * eps_g * p.gas_density * slip * root * root /
         (vr * vr * p.particle_diameter);
}
}  // namespace

TEST(SyamlalObrien, MatchesTheClosedFormForAirAndGlassBeads) {
  // Re = 6.7 (0.1 m/s) and 67 (1 m/s); at the larger Re the printed V_r loses ~2 digits to
  // cancellation (A − 0.06Re + √… with 0.06Re = 4 ≫ V_r = 0.31), hence 1e-11.
  const auto law = make_law("syamlal-obrien");
  const DragProperties p = air_and_glass_beads();
  for (const double eps_g : {0.4, 0.5, 0.9})
    for (const double slip : {0.1, 1.0}) {
      const double expected = syamlal_obrien_closed_form(p, eps_g, slip);
      EXPECT_NEAR(beta_at(*law, p, eps_g, slip), expected, 1e-11 * expected)
          << "ε_g = " << eps_g << ", slip = " << slip;
    }
  // Independent numbers (Python, double precision).
  EXPECT_NEAR(beta_at(*law, p, 0.5, 0.1), 985.305182, 1e-6);
  EXPECT_NEAR(beta_at(*law, p, 0.5, 1.0), 2147.646453, 1e-6);
  EXPECT_NEAR(beta_at(*law, p, 0.9, 0.1), 80.88944644, 1e-7);
  EXPECT_NEAR(beta_at(*law, p, 0.9, 1.0), 191.0945634, 1e-6);
  EXPECT_NEAR(terminal_velocity_ratio(0.5, 66.666666666666667, {}), 0.309830995, 1e-9);
}

TEST(SyamlalObrien, VelocityRatioRunsFromAAtRe0ToBAtLargeRe) {
  // Re → 0: V_r = ½(A + |A|) = A; Re → ∞: √… = 0.06Re + (2B − A) + O(1/Re), so V_r → B.
  // From V_r (V_r − A) = 0.06 Re (B − V_r): near 0, V_r ≈ A + 0.06 Re (B − A)/A; at large Re,
  // B − V_r ≈ B (B − A)/(0.06 Re).
  const GarsideAlDibouni defaults;
  for (const double eps_g : {0.3, 0.5, 0.8, 0.85, 0.9, 1.0}) {
    const double a = a_of(eps_g), b = b_of(eps_g);
    EXPECT_DOUBLE_EQ(terminal_velocity_ratio(eps_g, 0.0, defaults), a) << eps_g;
    const double small_re = 1e-8;
    const double slope = 0.06 * (b - a) / a;
    EXPECT_NEAR(terminal_velocity_ratio(eps_g, small_re, defaults) - a, slope * small_re,
                1e-4 * slope * small_re + 1e-15)
        << eps_g;
    const double large_re = 1e7;
    EXPECT_NEAR(b - terminal_velocity_ratio(eps_g, large_re, defaults),
                b * (b - a) / (0.06 * large_re), 1e-5 * b * (b - a) / (0.06 * large_re) + 1e-15)
        << eps_g;
    // In between V_r rises monotonically (B > A throughout [0.3, 1)).
    double previous = a;
    for (const double re : {0.1, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5}) {
      const double vr = terminal_velocity_ratio(eps_g, re, defaults);
      EXPECT_GE(vr, previous) << eps_g << " Re = " << re;
      previous = vr;
    }
  }
}

TEST(SyamlalObrien, VelocityRatioSolvesGarsideAlDibouni) {
  // (V_r − A)/(B − V_r) = 0.06 Re_ts with the single-particle terminal Reynolds number
  // Re_ts = Re/V_r; written as V_r (V_r − A) = 0.06 Re (B − V_r) to avoid 0/0.
  for (const double eps_g : {0.35, 0.6, 0.9})
    for (const double re : {0.01, 1.0, 100.0, 1e4, 1e6}) {
      const double vr = terminal_velocity_ratio(eps_g, re, {});
      const double lhs = vr * (vr - a_of(eps_g));
      const double rhs = 0.06 * re * (b_of(eps_g) - vr);
      EXPECT_NEAR(lhs, rhs, 1e-12 * (vr * vr + 0.06 * re * b_of(eps_g)))
          << "ε_g = " << eps_g << ", Re = " << re;
    }
}

TEST(SyamlalObrien, SlipZeroGivesTheDallaValleLimit) {
  // Re → 0: C_D·(Re/V_r) → 4.8² = 23.04 and V_r → A, so β → ¾ · 23.04 ε_s ε_g μ_g/(A d²)
  // = 17.28 ε_s μ_g ε_g^−3.14/d² (Dalla Valle's C_D → 23.04/Re, not Stokes' 24/Re).
  const auto law = make_law("syamlal-obrien");
  const DragProperties p = air_and_glass_beads();
  const double d2 = p.particle_diameter * p.particle_diameter;
  for (const double eps_g : {0.3, 0.5, 0.9, 0.999}) {
    const double limit = 17.28 * (1 - eps_g) * p.gas_viscosity * std::pow(eps_g, -3.14) / d2;
    EXPECT_NEAR(beta_at(*law, p, eps_g, 0.0), limit, 1e-13 * limit) << eps_g;
    // Continuous at 0: at 0.1 nm/s (Re = 7e-9) within 1e-3 (the √(Re/V_r) term of C_D·Re).
    EXPECT_NEAR(beta_at(*law, p, eps_g, 1e-10), limit, 1e-3 * limit) << eps_g;
  }
}

TEST(SyamlalObrien, SingleParticleLimitIsDallaValle) {
  // ε_g → 1: A = B = 1, V_r = 1, β/ε_s → ¾ ρ_g |slip| C_D(Re)/d with Dalla Valle's C_D.
  const auto law = make_law("syamlal-obrien");
  const DragProperties p = air_and_glass_beads();
  const double eps_s = 1e-6;
  for (const double slip : {0.01, 1.0, 30.0}) {
    const double re = p.gas_density * slip * p.particle_diameter / p.gas_viscosity;
    const double cd = std::pow(0.63 + 4.8 / std::sqrt(re), 2);
    const double single = 0.75 * p.gas_density * slip * cd / p.particle_diameter;
    // Tolerance: V_r and ε_g differ from 1 by O(ε_s) (4.14 ε_s at most, and through C_D).
    EXPECT_NEAR(beta_at(*law, p, 1.0 - eps_s, slip) / eps_s, single, 1e-5 * single) << slip;
  }
}

TEST(SyamlalObrien, DefaultConstantsMakeBContinuousAt085) {
  // c1 = 0.8, d1 = 2.65: 0.8·0.85^1.28 = 0.649750 against 0.85^2.65 = 0.650070 (0.05 %); V_r at
  // large Re (→ B) shows the same step.
  EXPECT_NEAR(b_of(0.85), 0.649750, 1e-6);
  const double below = terminal_velocity_ratio(0.85, 1e7, {});
  const double above = terminal_velocity_ratio(0.85 + 1e-12, 1e7, {});
  EXPECT_NEAR(above / below, 1.0, 5e-4);
}

TEST(SyamlalObrien, C1ActsOnTheDenseBranchAndD1OnTheDilute) {
  const auto defaults = make_law("syamlal-obrien");
  const auto c1 = make_law("syamlal-obrien", {{"c1", 0.5}});
  const auto d1 = make_law("syamlal-obrien", {{"d1", 5.0}});
  const DragProperties p = air_and_glass_beads();
  // B only matters away from Re = 0 (V_r(0) = A): compare at 1 m/s.
  EXPECT_NE(beta_at(*c1, p, 0.5, 1.0), beta_at(*defaults, p, 0.5, 1.0));
  EXPECT_EQ(beta_at(*c1, p, 0.9, 1.0), beta_at(*defaults, p, 0.9, 1.0));
  EXPECT_EQ(beta_at(*d1, p, 0.5, 1.0), beta_at(*defaults, p, 0.5, 1.0));
  EXPECT_NE(beta_at(*d1, p, 0.9, 1.0), beta_at(*defaults, p, 0.9, 1.0));
  EXPECT_EQ(beta_at(*c1, p, 0.5, 0.0), beta_at(*defaults, p, 0.5, 0.0));
}

}  // namespace bagnold::tests
