#pragma once
// The phase fractions at a staggered face, from the cell-centred ε of the two cells beside it
// (the owning cell c and its + neighbour n along d):
//   face_fraction     ε at the face for the momentum equation: linear between the two
//                     centres; at a boundary face, what flows through it (an inlet's own
//                     fraction coming in, the fluid cell's going out: the mean of the two would
//                     feed a bed only half its inflow's gas);
//   carried_fraction  ε carried through the face by continuity: the gas's face_fraction, the
//                     solids' upwind value (c when u_s ≥ 0).
// Below solids_threshold on both sides of a face the solids momentum there is not solved.

#include "solver/discretization.hpp"
#include "solver/simple/iteration_fields.hpp"
#include "src/run/flow_state.hpp"

namespace bagnold::solver {

// ε_s below which a face's solids momentum is not solved (u_s = 0 there): far below any
// fraction that carries momentum (the closures' dilute_cutoff defaults to the same 1e-6), so
// that the solids rows of an empty cell are not solved for a velocity nothing carries.
inline constexpr double solids_threshold = 1e-6;

// Inline, as solids_present: called for every solids momentum row.
inline double face_fraction(const Discretization& discretization, const run::FlowState& state,
                            Phase phase, int local, int d) {
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

// Inline: called for every face several times per outer iteration.
inline double carried_fraction(const Discretization& discretization, const run::FlowState& state,
                               Phase phase, int local, int d) {
  if (phase == gas) return face_fraction(discretization, state, gas, local, d);
  const int n = discretization.layout().neighbour(local, 2 * d + 1);
  const double u = state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
  const int upwind = (u >= 0.0 || n < 0) ? local : n;
  return state.solids_fraction[static_cast<std::size_t>(upwind)];
}
// Whether the solids momentum on the face of `local` along d is solved.
inline bool solids_present(const Discretization& discretization, const run::FlowState& state,
                           int local, int d) {
  const int n = discretization.layout().neighbour(local, 2 * d + 1);
  const auto& eps = state.solids_fraction;
  return eps[static_cast<std::size_t>(local)] > solids_threshold ||
         (n >= 0 && eps[static_cast<std::size_t>(n)] > solids_threshold);
}

// Refreshes carried(phase, d) at every local cell.
void carry_fractions(const Discretization& discretization, const run::FlowState& state, Phase phase,
                     int d, CarriedFractions& carried);
// Every phase and direction.
void carry_all_fractions(const Discretization& discretization, const run::FlowState& state,
                         CarriedFractions& carried);

}  // namespace bagnold::solver
