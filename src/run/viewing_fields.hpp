#pragma once
// What a snapshot carries only to be looked at (docs/output.md, "For viewing"), derived from a
// flow state and never read back:
//   gas_velocity, solids_velocity      each phase's velocity at the cell centres, 3 components,
//                                      the face-to-centre average of the staggered components
//                                      (parallel::centre_velocity, the solver's own);
//   on the opening faces               each phase's face velocity as a vector along the face
//                                      normal (the tangential components are not stored on a
//                                      face: 0), and its component along the outward normal,
//                                      PHASE_outflow_velocity (> 0 leaving the domain).

#include <vector>

#include "src/io/snapshot.hpp"
#include "src/io/xdmf.hpp"
#include "src/parallel/domain.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::run {

class ViewingFields {
 public:
  // Finds the opening faces (the same on every rank) and the ones this rank owns.
  explicit ViewingFields(const parallel::Domain& domain);

  // The viewing data of `state`; its views point into this object, valid until the next call.
  const io::ViewingData& of(const FlowState& state);

  // Where the names are stored, for the XDMF index.
  static io::IndexedFields indexed_fields();
  // The names of the cell vectors (in /fields, with the fields).
  static std::vector<std::string> cell_vector_names() { return {"gas_velocity", "solids_velocity"}; }
  // How many opening faces a snapshot holds, and how many values each carries.
  std::size_t opening_face_count() const { return m_data.openings.faces.size(); }
  static std::size_t opening_values_per_face() { return 8; }

 private:
  const parallel::Domain& m_domain;
  std::vector<int> m_owned_owner;  // local index of each owned opening face's owner cell
  std::vector<double> m_gas_centre, m_solids_centre;  // 3 per local cell
  io::ViewingData m_data;
};

}  // namespace bagnold::run
