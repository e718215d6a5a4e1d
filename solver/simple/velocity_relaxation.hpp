#pragma once
// Under-relaxation of a momentum row (numerics.relax_velocity = α, numerics.velocity_relaxation).
//
// A row a_P u_P − Σ a_nb u_nb = b is solved as D u_P − Σ a_nb u_nb = b + (D − a_P) u*, u* the
// iterate, with the relaxed diagonal D:
//
//   diagonal (Patankar 1980, Sec. 6.7; MFIX's UNDER_RELAX_U):  D = a_P / α;
//   local:  D = a_P + (1/α − 1) (a_P − Σ a_nb).
//
// a_P − Σ a_nb is what the row keeps for a layer moving as a plug (inertia, drag, walls, the
// linearized sources): the neighbour links cancel for it. Under "diagonal" a dense viscous
// layer (μ_s ~ 10⁵ Pa s, a_nb ~ 10⁴ × the inertia at 1 ms steps) moves as a plug by about
// α/(1 − α) × (a_P − Σ a_nb)/a_P of its unbalanced force per outer iteration, so a wrong plug
// acceleration decays by a factor close to 1 per iteration; under "local" the relaxation is
// measured against the plug's own terms, as for an inviscid row. Neither changes a converged
// step (u = u* there).

#include <algorithm>

#include "src/deck/choices.hpp"

namespace bagnold::solver {

// D for a row with diagonal a_P = `diagonal` and Σ a_nb = `neighbours`.
inline double relaxed_diagonal(double diagonal, double neighbours, double alpha,
                               deck::VelocityRelaxation kind) {
  if (kind == deck::VelocityRelaxation::diagonal) return diagonal / alpha;
  return diagonal + (1.0 / alpha - 1.0) * std::max(diagonal - neighbours, 0.0);
}

}  // namespace bagnold::solver
