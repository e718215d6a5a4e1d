#include "src/run/flow_state.hpp"

#include <cmath>

namespace bagnold::run {

namespace {
constexpr std::size_t cell_field_count = 6;  // the fields before the velocities
const io::Centering face_of[3] = {io::Centering::x_face, io::Centering::y_face,
                                  io::Centering::z_face};
const char* const axis_suffix[3] = {"_x", "_y", "_z"};
}  // namespace

FlowState::FlowState(int local_count) {
  for (auto* f : fields()) f->assign(static_cast<std::size_t>(local_count), 0.0);
  gas_fraction.assign(static_cast<std::size_t>(local_count), 1.0);
  pressure_shear_rate.assign(static_cast<std::size_t>(local_count), std::nan(""));
}

std::vector<std::string> FlowState::field_names() {
  std::vector<std::string> names = {"solids_fraction", "gas_fraction", "gas_pressure",
                                    "solids_pressure", "granular_temperature",
                                    "pressure_shear_rate"};
  for (int d = 0; d < 3; ++d) names.push_back(std::string("gas_velocity") + axis_suffix[d]);
  for (int d = 0; d < 3; ++d) names.push_back(std::string("solids_velocity") + axis_suffix[d]);
  return names;
}

// Every field in snapshot order, as pointers to mutable or const vectors.
template <class Pointer, class State>
std::vector<Pointer> all_fields(State& s) {
  std::vector<Pointer> out = {&s.solids_fraction, &s.gas_fraction, &s.gas_pressure,
                              &s.solids_pressure, &s.granular_temperature, &s.pressure_shear_rate};
  for (auto& v : s.gas_velocity) out.push_back(&v);
  for (auto& v : s.solids_velocity) out.push_back(&v);
  return out;
}

std::vector<std::vector<double>*> FlowState::fields() {
  return all_fields<std::vector<double>*>(*this);
}

std::vector<const std::vector<double>*> FlowState::fields() const {
  return all_fields<const std::vector<double>*>(*this);
}

namespace {
// The SI units of a snapshot field, by name (docs/output.md).
std::string units_of(const std::string& name) {
  if (name.find("velocity") != std::string::npos) return "m/s";
  if (name.find("pressure_shear_rate") != std::string::npos) return "1/s";
  if (name.find("pressure") != std::string::npos) return "Pa";
  if (name == "granular_temperature") return "m^2/s^2";
  return "1";  // the volume fractions
}
}  // namespace

std::vector<io::FieldView> FlowState::views() const {
  const auto names = field_names();
  const auto all = fields();
  std::vector<io::FieldView> out;
  for (std::size_t f = 0; f < all.size(); ++f) {
    io::Centering centering = io::Centering::cell;
    if (f >= cell_field_count) centering = face_of[(f - cell_field_count) % 3];
    out.push_back({names[f], centering, *all[f], units_of(names[f])});
  }
  return out;
}

}  // namespace bagnold::run
