// Phase fractions at staggered faces (face_fractions.hpp).
#include "solver/simple/face_fractions.hpp"

namespace bagnold::solver {

double face_fraction(const Discretization& discretization, const run::FlowState& state, Phase phase,
                     int local, int d) {
  const auto& layout = discretization.layout();
  const auto& eps = phase == gas ? state.gas_fraction : state.solids_fraction;
  const int n = layout.neighbour(local, 2 * d + 1);
  if (n < 0) return eps[static_cast<std::size_t>(local)];
  if (layout.kind(local) == grid::CellKind::boundary || layout.kind(n) == grid::CellKind::boundary) {
    const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    const double u = velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
    const bool local_is_fluid = layout.kind(local) != grid::CellKind::boundary;
    const bool from_local = u > 0.0 || (u == 0.0 && local_is_fluid);
    return eps[static_cast<std::size_t>(from_local ? local : n)];
  }
  const double wc = discretization.width(local, d), wn = discretization.width(n, d);
  return (eps[static_cast<std::size_t>(local)] * wn + eps[static_cast<std::size_t>(n)] * wc) / (wc + wn);
}

double carried_fraction(const Discretization& discretization, const run::FlowState& state,
                        Phase phase, int local, int d) {
  if (phase == gas) return face_fraction(discretization, state, gas, local, d);
  const int n = discretization.layout().neighbour(local, 2 * d + 1);
  const double u = state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
  const int upwind = (u >= 0.0 || n < 0) ? local : n;
  return state.solids_fraction[static_cast<std::size_t>(upwind)];
}

bool solids_present(const Discretization& discretization, const run::FlowState& state, int local, int d) {
  const int n = discretization.layout().neighbour(local, 2 * d + 1);
  const auto& eps = state.solids_fraction;
  return eps[static_cast<std::size_t>(local)] > solids_threshold ||
         (n >= 0 && eps[static_cast<std::size_t>(n)] > solids_threshold);
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
