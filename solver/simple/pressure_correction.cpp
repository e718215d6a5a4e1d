// Step 2 of the outer iteration: the pressure correction from the mixture volume continuity.
//
// Both phases are incompressible and ε_g + ε_s = 1, so the sum of their continuity equations is
// ∇·(ε_g u_g + ε_s u_s) = 0 (the transient terms cancel). With, on every unknown face,
// u_m = u*_m + d_m (p'_c − p'_n) (d_m from the predictors' 2 × 2 drag-coupled response) and
// p' = 0 in pressure-boundary cells, continuity in each fluid cell P becomes
//     Σ_faces A (ε_g d_g + ε_s d_s) (p'_P − p'_nb) = −Σ_faces A (ε_g u*_g + ε_s u*_s)_out,
// with ε_m the fractions the phases carry through the face (CarriedFractions): symmetric positive
// (semi-)definite, CG with algebraic multigrid (GAMG or BoomerAMG); a closed domain has the
// constant null space, removed in the solve. Then P += α_p p' in fluid cells, and both phases'
// velocities are corrected. Without solids this is the single-phase pressure correction.
// Its residual is the volume imbalance before the correction, Σ|Σ_faces Q_out| / Σ ½ Σ_faces |Q|
// (at least the volume flux of the residual velocity scale through every face): the local sums
// go into IterationSums::continuity[0].
#include <algorithm>
#include <cmath>

#include "solver/simple/pressure_correction.hpp"

namespace bagnold::solver {

std::vector<std::pair<std::string, std::string>> boomeramg_options() {
  return {{"pc_hypre_boomeramg_coarsen_type", "HMIS"},
          {"pc_hypre_boomeramg_interp_type", "ext+i"},
          {"pc_hypre_boomeramg_P_max", "4"},
          {"pc_hypre_boomeramg_agg_nl", "1"}};
}

PressureCorrection::PressureCorrection(const deck::Deck& deck, const Discretization& discretization,
                                       const SolverSettings& settings)
    : m_discretization(discretization), m_settings(settings) {
  const auto& numbering = discretization.cell_numbering();
  KrylovSettings pressure;
  pressure.ksp_type = "cg";
  pressure.pc_type = deck.numerics.pressure_preconditioner;
  pressure.relative_tolerance = deck.numerics.pressure_tolerance;
  pressure.constant_null_space = !discretization.faces(gas).has_pressure_boundary;
  if (pressure.pc_type == "hypre") pressure.default_options = boomeramg_options();
  m_system = std::make_unique<LinearSystem>(discretization.layout().comm().get(),
                                            discretization.cell_pattern(gas), numbering.first_row, "pressure_", pressure);
  m_preconditioner_steps = deck.numerics.pressure_preconditioner_steps;
  renew();
  m_x.resize(static_cast<std::size_t>(numbering.owned_rows()));
  m_correction.resize(static_cast<std::size_t>(discretization.layout().local_count()));
}

void PressureCorrection::start_step() {
  if (m_steps_since_build >= m_preconditioner_steps) {
    m_system->renew_preconditioner();
    m_steps_since_build = 0;
  }
  ++m_steps_since_build;
}

bool PressureCorrection::correct(const CorrectionResponse& response, const CarriedFractions& carried,
                                 run::FlowState& state, IterationSums& sums, WorstCells& worst,
                                 StepResult& record) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& numbering = disc.cell_numbering();
  const auto& kind = disc.faces(gas).kind;
  double imbalance = 0.0, throughput = 0.0;
  worst.reset(mixture_continuity);

  for (const int l : numbering.owned_locals) {
    double a_p = 0.0, b = 0.0;
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    for_each_cell_face(disc, l, [&](const CellFace& f) {
      const double eps_g = f.of(carried.value[gas]), eps_s = f.of(carried.value[solids]);
      const double flux_out = f.sign * f.area * (eps_g * f.of(state.gas_velocity) +
                                                 eps_s * f.of(state.solids_velocity));
      b -= flux_out;
      throughput += 0.5 * std::abs(flux_out);
      if (f.of(kind) != FaceClass::unknown) return;
      const double coefficient = f.area * (eps_g * f.of(response.pressure[gas]) +
                                           eps_s * f.of(response.pressure[solids]));
      a_p += coefficient;
      if (layout.kind(f.neighbour) == grid::CellKind::fluid) {
        columns[count] = numbering.global[static_cast<std::size_t>(f.neighbour)];
        values[count++] = -coefficient;
      }
    });
    imbalance += std::abs(b);
    worst.record(mixture_continuity, std::abs(b), l);
    columns[count] = numbering.global[static_cast<std::size_t>(l)];
    values[count++] = a_p;
    m_system->set_row(numbering.global[static_cast<std::size_t>(l)], columns, values, count, b);
  }
  sums.continuity[0][0] += imbalance;
  sums.continuity[0][1] += throughput;

  std::fill(m_x.begin(), m_x.end(), 0.0);
  const SolveReport report = m_system->solve(m_x);
  // The multigrid hierarchy built by a solve is reused by the later ones until start_step()
  // renews it: within a step the matrix changes only through d.
  m_system->keep_preconditioner();
  record.linear_iterations[pressure_system] += report.iterations;
  std::fill(m_correction.begin(), m_correction.end(), 0.0);
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    m_correction[static_cast<std::size_t>(numbering.owned_locals[row])] = m_x[row];
  parallel::exchange_halo<double>(layout, m_correction);

  const double alpha_p = m_settings.relax_pressure;
  for (const int l : numbering.owned_locals)
    state.gas_pressure[static_cast<std::size_t>(l)] += alpha_p * m_correction[static_cast<std::size_t>(l)];
  parallel::exchange_halo<double>(layout, state.gas_pressure);
  for (const Phase phase : {gas, solids}) {
    if (!m_settings.moves[phase]) continue;
    auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      auto& u = velocity[ud];
      const auto& d_m = response.pressure[phase][ud];
      for (const int l : disc.velocity_numbering(d).owned_locals) {
        const int n = layout.neighbour(l, 2 * d + 1);
        u[static_cast<std::size_t>(l)] += d_m[static_cast<std::size_t>(l)] *
                                          (m_correction[static_cast<std::size_t>(l)] -
                                           m_correction[static_cast<std::size_t>(n)]);
      }
      parallel::exchange_halo<double>(layout, u);
    }
  }
  if (!report.converged)
    record.failure = "the pressure correction's linear solve did not converge (" + report.reason + ")";
  return report.converged;
}

}  // namespace bagnold::solver
