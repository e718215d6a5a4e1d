// Step 1b of the outer iteration: the momentum predictors of both phases for the component d,
// with partial elimination of the drag coupling (Spalding's PEA, as MFIX).
//
// Row by row, with A_m = a_m + βV the diagonal including drag and R_m = b_m + Σ a_nb u_nb the
// rest of the row at the current iterate, the pair
//     A_g u_g − βV u_s = R_g,      A_s u_s − βV u_g = R_s
// is solved for each phase with the other phase's own row eliminated:
//     (A_g − (βV)²/A_s) u_g = b_g + Σ a_nb u_nb + βV R_s / A_s       (and likewise the solids),
// so a strong drag couples the phases within the predictor instead of across outer iterations.
// Then Patankar under-relaxation (diag / α_u, b + (1 − α_u) diag u*), and one BiCGStab solve per
// phase (numerics.solids_momentum = "coupled": the solids rows of the three components go into
// one system, solved after the third, coupled_solids_momentum.hpp). Where the solids are below the threshold their velocity is zero (and the gas sees
// β (0 − u_g)); a frozen solids phase enters with its given velocity.
//
// The corrections' velocity responses come from the same 2 × 2 system with the relaxed
// diagonals D_m (SIMPLEC: D_m − Σ a_nb):
//   [D_g, −βV; −βV, D_s] (u'_g, u'_s) = (ε_g A, ε_s A) (p'_c − p'_n)  →  d_g, d_s,
//   [D_g, −βV; −βV, D_s] (u'_g, u'_s) = (0, A) (P'_c − P'_n)          →  e (solids),
// with P'_s = K ε' in each cell (K = dP_s/dε_s) applied by the fraction correction.
// Residuals: Σ|R_m + βV u_other − A_m u_m| per phase, normalized as numerics.residual_normalization
// says (momentum_residual.hpp).
#include <algorithm>
#include <cmath>

#include "solver/simple/momentum_predictor.hpp"
#include "solver/simple/row_trace.hpp"

namespace bagnold::solver {

namespace {
// The friction response w (below) is taken only where the face's P_s is above this [Pa], and
// kept within ±this, so that the fraction correction's coefficients (1 ± w) stay positive.
constexpr double least_friction_pressure = 1e-3;
constexpr double max_friction_response = 0.9;
// numerics.residual_normalization = "mfix": MFIX's SMALL_NUMBER (rows slower than this [m/s] do
// not count) and DIL_EP_S (solids rows at or below this fraction do not count).
constexpr double mfix_least_speed = 1e-15;
constexpr double mfix_dilute_fraction = 1e-4;

// The relaxed diagonal that the corrections see: SIMPLEC drops the neighbours' corrections.
double correction_diagonal(double relaxed, double neighbours, bool simplec) {
  return simplec && relaxed - neighbours > 1e-12 * relaxed ? relaxed - neighbours : relaxed;
}
}  // namespace

MomentumPredictor::MomentumPredictor(const deck::Deck& deck, const Discretization& discretization,
                                     const SolverSettings& settings,
                                     const models::SolidsStressModel* closure)
    : m_discretization(discretization), m_settings(settings) {
  const MPI_Comm comm = discretization.layout().comm().get();
  KrylovSettings krylov;
  krylov.ksp_type = "bcgs";
  krylov.pc_type = deck.numerics.momentum_preconditioner;
  krylov.relative_tolerance = deck.numerics.momentum_tolerance;
  const char* prefixes[2][3] = {{"momentum_x_", "momentum_y_", "momentum_z_"},
                                {"solids_momentum_x_", "solids_momentum_y_", "solids_momentum_z_"}};
  for (int d = 0; d < 3; ++d) {
    const auto& n = discretization.velocity_numbering(d);
    const SparsityPattern pattern = discretization.momentum_pattern(d);
    for (const Phase phase : {gas, solids}) {
      // A solids row where there are no solids is an identity row: solved directly.
      krylov.solve_decoupled_rows_directly = phase == solids;
      if (settings.moves[phase] && !(phase == solids && settings.coupled_solids_momentum))
        m_systems[phase][static_cast<std::size_t>(d)] = std::make_unique<LinearSystem>(
            comm, pattern, n.first_row, prefixes[phase][d], krylov);
    }
  }
  if (settings.moves[solids] && closure)
    m_walls = std::make_unique<SolidsWallCoefficients>(deck, discretization, *closure);
  if (settings.moves[solids] && settings.coupled_solids_momentum) {
    krylov.solve_decoupled_rows_directly = true;
    m_coupled = std::make_unique<CoupledSolidsMomentum>(discretization, krylov);
  }
}

bool MomentumPredictor::solve_coupled_solids(run::FlowState& state, StepResult& record) {
  const SolveReport report = m_coupled->solve(state.solids_velocity);
  record.linear_iterations[momentum_systems] += report.iterations;
  if (report.converged) return true;
  record.failure = "the coupled solids momentum linear solve did not converge (" + report.reason + ")";
  return false;
}

bool MomentumPredictor::predict(int d, const Inputs& in, run::FlowState& state,
                                CorrectionResponse& response, IterationSums& sums,
                                WorstCells& worst, StepResult& record) {
  const Discretization& disc = m_discretization;
  const SolverSettings& settings = m_settings;
  const auto& layout = disc.layout();
  const auto ud = static_cast<std::size_t>(d);
  const auto& numbering = disc.velocity_numbering(d);
  if (numbering.total_rows == 0) return true;  // e.g. no fluid faces along d
  const double alpha = settings.relax_velocity;
  const auto& moves = settings.moves;
  auto& u_g = state.gas_velocity[ud];
  auto& u_s = state.solids_velocity[ud];
  const auto& beta_cells = in.closures.drag;
  const auto& stiffness = in.closures.pressure_derivative;

  const MomentumAssemblyInputs assembly{disc, settings, in.old, in.dt, in.closures, in.carried, m_gas_source};
  auto& rows = m_rows;
  for (const Phase phase : {gas, solids})
    if (moves[phase])
      assemble_momentum_rows(assembly, phase, d, state, m_walls.get(), in.refresh_wall_coefficients,
                             rows[phase], m_assembly_scratch);

  // The deviation normalization measures each row about the phase's mean velocity over its
  // solved rows (two collectives per phase, so only when that normalization is chosen).
  std::array<double, 2> mean{0, 0};
  if (settings.residual_normalization == ResidualNormalization::deviation) {
    std::array<double, 2> sum{0, 0}, count{0, 0};
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      const auto ul = static_cast<std::size_t>(numbering.owned_locals[r]);
      if (moves[gas]) sum[gas] += u_g[ul], count[gas] += 1;
      if (moves[solids] && rows[solids][r].active) sum[solids] += u_s[ul], count[solids] += 1;
    }
    for (const Phase phase : {gas, solids}) {
      const double n = layout.comm().sum(count[phase]);
      mean[phase] = n > 0 ? layout.comm().sum(sum[phase]) / n : 0.0;
    }
  }
  const double least_speed = settings.least_speed;
  const bool mfix_norm = settings.residual_normalization == ResidualNormalization::mfix;
  std::array<MomentumResidual, 2> residual;
  for (const Phase phase : {gas, solids}) {
    residual[phase] = MomentumResidual(settings.residual_normalization, mean[phase], in.velocity_scale,
                                       least_speed, settings.net_force_residual);
    if (moves[phase]) sums.normalization[static_cast<std::size_t>(momentum_equation(phase, d))] = residual[phase];
  }
  auto& gas_sums = sums.momentum[static_cast<std::size_t>(momentum_equation(gas, d))];
  auto& solids_sums = sums.momentum[static_cast<std::size_t>(momentum_equation(solids, d))];
  auto& x = m_x;
  for (auto& v : x) v.resize(numbering.owned_locals.size());
  worst.reset(gas_momentum_x + d);
  worst.reset(solids_momentum_x + d);
  // Both phases' rows are assembled before either solve: the first solve's assembly segment
  // counts the gas rows and the solids rows where there are solids (busy_segments.hpp).
  double assembly_units = 0.0;
  double explicit_stiffness_faces = 0.0;
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    const int l = numbering.owned_locals[r];
    const auto ul = static_cast<std::size_t>(l);
    const int n = layout.neighbour(l, 2 * d + 1);
    const MomentumRow* g = moves[gas] ? &rows[gas][r] : nullptr;
    const MomentumRow* s = moves[solids] && rows[solids][r].active ? &rows[solids][r] : nullptr;
    const MomentumRow& any = g ? *g : rows[solids][r];
    if (g) sums.wall_shear[gas][ud] += g->wall_shear;
    if (s) sums.wall_shear[solids][ud] += s->wall_shear;
    assembly_units += (g ? 1.0 : 0.0) + (s ? 1.0 : 0.0);
    const double half_c = 0.5 * disc.width(l, d), half_n = 0.5 * disc.width(n, d);
    const double beta = (beta_cells[ul] * half_n + beta_cells[static_cast<std::size_t>(n)] * half_c) / (half_c + half_n);
    const double beta_v = settings.drag ? beta * any.volume : 0.0;
    const double A_g = g ? g->a + beta_v : 0.0, A_s = s ? s->a + beta_v : 0.0;
    const double R_g = g ? g->b + g->neighbours_u : 0.0, R_s = s ? s->b + s->neighbours_u : 0.0;

    // The row's residual at the current iterate, with the drag on the other phase's velocity.
    // Under "mfix" it is the residual of the row after the drag's partial elimination, as MFIX's
    // CALC_RESID_U sees it: r + (βV/A_o) r_o with r_o the other phase's row residual, over
    // |A − (βV)²/A_o| times the speed at the row's cell.
    auto add_residual = [&](Phase phase, const MomentumRow& row, double A, double u, double u_other,
                            const MomentumRow* other_row, double A_other) {
      double mfix_scale = 0.0, eliminated_part = 0.0;
      bool mfix_counted = true;
      if (mfix_norm) {
        const auto& v = phase == gas ? state.gas_velocity : state.solids_velocity;
        const double speed = std::sqrt(v[0][ul] * v[0][ul] + v[1][ul] * v[1][ul] + v[2][ul] * v[2][ul]);
        double eliminated = A;
        if (other_row && A_other > 0.0) {
          eliminated -= beta_v * beta_v / A_other;
          const double other_residual =
              other_row->b + beta_v * u + other_row->neighbours_u - A_other * u_other;
          eliminated_part = beta_v / A_other * other_residual;
        }
        mfix_scale = std::abs(eliminated) * speed;
        mfix_counted = speed > mfix_least_speed && (phase == gas || row.fraction > mfix_dilute_fraction);
      }
      const MomentumResidual::Row terms{
          .diagonal = A, .operator_u = A * u - row.neighbours_u,
          .operator_one = A - row.neighbours_a, .source = row.b + beta_v * u_other,
          .transient = row.transient, .weight = row.weight,
          .force = row.force + std::abs(beta_v * (u_other - u)),
          .mfix_scale = mfix_scale, .mfix_counted = mfix_counted, .mfix_coupling = eliminated_part};
      const double row_residual = residual[phase].add(phase == gas ? gas_sums : solids_sums, terms);
      worst.record((phase == gas ? gas_momentum_x : solids_momentum_x) + d, row_residual, l);
      if (m_row_trace.on())
        m_row_trace.report(disc.domain(), layout.comm(),
                           {.phase = phase, .component = d, .owner = layout.natural(l),
                            .plus = n >= 0 ? layout.natural(n) : -1,
                            .residual = terms.source - terms.operator_u, .weight = terms.weight,
                            .force = terms.force, .diagonal = terms.diagonal, .velocity = u,
                            .sources = terms.source, .neighbours = row.neighbours_u, .viscous = row.viscous});
    };

    if (g) {
      add_residual(gas, *g, A_g, u_g[ul], u_s[ul], s, A_s);
      double diagonal = A_g, rhs = g->b;
      if (s) {
        diagonal -= beta_v * beta_v / A_s;
        rhs += beta_v * R_s / A_s;
      } else {
        rhs += beta_v * u_s[ul];  // frozen solids, or none here (u_s = 0)
      }
      const double relaxed = diagonal / alpha;
      MomentumRow& row = rows[gas][r];  // the diagonal goes after the off-diagonal entries
      row.columns[row.count] = numbering.global[ul];
      row.values[row.count] = relaxed;
      m_systems[gas][ud]->set_row(numbering.global[ul], row.columns, row.values, row.count + 1,
                                  rhs + (1.0 - alpha) * relaxed * u_g[ul]);
      x[gas][r] = u_g[ul];
    }
    if (moves[solids]) {
      MomentumRow& row = rows[solids][r];
      double diagonal = 1.0, rhs = 0.0;
      if (s) {
        add_residual(solids, *s, A_s, u_s[ul], u_g[ul], g, A_g);
        diagonal = A_s;
        rhs = s->b;
        if (g) {
          diagonal -= beta_v * beta_v / A_g;
          rhs += beta_v * R_g / A_g;
        }
        diagonal /= alpha;
        rhs += (1.0 - alpha) * diagonal * u_s[ul];
      }
      if (m_coupled) {
        m_coupled->set_row(d, r, row, diagonal, rhs, state.solids_velocity);
      } else {
        row.columns[row.count] = numbering.global[ul];
        row.values[row.count] = diagonal;
        m_systems[solids][ud]->set_row(numbering.global[ul], row.columns, row.values, row.count + 1, rhs);
      }
      x[solids][r] = s ? u_s[ul] : 0.0;
    }

    // Velocity responses to the pressure and volume-fraction corrections.
    const double D_g = g ? correction_diagonal(A_g / alpha, g->neighbours_a, settings.simplec) : 0.0;
    const double D_s = s ? correction_diagonal(A_s / alpha, s->neighbours_a, settings.simplec) : 0.0;
    const double eps_g = g ? g->fraction : 0.0;
    const double eps_s = moves[solids] ? rows[solids][r].fraction : 0.0;
    // A closure whose P_s falls with ε_s at fixed strain rate (kinetic theory in its dilute
    // range) would make the correction anti-diffusive: the fraction correction takes K ≥ 0 and
    // that part stays explicit (counted as negative_stiffness, faces with such a cell).
    const bool l_fluid = layout.kind(l) == grid::CellKind::fluid, n_fluid = layout.kind(n) == grid::CellKind::fluid;
    if (s && ((l_fluid && stiffness[ul] < 0.0) || (n_fluid && stiffness[static_cast<std::size_t>(n)] < 0.0)))
      explicit_stiffness_faces += 1.0;
    double d_g = 0.0, d_s = 0.0, e = 0.0;
    if (g && s) {
      const double det = D_g * D_s - beta_v * beta_v;
      d_g = any.area * (eps_g * D_s + eps_s * beta_v) / det;
      d_s = any.area * (eps_s * D_g + eps_g * beta_v) / det;
      e = any.area * D_g / det;
    } else if (g) {
      d_g = eps_g * any.area / D_g;
    } else if (s) {
      d_s = eps_s * any.area / D_s;
      e = any.area / D_s;
    }
    response.pressure[gas][ud][ul] = d_g;
    response.pressure[solids][ud][ul] = d_s;
    response.fraction[ud][ul] = e;
    // The friction response w: the solids' stresses scale with P_s at a fixed strain rate (the
    // frictional and dense closures: τ = η P_s), so a P_s change δP on the face moves its viscous
    // force by F_visc δP/P; with the face's P the mean of its cells', the velocity responds by
    // e w (δP_l + δP_n), w = F_visc / (2 A P_face) (volume_fraction_correction.cpp).
    double w = 0.0;
    if (s && l_fluid && n_fluid) {
      const double p_face = 0.5 * (state.solids_pressure[ul] + state.solids_pressure[static_cast<std::size_t>(n)]);
      if (p_face > least_friction_pressure)
        w = std::clamp(s->viscous / (2.0 * any.area * p_face), -max_friction_response, max_friction_response);
    }
    response.friction[ud][ul] = w;
  }
  sums.interventions[negative_stiffness] += explicit_stiffness_faces;

  bool solved = true;
  for (const Phase phase : {gas, solids}) {
    if (!moves[phase]) continue;
    if (m_systems[phase][ud]) {
      m_systems[phase][ud]->set_assembly_units(assembly_units);
      assembly_units = 0.0;
    }
    if (phase == solids && m_coupled) {
      parallel::exchange_halo<double>(layout, response.pressure[phase][ud]);
      continue;
    }
    auto& u = phase == gas ? u_g : u_s;
    const SolveReport report = m_systems[phase][ud]->solve(x[phase]);
    record.linear_iterations[momentum_systems] += report.iterations;
    if (!report.converged && solved) {
      solved = false;
      record.failure = std::string("the ") + equation_name(momentum_equation(phase, d)) +
                       " linear solve did not converge (" + report.reason + ")";
    }
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r)
      u[static_cast<std::size_t>(numbering.owned_locals[r])] = x[phase][r];
    parallel::exchange_halo<double>(layout, u);
    parallel::exchange_halo<double>(layout, response.pressure[phase][ud]);
  }
  if (moves[solids]) parallel::exchange_halo<double>(layout, response.fraction[ud]);
  if (moves[solids]) parallel::exchange_halo<double>(layout, response.friction[ud]);
  return solved;
}

}  // namespace bagnold::solver
