// Phase fractions at staggered faces (face_fractions.hpp).
#include "solver/simple/face_fractions.hpp"

namespace bagnold::solver {

double carried_fraction(const Discretization& discretization, const run::FlowState& state,
                        Phase phase, int local, int d) {
  if (phase == gas) return face_fraction(discretization, state, gas, local, d);
  const int n = discretization.layout().neighbour(local, 2 * d + 1);
  const double u = state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
  const int upwind = (u >= 0.0 || n < 0) ? local : n;
  return state.solids_fraction[static_cast<std::size_t>(upwind)];
}

void carry_fractions(const Discretization& discretization, const run::FlowState& state, Phase phase,
                     int d, CarriedFractions& carried) {
  auto& out = carried.value[static_cast<std::size_t>(phase)][static_cast<std::size_t>(d)];
  const int local = discretization.layout().local_count();
  for (int l = 0; l < local; ++l)
    out[static_cast<std::size_t>(l)] = carried_fraction(discretization, state, phase, l, d);
}

void carry_all_fractions(const Discretization& discretization, const run::FlowState& state,
                         CarriedFractions& carried) {
  for (const Phase phase : {gas, solids})
    for (int d = 0; d < 3; ++d) carry_fractions(discretization, state, phase, d, carried);
}

}  // namespace bagnold::solver
