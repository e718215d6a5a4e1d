#pragma once
// The fields of a two-fluid run on one rank: every field has layout.local_count() entries
// (owned cells, then halo), indexed by the owning cell. Velocities are staggered: component d
// of a phase velocity lives on the face of the cell in the + direction d (east, north, top).

#include <array>
#include <string>
#include <vector>

#include "src/io/snapshot.hpp"
#include "src/parallel/layout.hpp"

namespace bagnold::run {

struct FlowState {
  explicit FlowState(int local_count);

  std::vector<double> solids_fraction;          // ε_s [-]
  std::vector<double> gas_fraction;             // ε_g = 1 − ε_s [-]
  std::vector<double> gas_pressure;             // P_g [Pa]
  std::vector<double> solids_pressure;          // P_s [Pa]
  std::vector<double> granular_temperature;     // Θ [m²/s²]
  // γ̇_P [1/s]: the strain rate sqrt(2 D:D) the closure's P_s was evaluated at (the current one,
  // or relaxed towards it over numerics.pressure_shear_rate_relaxation_time). NaN: not yet evaluated.
  std::vector<double> pressure_shear_rate;
  std::array<std::vector<double>, 3> gas_velocity;     // U_g, V_g, W_g [m/s] on +x, +y, +z faces
  std::array<std::vector<double>, 3> solids_velocity;  // U_s, V_s, W_s [m/s]

  // Every field, named as in the snapshots (docs/output.md).
  std::vector<io::FieldView> views() const;
  // The same fields, in the same order (writable ones for restart).
  std::vector<std::vector<double>*> fields();
  std::vector<const std::vector<double>*> fields() const;
  static std::vector<std::string> field_names();
  // Of those, the ones a snapshot may lack (added after format_version 1 was fixed): a restart
  // leaves them unset (NaN).
  static std::vector<std::string> optional_field_names() { return {"pressure_shear_rate"}; }
};

}  // namespace bagnold::run
