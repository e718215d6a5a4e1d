// Every registered stress model: the registry lists exactly what we ship, unknown names list
// the alternatives, coefficient declarations are complete, and outputs are finite over the
// whole state range the solver can visit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

TEST(SolidsStress, MismatchedArraysAreRejected) {
  std::vector<double> one(1, 0.3), two(2, 0.0);
  const models::SolidsState in{one, one, one};
  models::SolidsStress out{two, two, two, two, two};
  EXPECT_THROW(make_model("mkt")->evaluate(Material{}, in, out), std::invalid_argument);
}

}  // namespace bagnold::tests
