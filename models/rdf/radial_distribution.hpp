#pragma once
// Radial distribution functions at contact g0(φ), one file per member. Each is a template over
// the scalar type (double, or Dual for dg0/dφ) with explicit instantiations in its .cpp.
// Callers keep φ below the divergence (φ_c for Torquato and Chialvo–Sundaresan); the stress
// models do so with their jamming margin (docs/models.md, "At and above φ_c").

#include <string>
#include <vector>

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

// App. B Eq. 31 (MKT): g0 = g0_CS + α₂ φ²/(φ_c(μ) − φ)^{3/2}, α₂ = 0.58 (App. B Table II).
template <class Real>
Real chialvo_sundaresan(Real phi, double critical_fraction, double alpha_2 = 0.58);

enum class Kind { carnahan_starling, torquato, chialvo_sundaresan };

// Deck spellings: "carnahan-starling", "torquato", "mkt" (the MKT g0 of Eq. 31).
Kind kind_from_name(const std::string& name);
const std::vector<std::string>& kind_names();

template <class Real>
Real evaluate(Kind kind, Real phi, double critical_fraction) {
  switch (kind) {
    case Kind::torquato:
      return torquato(phi, critical_fraction);
    case Kind::chialvo_sundaresan:
      return chialvo_sundaresan(phi, critical_fraction);
    case Kind::carnahan_starling:
      break;
  }
  return carnahan_starling(phi);
}

}  // namespace bagnold::models::rdf
