#pragma once
// The array loop every stress model shares: it checks the spans, takes the strain-rate modulus
// the model is written in (its deviatoric part, or the whole) and hands one cell at a time to
// the model's point function (a non-virtual, inlinable callable), so the interface stays one
// virtual call per array.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "models/stress/solids_stress.hpp"

namespace bagnold::models {

struct PointStress {
  double pressure = 0.0;             // P_s [Pa]
  double pressure_derivative = 0.0;  // dP_s/dε_s [Pa] at fixed strain rate
  double shear_viscosity = 0.0;      // μ_s [Pa s]
  double bulk_viscosity = 0.0;       // λ_s [Pa s]
  double granular_temperature = std::numeric_limits<double>::quiet_NaN();  // T [m²/s²]
};

// Shear rate of the deviatoric strain, γ̇_s = sqrt(2 S:S) = sqrt(γ̇² − ⅔ (tr D)²), with
// γ̇ = sqrt(2 D:D) the interface's strain_rate. It equals γ̇ in simple shear (tr D = 0), and it
// is the rate that does work against a stress of the form τ Ŝ (2 μ_s S:S = μ_s γ̇_s²).
inline double deviatoric_shear_rate(double strain_rate, double divergence) {
  const double squared = strain_rate * strain_rate - (2.0 / 3.0) * divergence * divergence;
  return squared > 0.0 ? std::sqrt(squared) : 0.0;
}

// Which modulus of D a model's shear rate is. In simple shear (tr D = 0) both are γ̇.
enum class RateMeasure {
  deviatoric,  // γ̇_s = sqrt(2 S:S): the kinetic theories, whose production is 2 μ_s S:S
  whole,       // γ̇ = 2|D| = sqrt(2 D:D): App. A Eq. 14, with σ = p(I − η S/|D|) of Eq. 15
};

// Rejects material properties no closure can use (the deck range-checks them too; this guards
// direct callers). Kinetic models need e < 1: their temperature scales as 1/(1 − e²).
inline void require_valid_material(const Material& m, const std::string& model) {
  const bool valid = m.diameter > 0.0 && m.density > 0.0 && m.stiffness > 0.0 &&
                     m.restitution >= 0.0 && m.restitution < 1.0 && m.friction >= 0.0 &&
                     m.bond_number >= 0.0;
  if (!valid)
    throw std::invalid_argument(model +
                                ": material needs d > 0, ρ_s > 0, k > 0, 0 ≤ e < 1, "
                                "μ ≥ 0 and Bo* ≥ 0");
}

// point(φ, rate, tr D) -> PointStress for one cell, rate as `measure` says; φ is clipped below
// at 0 (a solver iterate may undershoot).
template <class PointFunction>
void evaluate_cells(const SolidsState& in, SolidsStress& out, PointFunction&& point,
                    RateMeasure measure = RateMeasure::deviatoric) {
  const std::size_t n = in.solids_fraction.size();
  if (in.strain_rate.size() != n || in.divergence.size() != n || out.pressure.size() != n ||
      out.pressure_derivative.size() != n || out.shear_viscosity.size() != n ||
      out.bulk_viscosity.size() != n || out.granular_temperature.size() != n)
    throw std::invalid_argument("solids stress: input and output arrays differ in length");
  for (std::size_t i = 0; i < n; ++i) {
    const double phi = in.solids_fraction[i] > 0.0 ? in.solids_fraction[i] : 0.0;
    const double divergence = in.divergence[i];
    const double rate = measure == RateMeasure::whole
                            ? in.strain_rate[i]
                            : deviatoric_shear_rate(in.strain_rate[i], divergence);
    const PointStress s = point(phi, rate, divergence);
    out.pressure[i] = s.pressure;
    out.pressure_derivative[i] = s.pressure_derivative;
    out.shear_viscosity[i] = s.shear_viscosity;
    out.bulk_viscosity[i] = s.bulk_viscosity;
    out.granular_temperature[i] = s.granular_temperature;
  }
}

}  // namespace bagnold::models
