// Every registered drag law: the registry lists exactly what we ship, coefficient declarations
// are complete, β is finite and non-negative over the stated range (slip exactly 0 included),
// vanishes linearly with ε_s, and out-of-range inputs are clipped or rejected as documented.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "models/drag/drag_law.hpp"
#include "tests/unit/models/drag/drag_probe.hpp"

namespace bagnold::tests {

namespace {
// Every law, and the non-default choices that change its form.
std::vector<std::pair<std::string, models::Coefficients>> every_variant() {
  return {{"wen-yu", {}},
          {"gidaspow", {}},
          {"gidaspow", {{"transition", std::string("arctan-blend")}}},
          {"syamlal-obrien", {}},
          {"syamlal-obrien", {{"c1", 0.3}, {"d1", 1.28 + std::log(0.3) / std::log(0.85)}}}};
}
}  // namespace

TEST(DragRegistry, ListsExactlyTheShippedLaws) {
  const std::vector<std::string> shipped{"gidaspow", "syamlal-obrien", "wen-yu"};
  EXPECT_EQ(models::drag_registry().names(), shipped);
  for (const auto& name : shipped) EXPECT_EQ(make_law(name)->name(), name);
}

TEST(DragRegistry, UnknownNameListsAlternatives) {
  try {
    make_law("wen-yue");
    FAIL() << "expected UnknownModel";
  } catch (const models::UnknownModel& e) {
    const std::string message = e.what();
    for (const auto& name : models::drag_registry().names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  EXPECT_THROW(make_law("gidaspow", {{"transitoin", std::string("step")}}),
               std::invalid_argument);
}

TEST(DragRegistry, EveryCoefficientHasUnitDocAndADefaultInRange) {
  for (const auto& entry : models::drag_registry().entries()) {
    EXPECT_FALSE(entry.summary.empty());
    for (const auto& spec : entry.coefficients) {
      const std::string where = entry.name + "." + spec.name;
      EXPECT_FALSE(spec.unit.empty()) << where;
      EXPECT_NE(spec.doc.find("[" + spec.unit + "]"), std::string::npos) << where;
      if (const auto* value = std::get_if<double>(&spec.default_value)) {
        EXPECT_GE(*value, spec.min) << where;
        EXPECT_LE(*value, spec.max) << where;
      } else {
        const auto& choice = std::get<std::string>(spec.default_value);
        EXPECT_NE(std::find(spec.choices.begin(), spec.choices.end(), choice), spec.choices.end())
            << where;
      }
    }
  }
}

TEST(DragLaw, FiniteAndNonNegativeOverTheStatedRange) {
  // ε_g ∈ [0.3, 1] every 0.0025 plus the switch points 0.8 and 0.85 and their neighbours,
  // slip 0…100 m/s with exact 0; air with 1 mm and 50 μm beads, and water with 1 mm beads.
  std::vector<double> eps, slip;
  std::vector<double> gas_fractions{0.8, 0.8 + 1e-15, 0.85, 0.85 + 1e-15, 1.0 - 1e-15};
  for (int i = 0; i <= 280; ++i) gas_fractions.push_back(0.3 + 0.0025 * i);
  for (const double e : gas_fractions)
    for (const double s : {0.0, 1e-300, 1e-12, 1e-6, 1e-3, 0.01, 0.1, 1.0, 10.0, 50.0, 100.0}) {
      eps.push_back(e);
      slip.push_back(s);
    }
  DragProperties fine = air_and_glass_beads();
  fine.particle_diameter = 50e-6;
  const DragProperties water{.gas_density = 1000.0, .gas_viscosity = 1e-3,
                             .particle_diameter = 1e-3, .particle_density = 2500.0};
  for (const auto& [name, coefficients] : every_variant()) {
    const auto law = make_law(name, coefficients);
    for (const DragProperties& p : {air_and_glass_beads(), fine, water}) {
      std::vector<double> beta(eps.size(), -1.0);
      law->evaluate(p, {eps, slip}, beta);
      for (std::size_t k = 0; k < eps.size(); ++k) {
        const std::string where = name + " d=" + std::to_string(p.particle_diameter) +
                                  " ε_g=" + std::to_string(eps[k]) +
                                  " slip=" + std::to_string(slip[k]);
        ASSERT_TRUE(std::isfinite(beta[k])) << where << " β=" << beta[k];
        if (eps[k] < 1.0)
          ASSERT_GT(beta[k], 0.0) << where;
        else
          ASSERT_EQ(beta[k], 0.0) << where;
      }
    }
  }
}

TEST(DragLaw, SlipZeroGivesAFiniteLimitContinuousWithSmallSlip) {
  // β(slip = 0) is the Re → 0 limit (Stokes, Darcy or Dalla Valle; the laws' own tests check
  // the value), not 0 and not NaN; at 10 nm/s (Re ≤ 7e-7) it has moved by less than 1 %
  // (Syamlal–O'Brien moves fastest, as √(Re/V_r) with V_r = A = 0.0068 at ε_g = 0.3: 0.3 %).
  const DragProperties p = air_and_glass_beads();
  for (const auto& [name, coefficients] : every_variant()) {
    const auto law = make_law(name, coefficients);
    for (const double eps_g : {0.3, 0.6, 0.8, 0.9, 0.99}) {
      const double at_zero = beta_at(*law, p, eps_g, 0.0);
      ASSERT_TRUE(std::isfinite(at_zero) && at_zero > 0.0) << name << " ε_g=" << eps_g;
      EXPECT_NEAR(beta_at(*law, p, eps_g, 1e-8), at_zero, 1e-2 * at_zero)
          << name << " ε_g=" << eps_g;
    }
  }
}

TEST(DragLaw, VanishesLinearlyAsSolidsFractionVanishes) {
  // β = ε_s · f(ε_g, slip) with f smooth at ε_g = 1: β/ε_s agrees at ε_s = 1e-5 and 1e-7 to
  // O(ε_s), with |d ln f/dε_g| < 20 at ε_g = 1 (largest for Syamlal–O'Brien, whose V_r carries
  // ε_g^4.14 and enters as V_r² and through C_D: 14 at 10 m/s); and β(ε_g = 1) = 0.
  const DragProperties p = air_and_glass_beads();
  for (const auto& [name, coefficients] : every_variant()) {
    const auto law = make_law(name, coefficients);
    for (const double slip : {0.0, 0.1, 10.0}) {
      const double coarse = beta_at(*law, p, 1.0 - 1e-5, slip) / 1e-5;
      const double fine = beta_at(*law, p, 1.0 - 1e-7, slip) / 1e-7;
      EXPECT_NEAR(coarse / fine, 1.0, 20 * 1e-5) << name << " slip=" << slip;
      EXPECT_EQ(beta_at(*law, p, 1.0, slip), 0.0) << name;
    }
  }
}

TEST(DragLaw, GasFractionsOutsideTheRangeAreClipped) {
  // Above 1 (an iterate with ε_s < 0): β = 0. Below min_gas_fraction (default 0.2): evaluated
  // at it, so β stays finite even at ε_g ≤ 0.
  const DragProperties p = air_and_glass_beads();
  for (const auto& name : models::drag_registry().names()) {
    const auto law = make_law(name);
    EXPECT_EQ(beta_at(*law, p, 1.05, 1.0), 0.0) << name;
    const double floor = beta_at(*law, p, 0.2, 1.0);
    EXPECT_EQ(beta_at(*law, p, 0.1, 1.0), floor) << name;
    EXPECT_EQ(beta_at(*law, p, -0.1, 1.0), floor) << name;
    EXPECT_EQ(beta_at(*law, p, 0.5, -1.0), beta_at(*law, p, 0.5, 1.0)) << name;  // |slip|
    const auto lower = make_law(name, {{"min_gas_fraction", 0.05}});
    EXPECT_GT(beta_at(*lower, p, 0.1, 1.0), floor) << name;
  }
}

TEST(DragLaw, RejectsBadPropertiesAndMismatchedArrays) {
  const auto law = make_law("gidaspow");
  DragProperties no_viscosity = air_and_glass_beads();
  no_viscosity.gas_viscosity = 0.0;
  EXPECT_THROW(beta_at(*law, no_viscosity, 0.5, 1.0), std::invalid_argument);
  DragProperties no_diameter = air_and_glass_beads();
  no_diameter.particle_diameter = 0.0;
  EXPECT_THROW(beta_at(*law, no_diameter, 0.5, 1.0), std::invalid_argument);
  const std::vector<double> one(1, 0.5), two(2, 0.5);
  std::vector<double> beta(1);
  EXPECT_THROW(law->evaluate(air_and_glass_beads(), {one, two}, beta), std::invalid_argument);
}

}  // namespace bagnold::tests
