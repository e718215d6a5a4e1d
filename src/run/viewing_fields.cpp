#include "src/run/viewing_fields.hpp"

#include "src/parallel/centre_velocity.hpp"

namespace bagnold::run {

namespace {

// The cell-centred velocity of a staggered field, 3 values per local cell.
void centre_vectors(const parallel::Layout& layout, const std::array<std::vector<double>, 3>& staggered,
                    std::vector<double>& out) {
  const int n = layout.local_count();
  out.assign(3 * static_cast<std::size_t>(n), 0.0);
  for (int l = 0; l < n; ++l)
    for (int d = 0; d < 3; ++d)
      out[3 * static_cast<std::size_t>(l) + static_cast<std::size_t>(d)] =
          parallel::centre_velocity(layout, staggered[static_cast<std::size_t>(d)], l, d);
}

}  // namespace

ViewingFields::ViewingFields(const parallel::Domain& domain) : m_domain(domain) {
  auto& openings = m_data.openings;
  openings.faces = grid::opening_faces(domain.grid, domain.flags, domain.regions);
  for (const auto& region : domain.regions.regions) openings.region_names.push_back(region.name);
  const auto& layout = domain.layout;
  for (std::size_t f = 0; f < openings.faces.size(); ++f) {
    const int l = layout.find(openings.faces[f].owner);
    if (l < 0 || !layout.is_owned(l)) continue;
    openings.owned.push_back(f);
    m_owned_owner.push_back(l);
  }
  openings.fields = {{"gas_velocity", 3, {}, "m/s"},
                     {"solids_velocity", 3, {}, "m/s"},
                     {"gas_outflow_velocity", 1, {}, "m/s"},
                     {"solids_outflow_velocity", 1, {}, "m/s"}};
}

io::IndexedFields ViewingFields::indexed_fields() {
  io::IndexedFields names;
  names.cell_scalars = FlowState::field_names();
  names.cell_vectors = cell_vector_names();
  names.opening_vectors = {"gas_velocity", "solids_velocity"};
  names.opening_scalars = {"gas_outflow_velocity", "solids_outflow_velocity"};
  return names;
}

const io::ViewingData& ViewingFields::of(const FlowState& state) {
  const auto& layout = m_domain.layout;
  centre_vectors(layout, state.gas_velocity, m_gas_centre);
  centre_vectors(layout, state.solids_velocity, m_solids_centre);
  const auto names = cell_vector_names();
  m_data.cell_vectors = {{names[0], m_gas_centre, "m/s"}, {names[1], m_solids_centre, "m/s"}};

  auto& openings = m_data.openings;
  for (auto& field : openings.fields) field.values.clear();
  const std::array<const std::array<std::vector<double>, 3>*, 2> phases = {&state.gas_velocity,
                                                                           &state.solids_velocity};
  for (std::size_t p = 0; p < openings.owned.size(); ++p) {
    const auto& face = openings.faces[openings.owned[p]];
    const auto owner = static_cast<std::size_t>(m_owned_owner[p]);
    for (std::size_t phase = 0; phase < 2; ++phase) {
      const double normal = (*phases[phase])[static_cast<std::size_t>(face.direction)][owner];
      auto& vector = openings.fields[phase].values;
      for (int c = 0; c < 3; ++c) vector.push_back(c == face.direction ? normal : 0.0);
      openings.fields[2 + phase].values.push_back(face.outward_sign * normal);
    }
  }
  return m_data;
}

}  // namespace bagnold::run
