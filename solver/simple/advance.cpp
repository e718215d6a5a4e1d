// One implicit-Euler time step: outer iterations (closures, momentum predictors, pressure
// correction, solids volume fraction correction, granular energy where Θ is transported) until every normalized residual is below
// numerics.tolerance, or numerics.max_outer_iterations, or a linear solve fails.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "solver/petsc/log_stage.hpp"
#include "solver/petsc/work_clock.hpp"
#include "solver/simple/face_fractions.hpp"
#include "solver/simple/flow_solver.hpp"
#include "solver/simple/solids_conservation.hpp"

namespace bagnold::solver {

namespace {
// numerics.residual_normalization = "mfix": a continuity imbalance below this fraction of the
// throughput the velocity scale carries counts as none (MFIX's 10⁻¹⁵ floor on RESID_P, in units
// that do not depend on the case).
constexpr double mfix_least_imbalance = 1e-12;

// MFIX's CHECK_CONVERGENCE: the sum of the momentum and continuity residuals (the granular
// energy, which MFIX judges on its own, by its own size).
double mfix_sum(const Residuals& residuals) {
  double sum = 0.0;
  for (int e = 0; e <= solids_continuity; ++e) sum += residuals.value[static_cast<std::size_t>(e)];
  return std::max(sum, residuals.value[granular_energy]);
}

// MFIX's continuity residual: the imbalance against the step's first one above `floor` (which
// becomes `first`, value 1, and is kept for the step); none below the floor.
double relative_to_first(double imbalance, double floor, double& first) {
  if (imbalance <= floor) return 0.0;
  if (first > 0.0) return imbalance / first;
  first = imbalance;
  return 1.0;
}
}  // namespace

bool FlowSolver::iterate(run::FlowState& state, const run::FlowState& old, double dt, bool first,
                         double velocity_scale, IterationSums& sums, StepResult& result) {
  const Discretization& disc = m_discretization;
  IterationFields& f = m_fields;
  // What each stage's rest counts as work (busy_segments.hpp): its fluid cells, the closures'
  // also its cells holding solids.
  const int fluid_cells = disc.layout().owned_fluid_count();
  int solids_cells = 0;
  for (int l = 0; l < fluid_cells; ++l)
    if (state.solids_fraction[static_cast<std::size_t>(l)] > solids_threshold) ++solids_cells;
  {
    const ScopedStage stage(Stage::closures, fluid_cells + solids_cells);
    m_closures.evaluate(disc, state, old, dt, f.closures);
  }
  carry_all_fractions(disc, state, f.carried);
  {
    const ScopedStage stage(Stage::momentum, fluid_cells);
    const MomentumPredictor::Inputs inputs{old, dt, f.closures, f.carried, velocity_scale, first};
    for (int d = 0; d < 3; ++d) {
      if (!m_predictor.predict(d, inputs, state, f.response, sums, f.worst, result)) return false;
      for (const Phase phase : {gas, solids}) carry_fractions(disc, state, phase, d, f.carried);
    }
    if (m_predictor.coupled_solids()) {
      if (!m_predictor.solve_coupled_solids(state, result)) return false;
      for (int d = 0; d < 3; ++d) carry_fractions(disc, state, solids, d, f.carried);
    }
  }
  if (m_pressure) {
    const ScopedStage stage(Stage::pressure, fluid_cells);
    if (!m_pressure->correct(f.response, f.carried, state, sums, f.worst, result)) return false;
    carry_all_fractions(disc, state, f.carried);
  }
  if (m_fraction) {
    const ScopedStage stage(Stage::fraction, fluid_cells);
    if (!m_fraction->correct(old, dt, f.closures, f.response, f.carried, state, sums, f.worst, result))
      return false;
  }
  if (m_energy) {
    const ScopedStage stage(Stage::energy, fluid_cells);
    carry_all_fractions(disc, state, f.carried);
    if (!m_energy->solve(old, dt, f.closures, f.carried, state, sums, f.worst, result)) return false;
  }
  return true;
}

StepResult FlowSolver::advance(run::FlowState& state, const run::FlowState& old, double dt,
                               bool (*stop_probe)()) {
  const ScopedWorkClock clock(ScopedWorkClock::step);  // this rank's balance (work_clock.hpp)
  if (m_newton) {
    StepResult result = m_newton->advance(state, old, dt, m_fields.worst, stop_probe);
    if (result.converged && m_fraction) {
      m_stepped_solids_flux = conserve_solids(m_discretization, m_newton->carried(), m_settings.density[solids], old,
                                              dt, state);
      // A cell the step empties can end a round-off below zero (its imbalance is within the
      // tolerance, not zero): held at zero, as the fraction correction holds it.
      double clamped = 0.0;
      for (const int l : m_discretization.cell_numbering().owned_locals)
        if (auto& eps = state.solids_fraction[static_cast<std::size_t>(l)]; eps < 0.0) eps = 0.0, clamped += 1.0;
      result.interventions[fraction_clamped_at_zero] += m_discretization.layout().comm().sum(clamped);
      parallel::exchange_halo<double>(m_discretization.layout(), state.solids_fraction);
      update_gas_fraction(m_discretization, state);
    }
    return result;
  }
  StepResult result;
  apply_boundary_values(state);
  // BAGNOLD_TRACE=1: a line naming the step's dt and the columns, then every outer iteration's
  // residuals and the cell of the largest, on stderr.
  const bool trace = std::getenv("BAGNOLD_TRACE") != nullptr;
  const auto& comm = m_discretization.layout().comm();
  if (trace && comm.is_root()) {
    std::fprintf(stderr, "  step of dt = %.6g s, residuals of:", dt);
    for (int equation = 0; equation < equation_count; ++equation)
      std::fprintf(stderr, "%s %s", equation == 0 ? "" : ",", equation_name(equation));
    std::fprintf(stderr, "\n");
  }
  const double largest_scale = scale_growth_cap * residual_velocity_scale(old, INFINITY, nullptr);
  if (m_pressure) m_pressure->start_step();
  if (m_anderson) m_anderson->start_step(old);
  StallWatch stall_watch;
  // numerics.residual_normalization = "mfix": each continuity residual against its value in the
  // step's first outer iteration (MFIX's NORM_G and NORM_S from RESID_P of iteration 1,
  // iterate.f), and the decision on the sum of all (CHECK_CONVERGENCE).
  const bool mfix = m_settings.residual_normalization == ResidualNormalization::mfix;
  std::array<double, 2> first_imbalance{0.0, 0.0};
  for (int iteration = 1; iteration <= m_settings.max_outer_iterations; ++iteration) {
    IterationSums sums;
    const double velocity_scale = residual_velocity_scale(state, largest_scale, &sums);
    result.iterations = iteration;
    if (m_anderson) m_anderson->remember_input(state);
    if (!iterate(state, old, dt, iteration == 1, velocity_scale, sums, result)) return result;
    sums.stop = stop_probe && stop_probe() ? 1.0 : 0.0;
    sums.reduce(comm);  // one Allreduce: residual sums, limiter counts, a stop request
    if (sums.stop > 0.0) {
      result.abandoned = true;
      return result;
    }
    judge_momentum(sums, result);
    // A flow at rest has no throughput: measure against the flux the velocity scale would carry.
    // Under the force norm the solids' sums are forces, their scale never 0
    // (volume_fraction_correction.cpp).
    const double least_throughput = m_discretization.reference_area() * velocity_scale;
    const bool solids_in_forces = m_settings.residual_normalization == ResidualNormalization::force;
    for (int c = 0; c < 2; ++c) {
      const auto& [imbalance, throughput] = sums.continuity[static_cast<std::size_t>(c)];
      const bool solved = c == 0 ? m_pressure != nullptr : m_fraction != nullptr;
      const double least = c == 1 && solids_in_forces ? 1e-300 : least_throughput;
      result.residuals.value[static_cast<std::size_t>(mixture_continuity + c)] =
          !solved || imbalance <= 1e-300 ? 0.0
          : mfix ? relative_to_first(imbalance, mfix_least_imbalance * least_throughput,
                                     first_imbalance[static_cast<std::size_t>(c)])
                 : imbalance / std::max(throughput, least);
    }
    const auto& [energy_imbalance, energy_scale] = sums.energy;
    result.residuals.value[granular_energy] =
        !m_energy || energy_imbalance <= 1e-300 ? 0.0 : energy_imbalance / std::max(energy_scale, 1e-300);
    result.wall_shear = sums.wall_shear;
    for (int i = 0; i < intervention_count; ++i)
      result.interventions[static_cast<std::size_t>(i)] += sums.interventions[static_cast<std::size_t>(i)];
    const double largest = mfix ? mfix_sum(result.residuals) : result.residuals.largest();
    result.judged = largest;
    if (iteration == 1) result.first_largest = result.residuals.largest();
    if (trace) {
      const auto where = worst_cell(result.residuals.worst());  // collective
      if (comm.is_root()) {
        std::fprintf(stderr, "  it %d:", iteration);
        for (const double r : result.residuals.value) std::fprintf(stderr, " %.3e", r);
        std::fprintf(stderr, "  worst at (%d, %d, %d)\n", where.cell[0], where.cell[1], where.cell[2]);
      }
    }
    if (!std::isfinite(largest)) return result;  // diverged: the caller backs off
    if (iteration_converged(largest, m_settings.tolerance, sums)) {
      if (m_fraction) {
        for (int d = 0; d < 3; ++d) carry_fractions(m_discretization, state, solids, d, m_fields.carried);
        m_stepped_solids_flux = conserve_solids(m_discretization, m_fields.carried,
                                                m_settings.density[solids], old, dt, state);
      }
      result.converged = true;
      return result;
    }
    if (m_settings.detect_stall && stall_watch.has_stalled_after(iteration, largest)) {
      result.stalled = true;
      return result;
    }
    // The next iteration starts from Anderson's mixture of the last results (anderson_mixing.hpp).
    if (m_anderson)
      result.interventions[anderson_clipped] +=
          static_cast<double>(comm.sum(static_cast<double>(m_anderson->mix(state, velocity_scale))));
  }
  return result;
}

}  // namespace bagnold::solver
