// Step 3 of the outer iteration: the solids volume fraction correction (MFIX's ε_s correction).
//
// Solids continuity in each fluid cell P, in volume (ρ_s constant), implicit Euler, upwind:
//     R_P = (ε_P − ε_P^old) V / dt + Σ_faces A ε_up u_out.
// With ε = ε* + ε' and, on every unknown face, u_s = u*_s + e (K_c ε'_c − K_n ε'_n) (e from the
// predictor: the solids velocity's response to a solids-pressure difference; K = dP_s/dε_s of
// each cell, at least 0, so K ε' is the cell's P_s change, as in MFIX's CORRECT_1), the
// linearized equation is
//     V/dt ε'_P + Σ_faces A [ε*_up e (K_P ε'_P − K_nb ε'_nb) + u*_out ε'_up] = −R_P,
// an M-matrix by columns (non-symmetric: BiCGStab + block Jacobi). The e-terms act as a
// diffusion of P_s' = K ε': where the closure stiffens at the packing limit, the correction
// spreads the excess instead of over-packing — this is what keeps dense beds stable without an
// explicit, time-step-limiting solids pressure. Each cell's own K matters where a packed cell
// borders a loose one (the onset of a quasi-static pressure, K jumping by orders of magnitude
// between them): a face mean of K would give the loose cell's ε' the packed cell's stiffness.
// Then ε_s += ε', u_s += e (K_c ε'_c − K_n ε'_n); ε_g = 1 − ε_s.
// The friction response: a dense stress scales with P_s at fixed strain rate, so each face's
// velocity also responds to P_s through its viscous force: u' = e [(1 + w)(K ε')_c − (1 − w)
// (K ε')_n] with w = F_visc / (2 A P_face) from the predictor (momentum_predictor.cpp); the
// rows above take (1 ± w) on the cell's and its neighbour's e-terms (± as the face's side).
// Compression is damped (compression_limit.hpp) and ε_s kept ≥ 0. Outer iterations take the rest.
// Its residual is Σ|R_P| / Σ ½ Σ_faces |A ε_up u| (at least the volume flux of the residual
// velocity scale through every face): the local sums go into IterationSums::continuity[1].
// Under numerics.residual_normalization = "force" it is measured in forces instead, as the
// momentum rows are: the imbalance leaves the cell's fraction wrong by δε = |R_P| dt/V, which
// is a solids pressure error K δε on its faces and a weight error ρ_s V |g| δε, so
//     Σ δε (K A_max + ρ_s V |g|) / Σ ρ_s V (ε |g| + a_min),
// A_max the cell's largest face, a_min SolverSettings::least_acceleration (a cell without
// solids is judged against a full cell accelerating at a_min). Where the bed is packed, K is
// 10⁴–10⁸ Pa and the test asks for the fraction to 10⁻⁸–10⁻¹²: the precision at which P_s, and
// so the momentum balance, is what the iterate says it is.
#include <algorithm>
#include <cmath>

#include "solver/simple/volume_fraction_correction.hpp"

namespace bagnold::solver {

VolumeFractionCorrection::VolumeFractionCorrection(const Discretization& discretization,
                                                   const SolverSettings& settings,
                                                   const Closures& closures)
    : m_discretization(discretization), m_settings(settings), m_limit(discretization, settings, closures) {
  const auto& numbering = discretization.cell_numbering();
  // BiCGStab with block Jacobi (KrylovSettings' defaults): convection makes it non-symmetric.
  const KrylovSettings fraction{.relative_tolerance = linear_relative_tolerance,
                             .absolute_tolerance = linear_absolute_tolerance,
                             .solve_decoupled_rows_directly = true,
                             .default_options = {}};
  m_system = std::make_unique<LinearSystem>(discretization.layout().comm().get(),
                                            discretization.cell_pattern(solids), numbering.first_row, "solids_fraction_", fraction);
  m_x.resize(static_cast<std::size_t>(numbering.owned_rows()));
  m_correction.resize(static_cast<std::size_t>(discretization.layout().local_count()));
}

bool VolumeFractionCorrection::correct(const run::FlowState& old, double dt,
                                       const ClosureFields& closures,
                                       const CorrectionResponse& response,
                                       const CarriedFractions& carried, run::FlowState& state,
                                       IterationSums& sums, WorstCells& worst, StepResult& record) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& numbering = disc.cell_numbering();
  const auto& kind = disc.faces(solids).kind;
  auto& eps = state.solids_fraction;
  const auto& u = state.solids_velocity;
  const auto& e = response.fraction;
  // K ≥ 0 (momentum_predictor.cpp); 0 outside the fluid, where ε' = 0.
  const auto stiffness = [&](int l) {
    return layout.kind(l) == grid::CellKind::fluid
               ? std::max(closures.pressure_derivative[static_cast<std::size_t>(l)], 0.0)
               : 0.0;
  };
  worst.reset(solids_continuity);
  const bool force_norm = m_settings.residual_normalization == ResidualNormalization::force;
  const double rho = m_settings.density[solids], g = m_settings.gravity_magnitude;

  double imbalance = 0.0, throughput = 0.0;
  for (const int l : numbering.owned_locals) {
    const auto ul = static_cast<std::size_t>(l);
    const double v_dt = disc.volume(l) / dt;
    double a_p = v_dt;
    double b = -(eps[ul] - old.solids_fraction[ul]) * v_dt;
    double face_flux = 0.0;
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    for_each_cell_face(disc, l, [&](const CellFace& f) {
      const double eps_up = f.of(carried.value[solids]);
      const double u_face = f.of(u), u_out = f.sign * u_face;
      b -= f.area * eps_up * u_out;
      face_flux += 0.5 * std::abs(f.area * eps_up * u_out);
      if (f.of(kind) != FaceClass::unknown) return;
      // Upwind as carried_fraction decides: the owner when u >= 0.
      const bool upwind_is_l = (u_face >= 0.0) == (f.sign > 0);
      const bool neighbour_free = layout.kind(f.neighbour) == grid::CellKind::fluid;  // boundary ε' = 0
      double off = 0.0;
      const double diffusion = f.area * eps_up * f.of(e);
      const double w = f.sign * f.of(response.friction);
      a_p += diffusion * stiffness(l) * (1.0 + w);
      off -= diffusion * stiffness(f.neighbour) * (1.0 - w);
      if (upwind_is_l) a_p += f.area * std::abs(u_out);
      else off -= f.area * std::abs(u_out);
      if (neighbour_free) {
        columns[count] = numbering.global[static_cast<std::size_t>(f.neighbour)];
        values[count++] = off;
      }
    });
    if (force_norm) {
      const double volume = disc.volume(l), fraction_error = std::abs(b) * dt / volume;
      const double largest_area = std::max({disc.face_area(l, 0), disc.face_area(l, 1), disc.face_area(l, 2)});
      const double force = fraction_error * (stiffness(l) * largest_area + rho * volume * g);
      imbalance += force;
      throughput += rho * volume * (std::max(eps[ul], 0.0) * g + m_settings.least_acceleration);
      worst.record(solids_continuity, force, l);
    } else {
      imbalance += std::abs(b);
      throughput += face_flux;
      worst.record(solids_continuity, std::abs(b), l);
    }
    columns[count] = numbering.global[ul];
    values[count++] = a_p;
    m_system->set_row(numbering.global[ul], columns, values, count, b);
  }
  sums.continuity[1][0] += imbalance;
  sums.continuity[1][1] += throughput;

  std::fill(m_x.begin(), m_x.end(), 0.0);
  const SolveReport report = m_system->solve(m_x);
  record.linear_iterations[fraction_system] += report.iterations;
  std::fill(m_correction.begin(), m_correction.end(), 0.0);
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    m_correction[static_cast<std::size_t>(numbering.owned_locals[row])] = m_x[row];
  m_limit.apply(state, closures, m_correction, sums);
  parallel::exchange_halo<double>(layout, m_correction);
  for (const int l : numbering.owned_locals) eps[static_cast<std::size_t>(l)] += m_correction[static_cast<std::size_t>(l)];
  parallel::exchange_halo<double>(layout, eps);
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    auto& velocity = state.solids_velocity[ud];
    for (const int l : disc.velocity_numbering(d).owned_locals) {
      const int n = layout.neighbour(l, 2 * d + 1);
      const double w = response.friction[ud][static_cast<std::size_t>(l)];
      velocity[static_cast<std::size_t>(l)] +=
          e[ud][static_cast<std::size_t>(l)] *
          ((1.0 + w) * stiffness(l) * m_correction[static_cast<std::size_t>(l)] -
           (1.0 - w) * stiffness(n) * m_correction[static_cast<std::size_t>(n)]);
    }
    parallel::exchange_halo<double>(layout, velocity);
  }
  update_gas_fraction(disc, state);
  if (!report.converged)
    record.failure = "the solids volume fraction correction's linear solve did not converge (" +
                     report.reason + ")";
  return report.converged;
}

void update_gas_fraction(const Discretization& discretization, run::FlowState& state) {
  const auto& layout = discretization.layout();
  for (int l = 0; l < layout.local_count(); ++l)
    if (layout.kind(l) == grid::CellKind::fluid)
      state.gas_fraction[static_cast<std::size_t>(l)] = 1.0 - state.solids_fraction[static_cast<std::size_t>(l)];
}

}  // namespace bagnold::solver
