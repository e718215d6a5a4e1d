// Phase fractions at staggered faces (face_fractions.hpp).
#include "solver/simple/face_fractions.hpp"

namespace bagnold::solver {

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
