// Every registered stress model: the registry lists exactly what we ship, unknown names list
// the alternatives, coefficient declarations are complete, outputs are finite over the whole
// state range the solver can visit, and the packing limit and wall g0 each model reports are
// those the solver computed itself before the interface had them (solids_wall.cpp, issue 18).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "models/rdf/radial_distribution.hpp"
#include "models/stress/friction_table.hpp"
#include "models/stress/solids_stress.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {

TEST(StressRegistry, ListsExactlyTheShippedModels) {
  const std::vector<std::string> shipped{"mfix-default", "mkt",          "plastic",
                                         "skt",          "steady-shear", "steady-shear-cohesive"};
  EXPECT_EQ(models::stress_registry().names(), shipped);
  for (const auto& name : shipped) EXPECT_EQ(make_model(name)->name(), name);
}

TEST(StressRegistry, UnknownNameListsAlternatives) {
  try {
    make_model("mtk");
    FAIL() << "expected UnknownModel";
  } catch (const models::UnknownModel& e) {
    const std::string message = e.what();
    for (const auto& name : models::stress_registry().names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(StressRegistry, UnknownCoefficientIsRejected) {
  EXPECT_THROW(make_model("mkt", {{"jaming_margin", 0.01}}), std::invalid_argument);
}

TEST(StressRegistry, EveryCoefficientHasUnitDocAndADefaultInRange) {
  for (const auto& entry : models::stress_registry().entries()) {
    EXPECT_FALSE(entry.summary.empty());
    for (const auto& spec : entry.coefficients) {
      const std::string where = entry.name + "." + spec.name;
      EXPECT_FALSE(spec.unit.empty()) << where;
      // The doc names the unit in brackets after the report's symbol, e.g. "δ [-]: ...".
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

TEST(SolidsStress, EveryModelIsFiniteOverTheWholeStateRange) {
  // φ ∈ [0, 0.7] (past every φ_c), γ̇ ∈ [0, 1e4] 1/s, compression and expansion, several μ and
  // Bo*: P_s, dP_s/dε_s, μ_s, λ_s finite and non-negative where they must be; T finite where
  // the model defines it.
  std::vector<double> phi, rate, divergence;
  for (int i = 0; i <= 140; ++i)
    for (const double g : {0.0, 1e-6, 1e-3, 1.0, 30.0, 1e3, 1e4})
      for (const double t : {0.0, 0.5, -0.5}) {
        phi.push_back(0.005 * i);
        rate.push_back(g);
        divergence.push_back(t * g);
      }
  const std::size_t n = phi.size();
  for (const auto& name : models::stress_registry().names()) {
    const auto model = make_model(name);
    for (const double friction : {0.0, 0.3, 1.0, 2.0})
      for (const double bond : {0.0, 5e-5}) {
        Material m;
        m.friction = friction;
        m.bond_number = bond;
        std::vector<double> p(n), dp(n), mu(n), lambda(n), temperature(n);
        const models::SolidsState in{phi, rate, divergence};
        models::SolidsStress out{p, dp, mu, lambda, temperature};
        model->evaluate(m, in, out);
        for (std::size_t k = 0; k < n; ++k) {
          const std::string where =
              name + " μ=" + std::to_string(friction) + " Bo*=" + std::to_string(bond) +
              " φ=" + std::to_string(phi[k]) + " γ̇=" + std::to_string(rate[k]) +
              " trD=" + std::to_string(divergence[k]);
          ASSERT_TRUE(std::isfinite(p[k]) && p[k] >= 0.0) << where << " P=" << p[k];
          ASSERT_TRUE(std::isfinite(dp[k])) << where << " dP=" << dp[k];
          ASSERT_TRUE(std::isfinite(mu[k]) && mu[k] >= 0.0) << where << " μ_s=" << mu[k];
          ASSERT_TRUE(std::isfinite(lambda[k]) && lambda[k] >= 0.0) << where;
          if (model->defines_temperature())
            ASSERT_TRUE(std::isfinite(temperature[k]) && temperature[k] >= 0.0) << where;
          else
            ASSERT_TRUE(std::isnan(temperature[k])) << where;
        }
      }
  }
}

namespace {
// What solver/simple/solids_wall.cpp computed from the deck before the interface had these
// calls (solids_packing_limit and capped_carnahan_starling at dc6e78f), for the models to match
// bit for bit.
double packing_limit_by_coefficient_name(const models::Coefficients& resolved, double friction) {
  const auto found = resolved.find("packed_gas_fraction");
  if (found != resolved.end() && std::holds_alternative<double>(found->second))
    return 1.0 - std::get<double>(found->second);
  return models::chialvo2012::critical_fraction(friction);
}
double wall_g0_before(double fraction, double packing_limit) {
  return models::rdf::carnahan_starling(
      std::clamp(std::max(fraction, 0.0), 0.0, std::max(packing_limit - 0.01, 0.0)));
}
}  // namespace

TEST(SolidsStress, PackingLimitIsWhatTheWallsLookedUpByName) {
  for (const auto& entry : models::stress_registry().entries()) {
    for (const models::Coefficients& given :
         {models::Coefficients{}, entry.name == "plastic" || entry.name == "mfix-default"
                                      ? models::Coefficients{{"packed_gas_fraction", 0.45}}
                                      : models::Coefficients{}}) {
      const auto model = make_model(entry.name, given);
      const auto resolved = models::resolve(entry.coefficients, test_coefficients(entry.name, given));
      for (const double friction : {0.0, 0.1, 0.2, 0.3, 0.5, 0.77, 1.0}) {
        Material m;
        m.friction = friction;
        EXPECT_EQ(model->packing_limit(m), packing_limit_by_coefficient_name(resolved, friction))
            << entry.name << " at μ = " << friction;
      }
    }
  }
  // Written out: 1 − ε_g* for the plastic closures, App. A Table I's φ_c(0.3) = 0.596 otherwise.
  Material m;
  m.friction = 0.3;
  EXPECT_DOUBLE_EQ(make_model("plastic", {{"packed_gas_fraction", 0.45}})->packing_limit(m), 0.55);
  EXPECT_DOUBLE_EQ(make_model("mfix-default")->packing_limit(m), 0.6);
  for (const std::string name : {"skt", "mkt", "steady-shear", "steady-shear-cohesive"})
    EXPECT_DOUBLE_EQ(make_model(name)->packing_limit(m), 0.596) << name;
}

TEST(SolidsStress, WallRadialDistributionIsCarnahanStarlingCappedBelowThePackingLimit) {
  for (const auto& name : models::stress_registry().names()) {
    const auto model = make_model(name);
    for (const double friction : {0.1, 0.5}) {
      Material m;
      m.friction = friction;
      const double limit = model->packing_limit(m);
      for (const double phi : {-0.05, 0.0, 1e-8, 0.2, 0.45, limit - 0.02, limit - 0.01,
                               limit - 0.005, limit, limit + 0.03, 1.0})
        EXPECT_EQ(model->wall_radial_distribution(m, phi), wall_g0_before(phi, limit))
            << name << " at φ = " << phi;
    }
  }
  // Hand values: mfix-default's φ_max = 0.6 caps φ at 0.59, g0 = (1 − 0.295)/0.41³; below the
  // cap, Carnahan–Starling itself, (1 − 0.15)/0.7³ at φ = 0.3; g0 = 1 for an empty cell.
  const auto mfix = make_model("mfix-default");
  EXPECT_NEAR(mfix->wall_radial_distribution(Material{}, 0.7), 0.705 / (0.41 * 0.41 * 0.41), 1e-12);
  EXPECT_NEAR(mfix->wall_radial_distribution(Material{}, 0.3), 0.85 / (0.7 * 0.7 * 0.7), 1e-12);
  EXPECT_EQ(mfix->wall_radial_distribution(Material{}, -0.1), 1.0);
}

TEST(SolidsStress, MismatchedArraysAreRejected) {
  std::vector<double> one(1, 0.3), two(2, 0.0);
  const models::SolidsState in{one, one, one};
  models::SolidsStress out{two, two, two, two, two};
  EXPECT_THROW(make_model("mkt")->evaluate(Material{}, in, out), std::invalid_argument);
}

}  // namespace bagnold::tests
