// Step 3 of the outer iteration: the solids volume fraction correction (MFIX's ε_s correction).
//
// Solids continuity in each fluid cell P, in volume (ρ_s constant), implicit Euler, upwind:
//     R_P = (ε_P − ε_P^old) V / dt + Σ_faces A ε_up u_out.
// With ε = ε* + ε' and, on every unknown face, u_s = u*_s + e (ε'_c − ε'_n) (e from the
// predictor: the solids velocity's response to the solids-pressure difference through
// K = dP_s/dε_s), the linearized equation is
//     V/dt ε'_P + Σ_faces A [ε*_up e (ε'_P − ε'_nb) + u*_out ε'_up] = −R_P,
// an M-matrix (non-symmetric: BiCGStab + block Jacobi). The e-terms act as a diffusion of ε' with
// coefficient ε_s K: where the closure stiffens at the packing limit, the correction spreads
// the excess instead of over-packing — this is what keeps dense beds stable without an
// explicit, time-step-limiting solids pressure.
// Then ε_s += ε', u_s += e (ε'_c − ε'_n); ε_g = 1 − ε_s.
// Compression is damped (limit_compression): P_s is convex near packing, so Newton from below
// overshoots into astronomically large pressures; where the closure's P_s at ε* + ε' exceeds
// twice its linear prediction (plus the weight of one cell of packed solids), ε' is halved in
// that cell until it does not. Outer iterations take the rest.
// Once a step has converged, conserve_solids recomputes ε_s from the converged fluxes in
// conservative form, ε_P = ε_P^old − dt/V Σ_faces A ε_up u_out: each face's flux is computed
// once for both sides, so the solids mass changes only through boundaries, to round-off (the
// change to ε_s is of the size of the converged continuity residual).
// Returns Σ|R_P| / Σ ½ Σ_faces |A ε_up u| (at least the volume flux of the residual velocity
// scale through every face).
#include <algorithm>
#include <cmath>

#include "solver/simple/flow_solver.hpp"

namespace bagnold::solver {

double FlowSolver::correct_volume_fraction(run::FlowState& state, const run::FlowState& old,
                                           double dt) {
  const auto& layout = m_domain.layout;
  const auto& numbering = *m_pressure_numbering;
  auto& eps = state.solids_fraction;
  const auto& u = state.solids_velocity;
  m_worst_value[solids_continuity] = 0.0;
  m_worst_local[solids_continuity] = -1;

  auto volume = [&](int l) { return width(l, 0) * width(l, 1) * width(l, 2); };

  double imbalance = 0.0, throughput = 0.0;
  for (const int l : numbering.owned_locals) {
    const auto ul = static_cast<std::size_t>(l);
    const double v_dt = volume(l) / dt;
    double a_p = v_dt;
    double b = -(eps[ul] - old.solids_fraction[ul]) * v_dt;
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    for (int face = 0; face < 6; ++face) {
      const int d = parallel::face_direction(face);
      const auto ud = static_cast<std::size_t>(d);
      const int s = parallel::face_sign(face);
      const int m = layout.neighbour(l, face);
      const int owner = s > 0 ? l : m;
      if (owner < 0) continue;
      const auto uo = static_cast<std::size_t>(owner);
      const double area = face_area(l, d);
      const double eps_up = flux_fraction(state, solids, owner, d);
      const double u_out = s * u[ud][uo];
      b -= area * eps_up * u_out;
      throughput += 0.5 * std::abs(area * eps_up * u_out);
      if (faces(solids).kind[ud][uo] != FaceClass::unknown) continue;
      // Upwind as flux_fraction decides: the owner when u >= 0.
      const bool upwind_is_l = (u[ud][uo] >= 0.0) == (s > 0);
      const bool neighbour_free = layout.kind(m) == grid::CellKind::fluid;  // boundary ε' = 0
      double off = 0.0;
      const double diffusion = area * eps_up * m_e[ud][uo];
      a_p += diffusion;
      off -= diffusion;
      if (upwind_is_l) a_p += area * std::abs(u_out);
      else off -= area * std::abs(u_out);
      if (neighbour_free) {
        columns[count] = numbering.global[static_cast<std::size_t>(m)];
        values[count++] = off;
      }
    }
    imbalance += std::abs(b);
    record_worst(solids_continuity, std::abs(b), l);
    columns[count] = numbering.global[ul];
    values[count++] = a_p;
    m_fraction_system->set_row(numbering.global[ul], columns, values, count, b);
  }

  std::vector<double> x(static_cast<std::size_t>(numbering.owned_rows()), 0.0);
  m_fraction_system->solve(x);
  std::vector<double> correction(static_cast<std::size_t>(layout.local_count()), 0.0);
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    correction[static_cast<std::size_t>(numbering.owned_locals[row])] = x[row];
  limit_compression(state, correction);
  parallel::exchange_halo<double>(layout, correction);
  for (const int l : numbering.owned_locals) eps[static_cast<std::size_t>(l)] += correction[static_cast<std::size_t>(l)];
  parallel::exchange_halo<double>(layout, eps);
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    auto& velocity = state.solids_velocity[ud];
    for (const int l : m_velocity_numbering[ud]->owned_locals) {
      const int n = layout.neighbour(l, 2 * d + 1);
      velocity[static_cast<std::size_t>(l)] += m_e[ud][static_cast<std::size_t>(l)] *
                                               (correction[static_cast<std::size_t>(l)] -
                                                correction[static_cast<std::size_t>(n)]);
    }
    parallel::exchange_halo<double>(layout, velocity);
  }
  update_gas_fraction(state);

  const double total_imbalance = layout.comm().sum(imbalance);
  const double total_throughput =
      std::max(layout.comm().sum(throughput), m_reference_area * m_velocity_scale);
  return total_imbalance <= 1e-300 ? 0.0 : total_imbalance / total_throughput;
}

}  // namespace bagnold::solver

namespace bagnold::solver {

void FlowSolver::limit_compression(const run::FlowState& state, std::vector<double>& correction) {
  const auto& layout = m_domain.layout;
  const auto& eps = state.solids_fraction;
  std::vector<int> cells;  // owned fluid cells that the correction compresses
  for (const int l : m_pressure_numbering->owned_locals) {
    auto& c = correction[static_cast<std::size_t>(l)];
    const double current = eps[static_cast<std::size_t>(l)];
    if (current + c < 0.0) c = -current;  // never below zero
    if (c > 0.0) cells.push_back(l);
  }
  if (cells.empty()) return;
  // The pressure scale below which the linearization need not be trusted: the weight of one
  // cell of packed solids (ρ_s |g| h ε_s, h the smallest cell width, ε_s = 0.6).
  double h = INFINITY;
  for (int d = 0; d < 3; ++d)
    for (int l = 0; l < layout.owned_fluid_count(); ++l) h = std::min(h, width(l, d));
  const double floor = std::max(m_deck.solids.material.density * m_gravity * h * 0.6, 1.0);
  const std::size_t n = cells.size();
  std::vector<double> lambda(n, 1.0), candidate(n), rate(n), divergence(n);
  std::vector<double> pressure(n), derivative(n), shear(n), bulk(n), temperature(n);
  for (std::size_t k = 0; k < n; ++k) {
    rate[k] = state.pressure_shear_rate[static_cast<std::size_t>(cells[k])];  // P_s's rate
    divergence[k] = m_divergence[static_cast<std::size_t>(cells[k])];
  }
  for (int halving = 0; halving < 40; ++halving) {
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(cells[k]);
      candidate[k] = eps[i] + lambda[k] * correction[i];
    }
    models::SolidsStress out{pressure, derivative, shear, bulk, temperature};
    m_stress->evaluate(m_deck.solids.material, {candidate, rate, divergence}, out);
    bool any = false;
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(cells[k]);
      const double predicted = state.solids_pressure[i] +
                               std::max(m_pressure_derivative[i], 0.0) * lambda[k] * correction[i];
      if (!(pressure[k] <= 2.0 * predicted + floor)) {  // NaN fails too
        lambda[k] *= 0.5;
        any = true;
      }
    }
    if (!any) break;
  }
  for (std::size_t k = 0; k < n; ++k) correction[static_cast<std::size_t>(cells[k])] *= lambda[k];
}

void FlowSolver::update_gas_fraction(run::FlowState& state) const {
  const auto& layout = m_domain.layout;
  for (int l = 0; l < layout.local_count(); ++l)
    if (layout.kind(l) == grid::CellKind::fluid)
      state.gas_fraction[static_cast<std::size_t>(l)] = 1.0 - state.solids_fraction[static_cast<std::size_t>(l)];
}

void FlowSolver::conserve_solids(run::FlowState& state, const run::FlowState& old, double dt) {
  const auto& layout = m_domain.layout;
  const auto& numbering = *m_pressure_numbering;
  const auto& u = state.solids_velocity;
  m_stepped_solids_flux = boundary_mass_flux(state, solids);  // collective
  std::vector<double> conserved(numbering.owned_locals.size());
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row) {
    const int l = numbering.owned_locals[row];
    double outflow = 0.0;  // net solids volume outflow; each face's flux as its neighbour sees it
    for (int face = 0; face < 6; ++face) {
      const int d = parallel::face_direction(face);
      const int owner = parallel::face_sign(face) > 0 ? l : layout.neighbour(l, face);
      if (owner < 0) continue;
      outflow += parallel::face_sign(face) * face_area(l, d) * flux_fraction(state, solids, owner, d) *
                 u[static_cast<std::size_t>(d)][static_cast<std::size_t>(owner)];
    }
    const double volume = width(l, 0) * width(l, 1) * width(l, 2);
    conserved[row] = old.solids_fraction[static_cast<std::size_t>(l)] - dt / volume * outflow;
  }
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    state.solids_fraction[static_cast<std::size_t>(numbering.owned_locals[row])] = conserved[row];
  parallel::exchange_halo<double>(layout, state.solids_fraction);
  update_gas_fraction(state);
}

}  // namespace bagnold::solver
