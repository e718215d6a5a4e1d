#pragma once
// The rheometer: a stress model under steady homogeneous simple shear u_x = γ̇ z (tr D = 0),
// the setting in which the report presents every closure (DESIGN.md, "Solids-stress
// interface"). The `bagnold rheometer` command and the unit tests are built on it.

#include <ostream>
#include <string>
#include <vector>

#include "models/material.hpp"
#include "models/stress/solids_stress.hpp"

namespace bagnold::models {

// One state point. SI units; NaN marks a quantity that is undefined there (no temperature in a
// model without one; stress ratio and inertial number where the pressure vanishes).
struct RheometerRow {
  std::string model;
  double phi;                   // φ [-]
  double shear_rate;            // γ̇ [1/s]
  double pressure;              // P_s [Pa]
  double shear_stress;          // τ = μ_s γ̇ [Pa], with the model's viscosity regularization
  double stress_ratio;          // η = τ/P_s [-]
  double granular_temperature;  // T [m²/s²]
  double inertial_number;       // I = γ̇ d / sqrt(P_s/ρ_s) [-]
};

// One point.
RheometerRow shear_rheometer(const SolidsStressModel& model, const Material& material, double phi,
                             double shear_rate);

// Every combination, φ outermost, evaluated in one call to the model.
std::vector<RheometerRow> shear_rheometer(const SolidsStressModel& model, const Material& material,
                                          const std::vector<double>& phis,
                                          const std::vector<double>& shear_rates);

// CSV with the header
//   model,phi,shear_rate,pressure,shear_stress,stress_ratio,granular_temperature,inertial_number
// (when `header`), an empty field for NaN, numbers as %.10g.
void write_rheometer_csv(std::ostream& out, const std::vector<RheometerRow>& rows, bool header);

}  // namespace bagnold::models
