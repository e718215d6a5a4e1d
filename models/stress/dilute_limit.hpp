#pragma once
// What the algebraic-temperature kinetic models (SKT, MKT, mfix-default) do as φ → 0.
// docs/models.md, "Dilute limit".
//
// Homogeneous-shear kinetic theory balances production against collisional dissipation, which
// vanishes as φ²: T ~ (γ̇d)²/φ² and, at a fixed shear rate, P_s = ρ_s H T ~ 1/φ. Below the
// fraction φ_d where P_s(φ) at fixed γ̇ is smallest (about 0.17 for the shipped models) the
// pressure therefore falls as solids are added: dP_s/dε_s < 0, a negative compressibility that
// empties dilute cells ever faster (the bin's free surface and jet blew up this way). Two
// treatments, chosen by the key dilute_stress:
//   ideal-gas (default)  below φ_d every stress is the one at φ_d scaled by φ/φ_d, at the
//                        temperature of φ_d: a dilute gas at fixed T has P = ρ_s φ T, linear in
//                        φ, and the kinematic viscosities μ_s/(ρ_s φ) stay those of φ_d. P_s is
//                        then continuous and non-decreasing in φ; dP_s/dε_s = P_s(φ_d)/φ_d.
//   kinetic              the formulas as printed, down to dilute_cutoff ("printed" for the
//                        steady-shear rheology, whose printed P_s stays finite at φ = 0).
// Below dilute_cutoff φ_min both give zero stress and T = 0 (NaN for a model without T).
// The steady-shear rheology uses the same treatment with the tangent anchor (below).

#include <cmath>
#include <optional>
#include <vector>

#include "models/coefficients.hpp"
#include "models/stress/pointwise.hpp"

namespace bagnold::models {

struct DiluteLimit {
  // Where the linear branch P_s = P_s(φ_d) φ/φ_d starts. pressure_minimum: the kinetic models,
  // whose P_s(φ) falls towards φ = 0 below its minimum. tangent: models whose P_s stays finite
  // at φ = 0 (the steady-shear rheology); φ_d is where P_s/φ is smallest, so the line through
  // the origin is tangent to P_s there and dP_s/dε_s is continuous.
  enum class Anchor { pressure_minimum, tangent };
  double cutoff = 1e-6;    // φ_min [-]
  bool ideal_gas = true;   // dilute_stress = "ideal-gas"
  Anchor anchor = Anchor::pressure_minimum;
  // What the owning model's point function gives for the last material it saw: φ_d (the
  // bisection costs ~60 point evaluations) and T in an empty cell (0 where the model defines a
  // temperature, NaN where it has none). A run's material does not change between calls.
  mutable std::optional<Material> minimum_for;
  mutable double minimum = 0.0;
  mutable double empty_temperature = 0.0;

  static std::vector<CoefficientSpec> specs(Anchor anchor = Anchor::pressure_minimum);
  static DiluteLimit read(const Coefficients& c, Anchor anchor = Anchor::pressure_minimum);
};

// The fraction φ_d in [lower, upper] where pressure_slope(φ) (dP_s/dφ at a fixed shear rate)
// changes sign from negative to positive, by bisection; lower if the slope is already ≥ 0
// there (no falling branch), upper if it is still negative there.
template <class SlopeFunction>
double pressure_minimum_fraction(SlopeFunction&& pressure_slope, double lower, double upper) {
  if (!(pressure_slope(lower) < 0.0)) return lower;
  if (pressure_slope(upper) < 0.0) return upper;
  for (int k = 0; k < 60 && upper - lower > 1e-10; ++k) {
    const double middle = 0.5 * (lower + upper);
    (pressure_slope(middle) < 0.0 ? lower : upper) = middle;
  }
  return 0.5 * (lower + upper);
}

// evaluate_cells with the dilute treatment above wrapped around the model's point function.
// φ_d is found on the point function itself at γ̇ = 1, tr D = 0, once per material: the kinetic
// pressure scales as γ̇², so their φ_d does not depend on the rate; the steady-shear tangent
// point does only outside the inertial regime.
template <class PointFunction>
void evaluate_cells_dilute_limited(const DiluteLimit& dilute, const Material& material,
                                   const SolidsState& in, SolidsStress& out, PointFunction&& point,
                                   RateMeasure measure = RateMeasure::deviatoric) {
  const auto limited = [&](double phi, double shear_rate, double divergence) {
    if (phi < dilute.cutoff) {
      PointStress zero;
      zero.granular_temperature = dilute.empty_temperature;
      return zero;
    }
    return point(phi, shear_rate, divergence);
  };
  if (dilute.minimum_for != material) {
    const double sample_temperature = point(0.5, 1.0, 0.0).granular_temperature;
    dilute.empty_temperature = std::isnan(sample_temperature) ? sample_temperature : 0.0;
    const double lowest = dilute.cutoff > 1e-4 ? dilute.cutoff : 1e-4;
    // The sign of dP_s/dφ, or for the tangent that of d(P_s/φ)/dφ times φ².
    dilute.minimum = pressure_minimum_fraction(
        [&](double phi) {
          const PointStress s = limited(phi, 1.0, 0.0);
          return dilute.anchor == DiluteLimit::Anchor::tangent
                     ? s.pressure_derivative * phi - s.pressure
                     : s.pressure_derivative;
        },
        lowest, 0.5);
    dilute.minimum_for = material;
  }
  if (!dilute.ideal_gas) {
    evaluate_cells(in, out, limited, measure);
    return;
  }
  const double minimum = dilute.minimum;
  evaluate_cells(in, out, [&](double phi, double shear_rate, double divergence) {
    if (phi >= minimum || phi < dilute.cutoff) return limited(phi, shear_rate, divergence);
    PointStress s = limited(minimum, shear_rate, divergence);
    const double scale = phi / minimum;
    s.pressure_derivative = s.pressure / minimum;
    s.pressure *= scale;
    s.shear_viscosity *= scale;
    s.bulk_viscosity *= scale;
    return s;
  }, measure);
}

}  // namespace bagnold::models
