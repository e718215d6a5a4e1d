#pragma once
// The solids-stress interface (DESIGN.md, "Solids-stress interface"): one call evaluates a
// closure over whole arrays of cells, never a virtual call per cell.
//
// Conventions (see ../shared/reference/model-notes.md):
//   strain_rate  γ̇ = sqrt(2 D:D) = 2|D|, with D the symmetric part of ∇u; in simple shear
//                u_x = γ̇ z this returns γ̇.
//   divergence   tr D = ∇·u [1/s].
//   Stresses are compression-positive: σ = P_s I − 2 μ_s S − λ_s tr(D) I, S = D − ⅓ tr(D) I,
//   so the shear stress in simple shear is τ = μ_s γ̇.

#include <span>
#include <string>

#include "models/material.hpp"
#include "models/registry.hpp"

namespace bagnold::models {

struct SolidsState {
  std::span<const double> solids_fraction;  // ε_s = φ [-]
  std::span<const double> strain_rate;      // γ̇ [1/s]
  std::span<const double> divergence;       // tr D [1/s]
};

struct SolidsStress {
  std::span<double> pressure;              // P_s [Pa]
  std::span<double> pressure_derivative;   // dP_s/dε_s [Pa] at fixed strain rate
  std::span<double> shear_viscosity;       // μ_s [Pa s]
  std::span<double> bulk_viscosity;        // λ_s [Pa s]
  std::span<double> granular_temperature;  // Θ [m²/s²]; NaN where the model defines none
};

class SolidsStressModel {
 public:
  virtual ~SolidsStressModel() = default;
  virtual std::string name() const = 0;
  // Evaluates every cell of `in` into `out` (all spans of equal length).
  virtual void evaluate(const Material& material, const SolidsState& in,
                        SolidsStress& out) const = 0;
  // Whether granular_temperature is meaningful (empty column in the rheometer otherwise).
  virtual bool defines_temperature() const = 0;
};

Registry<SolidsStressModel>& stress_registry();

}  // namespace bagnold::models
