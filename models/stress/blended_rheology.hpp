#pragma once
// The blended steady-shear rheology shared by `steady-shear` (Chialvo, Sun & Sundaresan 2012,
// report App. A Eqs. 7–15) and `steady-shear-cohesive` (Gu, Chialvo & Sundaresan 2014,
// App. D Eqs. 7–19): App. A is App. D's non-cohesive form with ε = 2/3, χ = 2 and its own
// constants, so one implementation serves both; each model file supplies its table.
//
// In scaled form (p̂ = p d/k, γ̂ = γ̇ d/sqrt(k/(ρ_s d)), Hookean contacts):
//   p̂_QS    = α_QS |φ − φ_c|^ε                      A Eq. 8,  D Eq. 7
//   p̂_int   = α_int γ̂^{2ε/(ε+χ)}                    A Eq. 9,  D Eq. 8
//   p̂_inert = α_inert γ̂² / |φ_c − φ|^χ              A Eq. 10, D Eq. 9
//   p̂_coh,1 = α_coh,1 Bo* |φ − φ_a| / |φ_c − φ|      D Eq. 11
//   p̂_coh,2 = α_coh,2 Bo*^{ε/(ε+χ)}                  D Eq. 12
//   φ ≥ φ_c: p̂ = p̂_QS + p̂_int + p̂_coh,2;  φ < φ_c: harmonic blend of (p̂_inert + p̂_coh,1) and
//   (p̂_int + p̂_coh,2)                               A Eq. 7,  D Eq. 10
//   η = η_hard(I) − η_soft(γ̂) + α₃ φ Bo* (k/d)/p · 1/(γ̂/(α₄√Bo*) + 1)
//                                     A Eqs. 11–13, D Eqs. 13–15, 19 (γ̂, not γ̇: see D Eq. 25)
//   I = γ̇ d/sqrt(p/ρ_s) = γ̂/sqrt(p̂), with the full (cohesive) pressure.
//   σ = p(I − η Ŝ) (A Eq. 15): shear viscosity μ_s = η p/γ̇ (regularized), no bulk viscosity.
//
// Valid: dense flow, φ ≳ 0.5 (App. D Fig. 9 data reach down to φ ≈ 0.5), Hookean contacts.
// Outside: the formulas stay finite at any φ ≥ 0 and γ̇ ≥ 0; they are not a dilute theory.

#include <string>
#include <vector>

#include "models/coefficients.hpp"
#include "models/dual.hpp"
#include "models/material.hpp"
#include "models/stress/onset_smoothing.hpp"
#include "models/stress/pointwise.hpp"
#include "models/stress/regularization.hpp"

namespace bagnold::models::blended {

// The stress-ratio constants of η_hard and η_soft, which App. A (Eqs. 11–12, Table II) and
// App. D (Eqs. 14–15, Table I) print with the same values: declared once, here, for both models
// (deck keys i0, alpha_1, beta_1, gamma_hat_0, alpha_2, beta_2).
struct StressRatio {
  double transition_inertial_number = 0.32;  // I_0 [-]
  double hard_rise = 0.37;                   // α₁ [-]
  double hard_exponent = 1.5;                // β₁ [-]
  double transition_shear_rate = 0.1;        // γ̂_0 [-]
  double soft_drop = 0.2;                    // α₂ [-]
  double soft_exponent = 1.0;                // β₂ [-]
};

struct Constants {
  // μ-dependent (from the model's table at the material's μ)
  double critical_fraction;            // φ_c [-]
  double quasi_static_exponent;        // ε [-]  (2/3 in App. A)
  double inertial_exponent;            // χ [-]  (2 in App. A)
  double quasi_static;                 // α_QS [-]
  double intermediate;                 // α_int [-]
  double yield_stress_ratio;           // η_s [-]
  double cohesive_1 = 0.0;             // α_coh,1 [-]
  double cohesive_stress_ratio = 0.0;  // α₃ [-]
  // μ-independent
  double inertial;           // α_inert [-]
  StressRatio stress_ratio;  // I_0, α₁, β₁, γ̂_0, α₂, β₂
  // Cohesion (App. D): zero, i.e. none, unless the model sets them (steady_shear_cohesive.hpp
  // holds their defaults); each multiplies Bo* or is used only where Bo* > 0.
  double cohesive_onset_fraction = 0.0;  // φ_a [-]
  double cohesive_2 = 0.0;               // α_coh,2 [-]
  double cohesive_rate = 0.0;            // α₄ [-]
  double onset_smoothing;  // x_s [-] at onset of |φ − φ_c|^ε (onset_smoothing.hpp)
};

// γ̂ = γ̇ d / sqrt(k/(ρ_s d)), App. A Sec. III.
double scaled_shear_rate(double shear_rate, const Material& material);

// p̂(φ, γ̂, Bo*) of App. A Eq. 7 / App. D Eq. 10 (Real = double or Dual in φ).
template <class Real>
Real scaled_pressure(Real phi, double scaled_rate, double bond_number, const Constants& c);

// η_hard(I) = η_s + α₁/((I_0/I)^β₁ + 1), App. A Eq. 11 / App. D Eq. 14.
double hard_stress_ratio(double inertial_number, const Constants& c);
// η_soft(γ̂) = α₂/((γ̂_0/γ̂)^β₂ + 1), App. A Eq. 12 / App. D Eq. 15.
double soft_stress_ratio(double scaled_rate, const Constants& c);
// τ̂ = τ d/k = η p̂, App. A Eq. 13 / App. D Eq. 19 multiplied through by p̂ (no 0/0 at p̂ = 0);
// η is kept ≥ 0 (η_soft can exceed η_hard at large γ̂ for small η_s).
double scaled_shear_stress(double phi, double scaled_rate, double scaled_pressure,
                           double bond_number, const Constants& c);

// The point stress of the blended rheology (T undefined: NaN).
PointStress point_stress(double phi, double shear_rate, const Material& material,
                         const Constants& c, const ViscosityLimits& limits);

// The stress-ratio constants both rheology models declare, with the same defaults (App. A
// Eqs. 11–12 and Table II; App. D Eqs. 14–15 and Table I). `hard`, `soft` and `table` name the
// equations and table of the model's own appendix, for the docs.
std::vector<CoefficientSpec> stress_ratio_specs(const std::string& hard, const std::string& soft,
                                                const std::string& table);

// Reads those constants from a model's resolved coefficients.
StressRatio read_stress_ratio(const Coefficients& c);

}  // namespace bagnold::models::blended
