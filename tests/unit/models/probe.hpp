#pragma once
// Test helpers for models/: evaluate a stress model at one point, central finite differences
// and log-log slopes. Header-only, shared by the tests of this folder.

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "models/stress/pointwise.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::tests {

using models::Material;
using models::PointStress;

inline PointStress probe(const models::SolidsStressModel& model, const Material& material,
                         double phi, double strain_rate, double divergence = 0.0) {
  std::vector<double> f{phi}, g{strain_rate}, t{divergence}, p(1), dp(1), mu(1), lambda(1),
      temperature(1);
  const models::SolidsState in{f, g, t};
  models::SolidsStress out{p, dp, mu, lambda, temperature};
  model.evaluate(material, in, out);
  return {p[0], dp[0], mu[0], lambda[0], temperature[0]};
}

// Central difference of P_s in φ at fixed strain rate.
inline double finite_difference_pressure_derivative(const models::SolidsStressModel& model,
                                                    const Material& material, double phi,
                                                    double strain_rate, double step) {
  return (probe(model, material, phi + step, strain_rate).pressure -
          probe(model, material, phi - step, strain_rate).pressure) /
         (2.0 * step);
}

// Slope of log y against log x between two points.
inline double log_log_slope(double x1, double y1, double x2, double y2) {
  return std::log(y2 / y1) / std::log(x2 / x1);
}

// The rheology models' scaled variables (App. A Sec. III): γ̇ for a scaled shear rate γ̂, the
// scaled pressure p d/k at γ̂, and its log-log slope between two γ̂.
inline double rate_for(double scaled_rate, const Material& m) {
  return scaled_rate * std::sqrt(m.stiffness / (m.density * m.diameter)) / m.diameter;
}
inline double scaled_pressure(const models::SolidsStressModel& model, const Material& m,
                              double phi, double scaled_rate) {
  return probe(model, m, phi, rate_for(scaled_rate, m)).pressure * m.diameter / m.stiffness;
}
inline double scaled_pressure_slope(const models::SolidsStressModel& model, const Material& m,
                                    double phi, double from, double to) {
  return log_log_slope(from, scaled_pressure(model, m, phi, from), to,
                       scaled_pressure(model, m, phi, to));
}

// `given`, with the tests' value of every coefficient a model requires: mfix-default's ε_g* 0.4.
inline models::Coefficients test_coefficients(const std::string& name, const models::Coefficients& given = {}) {
  models::Coefficients with = given;
  if (name == "mfix-default" && !with.contains("packed_gas_fraction")) with["packed_gas_fraction"] = 0.4;
  return with;
}

// The model with `given` coefficients (test_coefficients fills the required ones).
inline std::unique_ptr<models::SolidsStressModel> make_model(
    const std::string& name, const models::Coefficients& given = {}) {
  return models::stress_registry().create(name, test_coefficients(name, given));
}

}  // namespace bagnold::tests
