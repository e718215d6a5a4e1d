#pragma once
// The coefficients a kinetic theory gives the granular energy transport equation
// (solver/simple/granular_energy_equation.hpp), at the transported granular temperature Θ:
//   (3/2)[∂(ε_s ρ_s Θ)/∂t + ∇·(ε_s ρ_s u_s Θ)]
//       = −P_s tr D + 2 μ_s S:S + λ_s (tr D)² + ∇·(κ_s ∇Θ) − Γ − 3 β Θ + S_slip,
// with P_s, μ_s, λ_s the kinetic (collisional and streaming) parts of the stress only: the
// frictional and plastic stresses do no work on the particles' velocity fluctuations, as in
// MFIX's SOURCE_GRANULAR_ENERGY (source_granular_energy.f). Γ = c Θ^{3/2} is the collisional
// dissipation, S_slip the production by gas–particle slip where the theory has one.
// A model offers this through SolidsStressModel::granular_energy(); its evaluate() then takes
// Θ and β as inputs (SolidsState::temperature, ::drag) instead of an algebraic balance.

#include <span>
#include <string>

#include "models/material.hpp"

namespace bagnold::models {

struct KineticInput {
  std::span<const double> solids_fraction;  // ε_s = φ [-]
  std::span<const double> temperature;      // Θ [m²/s²], ≥ 0
  std::span<const double> drag;             // β [kg/(m³ s)] (0 without gas)
  std::span<const double> slip_speed;       // |u_g − u_s| at the centre [m/s]
  double gas_viscosity = 0.0;               // μ_g [Pa s] (0 without gas)
};

struct KineticTerms {
  std::span<double> pressure_per_temperature;  // P_s/Θ [kg/m³] (P_s is linear in Θ)
  std::span<double> shear_viscosity;           // μ_s [Pa s] at Θ
  std::span<double> bulk_viscosity;            // λ_s [Pa s] at Θ (MFIX's λ + ⅔ μ)
  std::span<double> conductivity;              // κ_s [kg/(m s)] at Θ
  std::span<double> dissipation_coefficient;   // c [kg s/m⁵]: Γ = c Θ^{3/2} [W/m³]
  std::span<double> slip_production;           // S_slip [W/m³] at Θ
  std::span<double> held;                      // 1 where the theory holds Θ = 0, else 0
};

class GranularEnergyTheory {
 public:
  virtual ~GranularEnergyTheory() = default;
  virtual std::string name() const = 0;
  // Every cell of `in` into `out` (all spans of equal length).
  virtual void evaluate(const Material& material, const KineticInput& in, KineticTerms& out) const = 0;
};

}  // namespace bagnold::models
