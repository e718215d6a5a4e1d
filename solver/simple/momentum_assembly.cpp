// Step 1a of the outer iteration: the momentum rows of one phase m (gas or solids) for the
// velocity component d, before drag, relaxation and partial elimination (momentum_predictor.cpp).
//
// The stress is the full Newtonian-form tensor of each phase,
//   σ_m = −P I + μ (∇u + ∇uᵀ) + (λ − ⅔ μ)(∇·u) I,
// with μ = ε_g μ_g, λ = 0 for the gas and the closure's μ_s, λ_s for the solids (the gas's P is
// its pressure, times ε_g; the solids' P_s). Its divergence for component d splits into
//   ∂_e(μ ∂_e u_d)   for every e: implicit (the a_nb below), as for a Laplacian;
//   ∂_d(μ ∂_d u_d)   the transpose's normal part: implicit too, by doubling D on the two faces
//                    normal to d (so the normal viscous stress is 2 μ ∂_d u_d);
//   ∂_e(μ ∂_d u_e)   e ≠ d, the transpose's cross part: explicit from the current iterate, at
//                    the CV's edges, with the same edge viscosity as D (MFIX's calc_tau_u_s
//                    does the same; it converges with the outer iteration); the row also
//                    records its terms c u_e, which numerics.solids_momentum = "coupled" moves
//                    into the matrix (coupled_solids_momentum.hpp);
//   ∂_d((λ − ⅔ μ) ∇·u)  explicit from the cell centres' ∇·u (closures.hpp).
// Edge viscosities are the arithmetic means of the cells around them, their harmonic means
// (MFIX's AVG_H, nested over an edge's four cells), or for the solids yield-bounded means
// (numerics.viscosity_average; yield_bounded_mean below); a face normal to d takes its cell's.
//
// For each unknown face velocity u_P (control volume between the centres of its owning cell c
// and c's + neighbour n), and each of its six faces:
//   F   outward mass flux ρ_m ε_m u A through the face, from the current iterate: the mean of
//       the continuity fluxes of the two cell faces it spans (ε_m carried: the gas's linear
//       face value, the solids' upwind value: CarriedFractions);
//   D   μ A / δ, with δ the distance to the neighbour (half a cell to a wall), μ the cell's on a
//       face normal to d (2 μ A/δ: the transpose's normal part) and the edge's (the mean of the
//       four cells around it) on the others; at a solids wall with a partial-slip law
//       (boundary.solids_wall), c_w A instead, with c_w ≤ μ_s/δ from the wall law
//       (solids_wall.hpp);
//   a_nb = D + max(−F, 0),  a_P += a_nb       (first-order upwind, implicit, non-conservative
//       form: the continuity imbalance is subtracted, so a_P = Σ a_nb + transient and the
//       rows stay diagonally dominant while ε_m is still changing within the step);
//   b −= F (φ_f^TVD − φ_upwind)               (TVD by deferred correction);
//   b += s μ_edge (u_e,n − u_e,c) A/δ_d        (the cross part on a face normal to e ≠ d, s = ±1
//       its side, u_e on the edge's two faces of c and n, δ_d the distance between their centres;
//       zero on a wall, where u_e vanishes, at a partial-slip wall, whose law gives the whole wall
//       stress, and at an opening).
// With numerics.shear_on_opening_faces = false an edge with an opening's outside cell among its
// four cells has neither D nor the cross part (MFIX's zero viscosity in flow cells), for both
// phases and every opening (pressure outflow or inflow, mass inflow).
// Sources: ε_m (P_c − P_n) A; for the solids also (P_s,c − P_s,n) A (an outflow cell's P_s as
// its region's solids_pressure says: its fluid neighbour's, or 0; closures.hpp);
// ((λ − ⅔ μ)∇·u)_n − ((λ − ⅔ μ)∇·u)_c) A over the fluid cells (∇·u = 0 beyond them, as an
// outlet's P_s); ε_m ρ_m g_d V; the implicit-Euler term ε_m ρ_m V / dt (u_P − u_P^old); the gas's
// optional manufactured source. row.force sums the magnitudes of the forces among these that act
// on the control volume (the weight ε_m ρ_m |g| V, also kept as row.weight, the pressure and P_s
// forces, the boundary stress a_nb |u_b − u_P| of walls and given velocities, the source, and
// the floor ε_m ρ_m a_min V), which the "force" residual normalization measures against, with
// the drag added by the predictor (momentum_residual.hpp). row.wall_shear is the walls' own
// tangential force on it, D (u_wall − u_P) summed over its faces along a wall (no slip, or a
// partial-slip law's c_w A), which the monitor sums (wall_shear_* columns).
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "solver/simple/face_fractions.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "solver/strain_rate.hpp"

namespace bagnold::solver {

namespace {
// The mean viscosity of two cells (MFIX's AVG_H when harmonic: 0 if both are 0).
// (The yield-bounded mean's pairs, which the Newton tangent takes, are arithmetic.)
double mean_viscosity(deck::ViscosityAverage average, double a, double b) {
  if (average != deck::ViscosityAverage::harmonic) return 0.5 * (a + b);
  const double sum = a + b;
  return sum > 0.0 ? 2.0 * a * b / sum : 0.0;
}

// numerics.viscosity_average = "yield-bounded": the mean of the viscosities μ_c of the cells
// around an edge (or along a wall edge), each taken at the edge's strain rate γ̇_e, the mean of
// the fluid cells' γ̇_c among them, as a plastic stress is (τ independent of the rate): a cell
// that shears slower than the edge gives μ_c γ̇_c/γ̇_e, its stress over the edge's rate, one
// that shears faster its own μ_c. Where the rates are smooth, γ̇_c/γ̇_e → 1 and this is the
// arithmetic mean. Where a rigid cell (μ_c = τ_y/γ̇_c, unbounded as γ̇_c → 0, up to the closure's
// cap) meets flowing ones, the arithmetic mean gives the edge a quarter of the rigid cell's
// viscosity and the flowing cells' shear across it a stress far above any of the cells' yield
// stresses; an edge turning in rigid rotation beside a stagnant corner then becomes a stiff
// constraint that the segregated outer iteration does not converge (docs/solver.md, "What holds
// the bin back under a force test"). The bound keeps the edge's stress within its cells'.
// `rate` gives a cell's γ̇_c for a fluid cell and a negative value for any other (which counts
// with its own viscosity and not in γ̇_e); -1: no cell.
template <class Viscosity, class Rate>
double yield_bounded_mean(std::initializer_list<int> cells, Viscosity viscosity, Rate rate) {
  double rate_sum = 0.0, fluid_cells = 0.0, count = 0.0;
  for (const int c : cells) {
    if (c < 0) continue;
    count += 1.0;
    if (const double own = rate(c); own >= 0.0) rate_sum += own, fluid_cells += 1.0;
  }
  if (count == 0.0) return 0.0;
  const double edge_rate = fluid_cells > 0.0 ? rate_sum / fluid_cells : 0.0;
  double sum = 0.0;
  for (const int c : cells) {
    if (c < 0) continue;
    const double own = rate(c);
    sum += viscosity(c) * (own >= 0.0 && own < edge_rate ? own / edge_rate : 1.0);
  }
  return sum / count;
}
}  // namespace

void assemble_momentum_rows(const MomentumAssemblyInputs& in, Phase phase, int d,
                            const run::FlowState& state, SolidsWallCoefficients* walls,
                            bool refresh_wall_coefficients, std::vector<MomentumRow>& rows,
                            MomentumAssemblyScratch& scratch) {
  const Discretization& disc = in.discretization;
  const auto& layout = disc.layout();
  const auto ud = static_cast<std::size_t>(d);
  const double rho = in.settings.density[phase];
  const Limiter limiter = in.settings.limiter;
  const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
  const auto& u = velocity[ud];
  const auto& u_old = (phase == gas ? in.old.gas_velocity : in.old.solids_velocity)[ud];
  const auto& mu = in.closures.viscosity[phase];
  const auto& links = disc.faces(phase).links[ud];
  const auto& kind = disc.faces(phase).kind[ud];
  const auto& numbering = disc.velocity_numbering(d);
  const auto& carried_d = in.carried(phase, d);
  auto at = [&](int local) { return u[static_cast<std::size_t>(local)]; };
  // The mass flux (per unit area and density) through the face along e that each local cell
  // stores: velocity_e times the fraction carried there. With numerics.copy_fluxes_into_openings
  // a pressure opening's outside cell carries its fluid neighbour's instead (MFIX's
  // SET_OUTFLOW_FLUXES). face_flux gives 0 for no cell.
  const bool copy_into_openings = in.settings.copy_fluxes_into_openings;
  for (int e = 0; e < 3; ++e) {
    const auto& velocity_e = velocity[static_cast<std::size_t>(e)];
    const auto& carried_e = in.carried(phase, e);
    auto& flux = scratch.flux[static_cast<std::size_t>(e)];
    flux.resize(static_cast<std::size_t>(layout.local_count()));
    for (int l = 0; l < layout.local_count(); ++l) {
      const int fluid = copy_into_openings ? disc.pressure_opening_fluid(l) : -1;
      const auto from = static_cast<std::size_t>(fluid >= 0 ? fluid : l);
      flux[static_cast<std::size_t>(l)] = velocity_e[from] * carried_e[from];
    }
  }
  auto face_flux = [&scratch](int e, int local) {
    return local >= 0 ? scratch.flux[static_cast<std::size_t>(e)][static_cast<std::size_t>(local)] : 0.0;
  };
  auto viscosity = [&](int local) { return local >= 0 ? mu[static_cast<std::size_t>(local)] : 0.0; };
  const deck::ViscosityAverage average = in.settings.viscosity_average;
  auto mean = [average](double a, double b) { return mean_viscosity(average, a, b); };
  const bool yield_bounded = phase == solids && average == deck::ViscosityAverage::yield_bounded;
  const auto& rate = in.closures.strain_rate;
  auto fluid_rate = [&](int local) {
    return layout.kind(local) == grid::CellKind::fluid ? rate[static_cast<std::size_t>(local)] : -1.0;
  };
  auto bounded = [&](std::initializer_list<int> cells) { return yield_bounded_mean(cells, viscosity, fluid_rate); };
  // Once per cell: the mean viscosity of each local cell and its + neighbour along d (the cell's
  // own without one), which a wall face takes for its row and an edge averages over the two rows
  // beside it; or, yield-bounded, each edge's viscosity from its four cells, stored at the lower
  // pair along e, so the rows above and below the edge take the same value.
  // Per local cell, the mean of `value` over the cell and its + neighbour along d (the cell's own
  // without one).
  auto fill_pair_means = [&](std::vector<double>& pair, auto&& value) {
    pair.resize(static_cast<std::size_t>(layout.local_count()));
    for (int l = 0; l < layout.local_count(); ++l) {
      const int n = layout.neighbour(l, 2 * d + 1);
      pair[static_cast<std::size_t>(l)] = n >= 0 ? mean(value(l), value(n)) : value(l);
    }
  };
  auto& pair_viscosity = scratch.secant;
  if (yield_bounded) {
    for (int e = 0; e < 3; ++e) {
      if (e == d) continue;
      auto& edge = scratch.bounded_edge[static_cast<std::size_t>(e)];
      edge.resize(static_cast<std::size_t>(layout.local_count()));
      for (int l = 0; l < layout.local_count(); ++l) {
        const int m = layout.neighbour(l, 2 * e + 1);
        edge[static_cast<std::size_t>(l)] = bounded({l, layout.neighbour(l, 2 * d + 1), m,
                                                     m >= 0 ? layout.neighbour(m, 2 * d + 1) : -1});
      }
    }
  } else {
    fill_pair_means(pair_viscosity, viscosity);
  }
  // numerics.shear_on_opening_faces = false: an edge with an opening's outside cell among its
  // four cells (c, n and their neighbours across the face) shears nothing, as MFIX's zero
  // viscosity in flow-boundary cells (SET_EPMUS_VALUES) makes its harmonic edge means.
  auto unsheared_edge = [&](int c, int n, int face) {
    return !in.settings.shear_on_opening_faces &&
           (disc.opening(c) || disc.opening(n) || disc.opening(layout.neighbour(c, face)) ||
            (n >= 0 && disc.opening(layout.neighbour(n, face))));
  };
  // Newton: the implicit part of each face's viscous coefficient is the tangent's, μ_s f_de
  // (ClosureFields::tangent_factor); the rest, (D − D_t)(u_nb − u_P), acts on the iterate.
  const auto& factors = in.closures.tangent_factor;
  const bool newton = phase == solids && !factors[0].empty();
  auto tangent_factor = [&](int local, int e) {
    return factors[static_cast<std::size_t>(symmetric_component(d, e))][static_cast<std::size_t>(local)];
  };
  auto tangent_viscosity = [&](int local, int e) { return local >= 0 ? viscosity(local) * tangent_factor(local, e) : 0.0; };
  if (newton)
    for (int e = 0; e < 3; ++e)
      if (e != d)
        fill_pair_means(scratch.tangent[static_cast<std::size_t>(e)], [&](int c) { return tangent_viscosity(c, e); });

  rows.resize(numbering.owned_locals.size());
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    MomentumRow& row = rows[r];
    row.reset();
    const int l = numbering.owned_locals[r];
    const int n = layout.neighbour(l, 2 * d + 1);
    const double half_c = 0.5 * disc.width(l, d), half_n = 0.5 * disc.width(n, d);
    row.area = disc.face_area(l, d);
    row.volume = (half_c + half_n) * row.area;
    // The gas carries its face fraction (carried_fraction), already evaluated for this iterate.
    row.fraction = phase == gas ? carried_d[static_cast<std::size_t>(l)] : face_fraction(disc, state, phase, l, d);
    if (phase == solids && !solids_present(disc, state, l, d)) {
      // Not solved (u_s = 0): the row keeps its pattern, with zero off-diagonal entries.
      for (int face = 0; face < 6; ++face) {
        const Link& link = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face)];
        if (link.kind != LinkKind::unknown) continue;
        row.columns[row.count] = numbering.global[static_cast<std::size_t>(link.local)];
        row.values[row.count++] = 0.0;
      }
      row.active = false;
      continue;
    }

    for (int face = 0; face < 6; ++face) {
      const Link& link = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face)];
      const int e = parallel::face_direction(face);
      const int s = parallel::face_sign(face);
      double flux_out = 0.0, diffusion = 0.0, tangent = 0.0;
      if (e == d) {
        // The control-volume face at the centre of n (s > 0) or of c (s < 0).
        // Its mass flux is the mean of the continuity fluxes through the two cell faces it lies
        // between (ε_m carried as continuity carries it), so momentum is convected only where
        // mass is: an empty cell above a bed's free surface brings the face below none.
        const bool has_far = link.kind == LinkKind::unknown || link.kind == LinkKind::fixed;
        const int centre = s > 0 ? n : l;
        const double own = face_flux(d, l);
        const double far = has_far ? face_flux(d, link.local) : own;
        flux_out = s * rho * row.area * 0.5 * (own + far);
        diffusion = has_far ? 2.0 * viscosity(centre) * row.area / disc.width(centre, d) : 0.0;
        if (newton && has_far) tangent = diffusion * tangent_factor(centre, d);
      } else {
        // The face between the owning cells' faces along e: half of c's and half of n's.
        const int t = 3 - d - e;
        const auto& v = velocity[static_cast<std::size_t>(e)];
        const int cv = s > 0 ? l : layout.neighbour(l, face);
        const int nv = s > 0 ? n : layout.neighbour(n, face);
        // u_e on the e-faces of c and n on this side (0 where not stored), and their mass fluxes.
        const double uc_e = cv >= 0 ? v[static_cast<std::size_t>(cv)] : 0.0;
        const double un_e = nv >= 0 ? v[static_cast<std::size_t>(nv)] : 0.0;
        const double vc = face_flux(e, cv), vn = face_flux(e, nv);
        flux_out = s * rho * (vc * half_c + vn * half_n) * disc.width(l, t);
        const double area = (half_c + half_n) * disc.width(l, t);
        if (unsheared_edge(l, n, face)) {
          // No shear on this face (numerics.shear_on_opening_faces); convection as elsewhere.
        } else if (link.kind == LinkKind::wall) {
          // No slip: μ A/δ. A solids partial-slip wall: c_w A, c_w ≤ μ_s/δ (solids_wall.hpp).
          if (phase == solids && walls && walls->partial(link)) {
            diffusion = walls->coefficient(disc, state, in.closures, link, l, d, face,
                                           refresh_wall_coefficients) * area;
            tangent = diffusion;
          } else {
            const double wall_distance = 0.5 * disc.width(l, e);
            diffusion = (yield_bounded ? bounded({l, n}) : pair_viscosity[static_cast<std::size_t>(l)]) * area /
                        wall_distance;
            if (newton) tangent = scratch.tangent[static_cast<std::size_t>(e)][static_cast<std::size_t>(l)] * area / wall_distance;
          }
        } else if (link.kind != LinkKind::zero_gradient) {
          // The edge between c, n and their neighbours m, m' across the face.
          const int m = link.local;
          const double edge_mu =
              yield_bounded ? scratch.bounded_edge[static_cast<std::size_t>(e)][static_cast<std::size_t>(s > 0 ? l : m)]
                            : mean(pair_viscosity[static_cast<std::size_t>(l)], pair_viscosity[static_cast<std::size_t>(m)]);
          diffusion = edge_mu * area / (0.5 * (disc.width(l, e) + disc.width(m, e)));
          if (newton) {
            const auto& pair = scratch.tangent[static_cast<std::size_t>(e)];
            tangent = mean(pair[static_cast<std::size_t>(l)], pair[static_cast<std::size_t>(m)]) * area /
                      (0.5 * (disc.width(l, e) + disc.width(m, e)));
          }
          // The transpose's cross part μ ∂_d u_e on this face: ∂_d u_e from uc_e and un_e,
          // δ_d = half_c + half_n apart (so A/δ_d = width along t).
          row.b += s * edge_mu * (un_e - uc_e) * disc.width(l, t);
          row.viscous += s * edge_mu * (un_e - uc_e) * disc.width(l, t);
          const double cross = s * edge_mu * disc.width(l, t);
          for (const auto& [cell, sign] : {std::pair{nv, 1.0}, std::pair{cv, -1.0}})
            if (cell >= 0) {
              row.cross_cell[row.cross_count] = cell;
              row.cross_component[row.cross_count] = e;
              row.cross_coefficient[row.cross_count++] = sign * cross;
            }
        }
      }
      // What the row holds implicitly; under Newton the rest, (D − D_t), acts on the iterate.
      const double implicit = newton ? tangent : diffusion;
      switch (link.kind) {
        case LinkKind::unknown: {
          const double a_nb = implicit + std::max(-flux_out, 0.0);
          if (newton) row.b += (diffusion - tangent) * (at(link.local) - at(l));
          row.a += a_nb;
          row.columns[row.count] = numbering.global[static_cast<std::size_t>(link.local)];
          row.values[row.count++] = -a_nb;
          row.neighbours_u += a_nb * at(link.local);
          row.viscous += diffusion * (at(link.local) - at(l));
          row.neighbours_a += a_nb;
          if (limiter != Limiter::upwind) {
            double upwind_upwind, upwind, downwind;
            if (flux_out > 0.0) {
              const Link& back = links[6 * static_cast<std::size_t>(l) + static_cast<std::size_t>(face ^ 1)];
              upwind = at(l);
              downwind = at(link.local);
              upwind_upwind = back.kind == LinkKind::wall ? back.value
                              : back.kind == LinkKind::zero_gradient ? at(l) : at(back.local);
            } else {
              const int beyond = layout.neighbour(link.local, face);
              upwind = at(link.local);
              downwind = at(l);
              upwind_upwind = (beyond >= 0 && kind[static_cast<std::size_t>(beyond)] != FaceClass::none)
                                  ? at(beyond) : upwind;
            }
            row.b -= flux_out * tvd_correction(limiter, upwind_upwind, upwind, downwind);
          }
          break;
        }
        case LinkKind::fixed:
        case LinkKind::wall: {
          const double value = link.kind == LinkKind::fixed ? at(link.local) : link.value;
          const double convective = std::max(-flux_out, 0.0);
          const double a_nb = implicit + convective;
          row.a += a_nb;
          row.b += a_nb * value;
          if (newton) row.b += (diffusion - tangent) * (value - at(l));
          row.force += (diffusion + convective) * std::abs(value - at(l));  // the whole wall stress
          if (link.kind == LinkKind::wall && e != d) row.wall_shear += diffusion * (value - at(l));
          row.viscous += diffusion * (value - at(l));
          break;
        }
        case LinkKind::zero_gradient:
          // Open end: inflow brings u_P in, lagged (cancels at convergence).
          row.a += std::max(-flux_out, 0.0);
          row.b += std::max(-flux_out, 0.0) * at(l);
          break;
      }
    }

    const auto uc = static_cast<std::size_t>(l), un = static_cast<std::size_t>(n);
    // The forces that act, also summed as magnitudes for the residual (momentum_residual.hpp).
    auto act = [&row](double force) {
      row.b += force;
      row.force += std::abs(force);
    };
    if (phase == gas || in.settings.moves[gas])
      act(row.fraction * (state.gas_pressure[uc] - state.gas_pressure[un]) * row.area);
    if (phase == solids) act((state.solids_pressure[uc] - state.solids_pressure[un]) * row.area);
    // The dilatational stress (λ − ⅔ μ) ∇·u, explicit like P_s, over the fluid cells only.
    const auto& divergence = in.closures.divergence[phase];
    auto dilatational = [&](int cell) {
      if (layout.kind(cell) != grid::CellKind::fluid) return 0.0;
      const auto i = static_cast<std::size_t>(cell);
      const double lambda = phase == solids ? in.closures.bulk_viscosity[i] : 0.0;
      return (lambda - (2.0 / 3.0) * mu[i]) * divergence[i];
    };
    row.b += (dilatational(n) - dilatational(l)) * row.area;
    row.b += row.fraction * rho * in.settings.gravity[ud] * row.volume;
    row.weight = row.fraction * rho * in.settings.gravity_magnitude * row.volume;
    row.force += row.weight + row.fraction * rho * in.settings.least_acceleration * row.volume;
    if (phase == gas && !in.gas_source[ud].empty()) act(in.gas_source[ud][uc] * row.volume);
    const double a_transient = row.fraction * rho * row.volume / in.dt;
    row.a += a_transient;
    row.transient = a_transient;
    row.b += a_transient * u_old[uc];
  }
}

}  // namespace bagnold::solver
