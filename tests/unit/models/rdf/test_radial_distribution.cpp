// Radial distribution functions at contact, App. B Eqs. 11, 12, 31: closed forms, divergence
// exponents, Dual derivatives against finite differences, and the table the deck names them by.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/dual.hpp"
#include "models/rdf/radial_distribution.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {
namespace rdf = models::rdf;
using models::Dual;

TEST(RadialDistribution, CarnahanStarlingClosedForm) {
  // Eq. 11 at φ = 0.3: (1 − 0.15)/0.7³; and g0 → 1 as φ → 0.
  EXPECT_NEAR(rdf::carnahan_starling(0.3), 0.85 / (0.7 * 0.7 * 0.7), 1e-14);
  EXPECT_DOUBLE_EQ(rdf::carnahan_starling(0.0), 1.0);
}

TEST(RadialDistribution, TorquatoIsCarnahanStarlingBelowFreezingAndContinuousAtIt) {
  const double phi_c = 0.636;
  EXPECT_DOUBLE_EQ(rdf::torquato(0.4, phi_c), rdf::carnahan_starling(0.4));
  // Continuity at φ_f (product form equals g0_CS(φ_f) there); 1e-9: one step of 1e-12 in φ.
  EXPECT_NEAR(rdf::torquato(rdf::freezing_fraction + 1e-12, phi_c),
              rdf::carnahan_starling(rdf::freezing_fraction), 1e-9);
}

TEST(RadialDistribution, TorquatoDivergesWithExponentMinusOne) {
  // The product form of Eq. 12 (model-notes.md): g0 (φ_c − φ) is constant above φ_f.
  const double phi_c = 0.587;
  const double slope = log_log_slope(1e-4, rdf::torquato(phi_c - 1e-4, phi_c), 1e-3,
                                     rdf::torquato(phi_c - 1e-3, phi_c));
  EXPECT_NEAR(slope, -1.0, 1e-12);  // exact power law; tolerance is rounding
}

TEST(RadialDistribution, ChialvoSundaresanDivergesWithExponentMinusThreeHalves) {
  // App. B Fig. 6a: g0 ~ (φ_c − φ)^{−3/2}. Fit over φ_c − φ ∈ [1e-5, 1e-4]; the additive g0_CS
  // (≈ 10 against ≈ 2e5) bends the slope by < 1e-4.
  const double phi_c = 0.613;
  const double slope = log_log_slope(1e-5, rdf::chialvo_sundaresan(phi_c - 1e-5, phi_c), 1e-4,
                                     rdf::chialvo_sundaresan(phi_c - 1e-4, phi_c));
  EXPECT_NEAR(slope, -1.5, 1e-3);
  // Eq. 31 at φ = 0.5, φ_c = 0.613, written out.
  EXPECT_NEAR(rdf::chialvo_sundaresan(0.5, phi_c),
              0.75 / 0.125 + 0.58 * 0.25 / std::pow(0.113, 1.5), 1e-12);
}

TEST(RadialDistribution, DualDerivativesMatchFiniteDifferences) {
  const double phi_c = 0.596;
  for (const double phi : {0.05, 0.3, 0.45, 0.52, 0.58, 0.59}) {
    for (const auto& g0 : rdf::radial_distributions()) {
      const double h = 1e-7;
      const double fd =
          (rdf::evaluate(g0, phi + h, phi_c) - rdf::evaluate(g0, phi - h, phi_c)) / (2 * h);
      const double exact = rdf::evaluate(g0, Dual::variable(phi), phi_c).slope;
      // Central difference with h = 1e-7: truncation ~h² g''' and rounding ~1e-16 g/h; 1e-6
      // relative covers both for these smooth functions away from φ_f.
      EXPECT_NEAR(exact, fd, 1e-6 * std::abs(fd)) << g0.name << " at φ = " << phi;
    }
  }
}

TEST(RadialDistribution, TableListsExactlyTheShippedFunctions) {
  const std::vector<std::string> shipped{"carnahan-starling", "torquato", "mkt"};
  EXPECT_EQ(rdf::radial_distribution_names(), shipped);
  for (const auto& name : shipped) EXPECT_EQ(rdf::radial_distribution(name).name, name);
}

TEST(RadialDistribution, EachNameEvaluatesItsOwnFormula) {
  // Above φ_f and below φ_c the three differ; each name must give its own closed form, in
  // double and in Dual.
  const double phi = 0.55, phi_c = 0.596;
  const double expected[] = {rdf::carnahan_starling(phi), rdf::torquato(phi, phi_c),
                             rdf::chialvo_sundaresan(phi, phi_c)};
  const auto& table = rdf::radial_distributions();
  ASSERT_EQ(table.size(), 3u);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_EQ(rdf::evaluate(table[i], phi, phi_c), expected[i]) << table[i].name;
    EXPECT_EQ(rdf::evaluate(table[i], Dual::variable(phi), phi_c).value, expected[i])
        << table[i].name;
  }
  EXPECT_NE(expected[0], expected[1]);
  EXPECT_NE(expected[1], expected[2]);
}

TEST(RadialDistribution, UnknownNamesAreRejectedWithTheAlternatives) {
  try {
    rdf::radial_distribution("lun");
    FAIL() << "expected an unknown-name error";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (const auto& name : rdf::radial_distribution_names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

}  // namespace bagnold::tests
