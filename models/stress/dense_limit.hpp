#pragma once
// What the kinetic models (SKT, MKT) do where kinetic theory stops: at and above the jamming
// point φ_c(μ), and at vanishing solids fraction. docs/models.md, "At and above φ_c".
//
//  1. Jamming cap. g0 (and MKT's dense temperature branch) are evaluated at
//     φ_j = min(φ, φ_c − δ), δ = jamming_margin, so they stay finite; the explicit φ factors of
//     H, J, K are not capped, so the kinetic pressure keeps growing mildly with φ.
//  2. Quasi-static pressure. From φ_j on, a rate-independent pressure of the form of
//     App. A Eq. 8 takes over the job of resisting compaction:
//        P_qs = s · α_QS(μ) · (k/d) · g(φ − φ_j),   g(x) = x² (x² + x_s²)^{1/3 − 1} for x > 0
//     g(x) → x^{2/3} for x ≫ x_s (Eq. 8's exponent) and g has a finite slope at onset, so
//     dP_s/dε_s stays finite (onset_smoothing.hpp, x_s shared with the rheology models). It carries
//     the yield shear stress τ_qs = η_s(μ) P_qs (Mohr–Coulomb with App. A's yield stress ratio),
//     whose viscosity is regularized.
// The other end, φ → 0, is dilute_limit.hpp's.

#include <vector>

#include "models/coefficients.hpp"
#include "models/dual.hpp"
#include "models/material.hpp"
#include "models/stress/onset_smoothing.hpp"

namespace bagnold::models {

struct DenseLimit {
  double jamming_margin = 0.01;                      // δ [-]
  double quasi_static_scale = 1.0;                   // s [-]
  double onset_smoothing = default_onset_smoothing;  // x_s [-]

  static std::vector<CoefficientSpec> specs();
  static DenseLimit read(const Coefficients& c);

  // φ_j = φ_c − δ: where g0 stops growing and the quasi-static pressure starts.
  double jamming_fraction(double critical_fraction) const {
    return critical_fraction - jamming_margin;
  }
  // min(φ, φ_j), with zero slope past the cap.
  template <class Real>
  Real capped(Real phi, double critical_fraction) const;
  // P_qs [Pa] for stiffness/diameter k/d [Pa] and friction coefficient μ.
  template <class Real>
  Real quasi_static_pressure(Real phi, double critical_fraction, double stiffness_over_diameter,
                             double friction) const;
};

// The pressure that SKT and MKT share: P_s = ρ_s H T + P_qs with T = T_factor (γ̇d)², where the
// factors H (pressure_factor) and T_factor come as duals in φ so dP_s/dε_s at fixed γ̇ is exact.
// quasi_static is P_qs, whose yield stress η_s P_qs each model adds as a regularized viscosity.
struct KineticDensePressure {
  double pressure = 0.0;             // P_s [Pa]
  double pressure_derivative = 0.0;  // dP_s/dε_s [Pa]
  double temperature = 0.0;          // T [m²/s²]
  double quasi_static = 0.0;         // P_qs [Pa]
};
KineticDensePressure kinetic_dense_pressure(double phi, double shear_rate, const Material& material,
                                            const Dual& pressure_factor,
                                            const Dual& temperature_factor,
                                            double critical_fraction, const DenseLimit& dense);

}  // namespace bagnold::models
