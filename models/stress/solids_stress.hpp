#pragma once
// The solids-stress interface (DESIGN.md, "Solids-stress interface"): one call evaluates a
// closure over whole arrays of cells, never a virtual call per cell.
//
// Conventions (docs/models.md):
//   strain_rate  γ̇ = sqrt(2 D:D) = 2|D|, with D the symmetric part of ∇u; in simple shear
//                u_x = γ̇ z this returns γ̇.
//   divergence   tr D = ∇·u [1/s].
//   Stresses are compression-positive: σ = P_s I − 2 μ_s S − λ_s tr(D) I, S = D − ⅓ tr(D) I,
//   so the shear stress in simple shear is τ = μ_s γ̇.
//
// Besides the stresses a closure reports two properties the wall laws need (models/wall/):
//   packing_limit            φ_max [-], the closure's packing limit for a material: 1 − ε_g*
//                            for the plastic-pressure closures (MFIX EP_STAR), φ_c(μ) of App. A
//                            Table I for the others (the jamming point the kinetic models cap
//                            g0 below, and the rheology's critical fraction).
//   wall_radial_distribution g0 [-] for the Johnson–Jackson wall (Johnson & Jackson 1987, as
//                            MFIX's and OpenFOAM's JohnsonJacksonParticleSlip): Carnahan–Starling
//                            (App. B Eq. 11) at φ clamped to [0, φ_max − wall_jamming_margin].

#include <span>
#include <string>

#include "models/material.hpp"
#include "models/registry.hpp"
#include "models/stress/granular_energy.hpp"

namespace bagnold::models {

// How far below φ_max the wall g0 is evaluated at most. Carnahan–Starling is finite up to φ = 1,
// but a solver iterate can be compressed past φ_max, and the wall's collision factor should then
// stay that of a dense, unjammed packing; 0.01 is also the kinetic models' default jamming
// margin δ (dense_limit.hpp), below φ_c where their own g0 stops growing.
inline constexpr double wall_jamming_margin = 0.01;

struct SolidsState {
  std::span<const double> solids_fraction;  // ε_s = φ [-]
  std::span<const double> strain_rate;      // γ̇ [1/s]
  std::span<const double> divergence;       // tr D [1/s]
  // With a transported granular temperature (granular_energy() not null): Θ [m²/s²] and the
  // drag β [kg/(m³ s)] per cell, and granular_temperature returns Θ. Empty: the algebraic
  // balance gives Θ.
  std::span<const double> temperature = {};
  std::span<const double> drag = {};
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
  // φ_max [-] for `material` (see the top of this file).
  virtual double packing_limit(const Material& material) const = 0;
  // g0 [-] the wall laws use at solids fraction φ; by default Carnahan–Starling at
  // min(max(φ, 0), max(φ_max − wall_jamming_margin, 0)).
  virtual double wall_radial_distribution(const Material& material, double solids_fraction) const;
  // The transport coefficients of the granular energy equation (granular_energy.hpp) when the
  // deck chose the transported Θ (the closure's key granular_energy = "transport"); null when
  // the closure's Θ is algebraic.
  virtual const GranularEnergyTheory* granular_energy() const { return nullptr; }
};

Registry<SolidsStressModel>& stress_registry();

}  // namespace bagnold::models
