#pragma once
// Radial distribution functions at contact g0(φ), one file per member. Each is a template over
// the scalar type (double, or Dual for dg0/dφ) with explicit instantiations in its .cpp.
// Callers keep φ below the divergence (φ_c for Torquato and Chialvo–Sundaresan); the stress
// models do so with their jamming margin (docs/models.md, "At and above φ_c").

#include <string>
#include <type_traits>
#include <vector>

#include "models/dual.hpp"

namespace bagnold::models::rdf {

// Freezing point of hard spheres, φ_f (App. B, Sec. I: "φ_f ≈ 0.49").
inline constexpr double freezing_fraction = 0.49;

// App. B Eq. 11: g0_CS = (1 − φ/2)/(1 − φ)³. Valid below φ_f; finite up to φ = 1.
template <class Real>
Real carnahan_starling(Real phi);

// App. B Eq. 12, Torquato: g0_CS(φ) for φ ≤ φ_f, and for φ > φ_f the product
// g0_CS(φ_f)·(φ_c − φ_f)/(φ_c − φ) — printed as a power, but the text says it diverges at φ_c
// with exponent −1, which only the product does (model-notes.md).
template <class Real>
Real torquato(Real phi, double critical_fraction);

// α₂ of App. B Eq. 31 (Table II); MKT's deck default (mkt.hpp) is this one.
inline constexpr double chialvo_sundaresan_scale = 0.58;

// App. B Eq. 31 (MKT): g0 = g0_CS + α₂ φ²/(φ_c(μ) − φ)^{3/2}, α₂ = 0.58 (App. B Table II).
template <class Real>
Real chialvo_sundaresan(Real phi, double critical_fraction,
                        double alpha_2 = chialvo_sundaresan_scale);

// A member the deck can name (SKT's radial_distribution): g0(φ; φ_c) in double and in Dual.
struct RadialDistribution {
  std::string name;     // deck spelling
  std::string summary;  // its equation, for the key reference
  double (*value)(double phi, double critical_fraction);
  Dual (*dual)(Dual phi, double critical_fraction);
};

// Every member, in the order the deck lists them: carnahan-starling, torquato, mkt (the MKT
// g0 of Eq. 31 with α₂ = 0.58). One table, in radial_distribution.cpp.
const std::vector<RadialDistribution>& radial_distributions();
// The member called `name`; throws UnknownModel (an std::invalid_argument) listing the others.
const RadialDistribution& radial_distribution(const std::string& name);
std::vector<std::string> radial_distribution_names();

template <class Real>
Real evaluate(const RadialDistribution& g0, Real phi, double critical_fraction) {
  if constexpr (std::is_same_v<Real, Dual>)
    return g0.dual(phi, critical_fraction);
  else
    return g0.value(phi, critical_fraction);
}

}  // namespace bagnold::models::rdf
