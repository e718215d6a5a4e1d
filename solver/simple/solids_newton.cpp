// numerics.solids_momentum = "newton-krylov": the solids momentum of one outer iteration solved
// by Newton-Krylov steps (newton_krylov.hpp) instead of one Picard solve.
//
// The unknowns are the solids face velocities of all three components (the coupled system's
// rows, coupled_solids_momentum.hpp); F(u) is each solids row's residual A u − b − βV u_g −
// Σ a_nb u_nb with the solids stress evaluated at u (μ_s, λ_s and P_s at u's strain rate: the
// dependences the Picard iteration lags), the gas velocity, the pressures' fraction parts and
// the fractions held at the outer iterate. Each component's rows are scaled by the mean force
// that acts on them (the force norm's F, momentum_residual.hpp), so that ||F|| weighs the
// components as the force norm does. The preconditioner is the Picard matrix the predictor
// assembled for this outer iteration (its relaxation and drag elimination included), solved
// by the coupled system's Krylov solver. The start is the Picard solution of that matrix.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "solver/simple/closures.hpp"
#include "solver/simple/momentum_predictor.hpp"
#include "solver/simple/newton_krylov.hpp"
#include "src/parallel/layout.hpp"

namespace bagnold::solver {

bool MomentumPredictor::refine_solids_newton(Closures& closures, ClosureFields& fields, const Inputs& in,
                                             run::FlowState& state, StepResult& record) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& comm = layout.comm();
  const MomentumAssemblyInputs assembly{disc, m_settings, in.old, in.dt, in.closures, in.carried, m_gas_source};
  const std::size_t size = m_coupled->owned_rows();
  std::array<double, 3> scale{1.0, 1.0, 1.0};  // 1 / (mean F) per component, set at the start
  bool scaled = false;

  auto residual = [&](const std::vector<double>& u, std::vector<double>& f) {
    for (int d = 0; d < 3; ++d) {
      const auto& numbering = disc.velocity_numbering(d);
      auto& velocity = state.solids_velocity[static_cast<std::size_t>(d)];
      for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r)
        velocity[static_cast<std::size_t>(numbering.owned_locals[r])] = u[m_coupled->position(d, r)];
      parallel::exchange_halo<double>(layout, velocity);
    }
    closures.evaluate_solids_stress(disc, state, in.old, in.dt, fields);
    std::array<double, 3> force{0.0, 0.0, 0.0}, rows{0.0, 0.0, 0.0};
    bool finite = true;
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      const auto& numbering = disc.velocity_numbering(d);
      if (numbering.total_rows == 0) continue;
      assemble_momentum_rows(assembly, solids, d, state, m_walls.get(), false, m_newton_rows, m_assembly_scratch);
      const auto& u_g = state.gas_velocity[ud];
      const auto& u_s = state.solids_velocity[ud];
      for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
        const int l = numbering.owned_locals[r];
        const auto ul = static_cast<std::size_t>(l);
        const MomentumRow& row = m_newton_rows[r];
        double& out = f[m_coupled->position(d, r)];
        if (!row.active) {
          out = 0.0;
          continue;
        }
        const double beta_v =
            m_settings.drag ? face_drag_coefficient(disc, in.closures.drag, l, d) * row.volume : 0.0;
        out = (row.a + beta_v) * u_s[ul] - row.b - beta_v * u_g[ul] - row.neighbours_u;
        finite = finite && std::isfinite(out);
        force[ud] += row.force + std::abs(beta_v * (u_g[ul] - u_s[ul]));
        rows[ud] += 1.0;
      }
    }
    if (!scaled) {
      for (std::size_t d = 0; d < 3; ++d) {
        const double total = comm.sum(force[d]), count = comm.sum(rows[d]);
        scale[d] = total > 0.0 ? count / total : 1.0;
      }
      scaled = true;
    }
    for (int d = 0; d < 3; ++d)
      for (std::size_t r = 0; r < disc.velocity_numbering(d).owned_locals.size(); ++r)
        f[m_coupled->position(d, r)] *= scale[static_cast<std::size_t>(d)];
    return comm.sum(finite ? 0.0 : 1.0) == 0.0;
  };
  std::vector<double> unscaled(size);
  auto precondition = [&](const std::vector<double>& v, std::vector<double>& z) {
    for (int d = 0; d < 3; ++d)
      for (std::size_t r = 0; r < disc.velocity_numbering(d).owned_locals.size(); ++r) {
        const std::size_t i = m_coupled->position(d, r);
        unscaled[i] = v[i] / scale[static_cast<std::size_t>(d)];
      }
    z.assign(size, 0.0);
    const SolveReport report = m_coupled->apply_inverse(unscaled, z);
    record.linear_iterations[momentum_systems] += report.iterations;
    return report.converged;
  };
  auto dot = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double local = 0.0;
    for (std::size_t i = 0; i < size; ++i) local += a[i] * b[i];
    return comm.sum(local);
  };

  std::vector<double> u(size);
  for (int d = 0; d < 3; ++d) {
    const auto& numbering = disc.velocity_numbering(d);
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r)
      u[m_coupled->position(d, r)] =
          state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(numbering.owned_locals[r])];
  }
  NewtonKrylovSettings settings;
  // Well below the tolerance the step is judged by, per row on average.
  settings.target = 0.1 * m_settings.tolerance * std::sqrt(comm.sum(static_cast<double>(size)));
  const NewtonKrylovReport report = newton_krylov({residual, precondition, dot}, settings, u);
  if (std::getenv("BAGNOLD_TRACE") && comm.is_root())
    std::fprintf(stderr, "    solids Newton-Krylov: ||F|| %.3e -> %.3e in %d steps, %d Krylov iterations, %d evaluations\n",
                 report.first, report.last, report.newton_steps, report.krylov_iterations,
                 report.residual_evaluations);
  if (!report.evaluated) {
    record.failure = "the solids Newton-Krylov solve met a residual that is not finite or a failed preconditioner";
    return false;
  }
  return true;
}

}  // namespace bagnold::solver
