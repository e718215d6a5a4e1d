// The step's residual and Jacobian from one evaluation of its rows (step_equations.hpp).
#include "solver/newton/step_equations.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "solver/petsc/handle.hpp"
#include "solver/simple/face_fractions.hpp"

namespace bagnold::solver {

namespace {
using Block = StepUnknowns::Block;

// The equation each block's rows belong to (momentum rows by phase and component).
int block_equation(Block block) {
  if (block < StepUnknowns::pressure) return block;  // gas x .. solids z in Equation's order
  return block == StepUnknowns::pressure ? mixture_continuity : solids_continuity;
}

// One Jacobian row under construction: its columns and values, added into J at once.
struct JacobianRow {
  PetscInt row = -1;
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
  void start(std::int64_t r) {
    row = static_cast<PetscInt>(r);
    columns.clear();
    values.clear();
  }
  void add(std::int64_t column, double value) {
    if (column < 0) return;
    columns.push_back(static_cast<PetscInt>(column));
    values.push_back(value);
  }
  void insert(Mat J, double scale) {
    for (auto& v : values) v *= scale;
    petsc_check(MatSetValues(J, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(), values.data(),
                             ADD_VALUES),
                "MatSetValues");
  }
};

// The weights of a face's linear fraction (face_fraction) on its two cells c and n along d.
std::pair<double, double> interpolation_weights(const Discretization& disc, int c, int n, int d) {
  const double wc = disc.width(c, d), wn = disc.width(n, d);
  return {wn / (wc + wn), wc / (wc + wn)};
}

// The pinned pressure row, P − P_start, per this many pascals (any scale serves: the row only
// fixes the level).
constexpr double pinned_pressure_scale = 1e-3;

bool is_fluid(const parallel::Layout& layout, int local) {
  return local >= 0 && layout.kind(local) == grid::CellKind::fluid;
}
}  // namespace

StepEquations::StepEquations(const Discretization& discretization, const SolverSettings& settings,
                             Closures& closures, SolidsWallCoefficients* walls,
                             const std::array<std::vector<double>, 3>& gas_source)
    : m_discretization(discretization), m_settings(settings), m_closures(closures), m_walls(walls),
      m_gas_source(gas_source), m_unknowns(discretization, settings.moves),
      m_fields(static_cast<std::size_t>(discretization.layout().local_count())),
      m_carried(static_cast<std::size_t>(discretization.layout().local_count())) {
  m_scale.assign(static_cast<std::size_t>(m_unknowns.owned_rows()), 1.0);
  const auto& layout = discretization.layout();
  for (int d = 0; d < 3; ++d) {
    const auto& global = discretization.velocity_numbering(d).global;
    for (int l = 0; l < layout.local_count(); ++l)
      if (global[static_cast<std::size_t>(l)] >= 0) m_local_of[static_cast<std::size_t>(d)][global[static_cast<std::size_t>(l)]] = l;
  }
  m_fraction_force.assign(static_cast<std::size_t>(discretization.layout().local_count()), 0.0);
  m_pin_pressure = m_unknowns.present(StepUnknowns::pressure) && !discretization.faces(gas).has_pressure_boundary &&
                   discretization.layout().comm().is_root() &&
                   !m_unknowns.owned_locals(StepUnknowns::pressure).empty();
}

void StepEquations::create_matrix(Mat* J) const {
  const auto owned = static_cast<PetscInt>(m_unknowns.owned_rows());
  const auto total = static_cast<PetscInt>(m_unknowns.total_rows());
  // At most: the diagonal, six neighbours, drag, eight cross terms, two pressures and two
  // fractions (a momentum row); twelve velocities and seven fractions (a mixture row).
  constexpr PetscInt per_row = 24;
  petsc_check(MatCreateAIJ(m_discretization.layout().comm().get(), owned, owned, total, total, per_row, nullptr,
                           per_row, nullptr, J),
              "MatCreateAIJ");
  petsc_check(MatSetOption(*J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
}

void StepEquations::start_step(const run::FlowState& old, double dt) {
  m_old = &old;
  m_dt = dt;
  m_first = true;
  if (m_pin_pressure)
    m_pinned_pressure = old.gas_pressure[static_cast<std::size_t>(m_unknowns.owned_locals(StepUnknowns::pressure).front())];
}

double StepEquations::face_drag(int l, int d, double volume) const {
  if (!m_settings.drag) return 0.0;
  const int n = m_discretization.layout().neighbour(l, 2 * d + 1);
  const double half_c = 0.5 * m_discretization.width(l, d), half_n = 0.5 * m_discretization.width(n, d);
  const auto& beta = m_fields.drag;
  return (beta[static_cast<std::size_t>(l)] * half_n + beta[static_cast<std::size_t>(n)] * half_c) / (half_c + half_n) *
         volume;
}

void StepEquations::residual(run::FlowState& state, Vec f, IterationSums& sums, WorstCells& worst) {
  const Discretization& disc = m_discretization;
  m_closures.evaluate(disc, state, *m_old, m_dt, m_fields);
  carry_all_fractions(disc, state, m_carried);
  const MomentumAssemblyInputs inputs{disc, m_settings, *m_old, m_dt, m_fields, m_carried, m_gas_source};
  for (const Phase phase : {gas, solids}) {
    if (!m_settings.moves[phase]) continue;
    for (int d = 0; d < 3; ++d)
      if (disc.velocity_numbering(d).total_rows > 0)
        assemble_momentum_rows(inputs, phase, d, state, m_walls, m_first, m_rows[phase][static_cast<std::size_t>(d)],
                               m_scratch);
  }
  PetscScalar* values = nullptr;
  petsc_check(VecGetArray(f, &values), "VecGetArray");
  if (m_first) {
    // The force a solids row's fraction error makes, per unit imbalance: δε = |R| dt/V acting
    // through dP_s/dε_s on the cell's largest face and on its weight.
    const auto& layout = disc.layout();
    for (int l = 0; l < layout.local_count(); ++l) {
      const double volume = disc.volume(l);
      const double largest_area = std::max({disc.face_area(l, 0), disc.face_area(l, 1), disc.face_area(l, 2)});
      const double stiffness = std::max(m_fields.pressure_derivative[static_cast<std::size_t>(l)], 0.0);
      m_fraction_force[static_cast<std::size_t>(l)] =
          m_dt / volume * (stiffness * largest_area + m_settings.density[solids] * volume * m_settings.gravity_magnitude);
    }
  }
  momentum_residual(state, values, sums, worst);
  continuity_residual(state, values, sums, worst);
  if (m_first) {
    // Each equation's mean normalization over its rows (all ranks).
    std::array<double, 2 * equation_count> local{}, total{};
    for (int e = 0; e < 6; ++e) local[static_cast<std::size_t>(e)] = sums.momentum[static_cast<std::size_t>(e)].values[5];
    for (int c = 0; c < 2; ++c) local[static_cast<std::size_t>(mixture_continuity + c)] = sums.continuity[static_cast<std::size_t>(c)][1];
    for (int b = 0; b < StepUnknowns::block_count; ++b)
      local[static_cast<std::size_t>(equation_count + block_equation(static_cast<Block>(b)))] +=
          static_cast<double>(m_unknowns.owned_locals(static_cast<Block>(b)).size());
    MPI_Allreduce(local.data(), total.data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM,
                  disc.layout().comm().get());
    // A flow at rest has no throughput: at least what the least speed carries through every face.
    const double least_throughput = disc.reference_area() * m_settings.least_speed;
    total[mixture_continuity] = std::max(total[mixture_continuity], least_throughput);
    if (m_settings.residual_normalization != ResidualNormalization::force)
      total[solids_continuity] = std::max(total[solids_continuity], least_throughput);
    for (int e = 0; e < equation_count; ++e)
      m_mean[static_cast<std::size_t>(e)] =
          std::max(total[static_cast<std::size_t>(e)] / std::max(total[static_cast<std::size_t>(equation_count + e)], 1.0), 1e-300);
    m_first = false;
  }
  // Each row against its equation's mean (m_scale holds the row's own factor until here).
  for (int b = 0; b < StepUnknowns::block_count; ++b) {
    const auto block = static_cast<Block>(b);
    const double mean = m_mean[static_cast<std::size_t>(block_equation(block))];
    const auto offset = m_unknowns.block_offset(block);
    const auto rows = static_cast<std::int64_t>(m_unknowns.owned_locals(block).size());
    for (std::int64_t r = offset; r < offset + rows; ++r) {
      auto& scale = m_scale[static_cast<std::size_t>(r)];
      scale = scale > 0.0 ? scale / mean : -scale;  // negative: a factor of its own
      values[r] *= scale;
    }
  }
  petsc_check(VecRestoreArray(f, &values), "VecRestoreArray");
}

void StepEquations::momentum_residual(const run::FlowState& state, PetscScalar* f, IterationSums& sums,
                                      WorstCells& worst) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& moves = m_settings.moves;
  // The velocity scale of the "velocity-scale" normalization: the largest face velocity.
  double largest = 0.0;
  for (const auto* velocity : {&state.gas_velocity, &state.solids_velocity})
    for (const auto& component : *velocity)
      for (int l = 0; l < layout.owned_count(); ++l) largest = std::max(largest, std::abs(component[static_cast<std::size_t>(l)]));
  const double velocity_scale = std::max(layout.comm().max(largest), m_settings.least_speed);
  const MomentumResidual measure(m_settings.residual_normalization, 0.0, velocity_scale, m_settings.least_speed);
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const auto& numbering = disc.velocity_numbering(d);
    if (numbering.total_rows == 0) continue;
    for (const Phase phase : {gas, solids})
      if (moves[phase]) sums.normalization[static_cast<std::size_t>(momentum_equation(phase, d))] = measure;
    worst.reset(gas_momentum_x + d);
    worst.reset(solids_momentum_x + d);
    const auto& u_g = state.gas_velocity[ud];
    const auto& u_s = state.solids_velocity[ud];
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      const int l = numbering.owned_locals[r];
      const auto ul = static_cast<std::size_t>(l);
      const MomentumRow* g = moves[gas] ? &m_rows[gas][ud][r] : nullptr;
      const MomentumRow* s = moves[solids] && m_rows[solids][ud][r].active ? &m_rows[solids][ud][r] : nullptr;
      const double beta_v = face_drag(l, d, (g ? *g : m_rows[solids][ud][r]).volume);
      auto add = [&](Phase phase, const MomentumRow& row, double u, double u_other) {
        const double A = row.a + beta_v;
        const MomentumResidual::Row terms{.diagonal = A, .operator_u = A * u - row.neighbours_u,
                                          .operator_one = A - row.neighbours_a, .source = row.b + beta_v * u_other,
                                          .transient = row.transient, .weight = row.weight,
                                          .force = row.force + std::abs(beta_v * (u_other - u))};
        const int equation = momentum_equation(phase, d);
        worst.record(equation, measure.add(sums.momentum[static_cast<std::size_t>(equation)], terms), l);
        const auto at = m_unknowns.block_offset(StepUnknowns::velocity_block(phase, d)) + static_cast<std::int64_t>(r);
        f[at] = terms.operator_u - terms.source;
        m_scale[static_cast<std::size_t>(at)] = 1.0;
      };
      if (g) add(gas, *g, u_g[ul], u_s[ul]);
      if (!moves[solids]) continue;
      if (s) {
        add(solids, *s, u_s[ul], u_g[ul]);
      } else {
        // No solids on either side: u_s = 0, measured against the reference speed.
        const auto at = m_unknowns.block_offset(StepUnknowns::velocity_block(solids, d)) + static_cast<std::int64_t>(r);
        f[at] = u_s[ul];
        m_scale[static_cast<std::size_t>(at)] = -1.0 / m_settings.reference_speed;
      }
    }
  }
}

void StepEquations::continuity_residual(const run::FlowState& state, PetscScalar* f, IterationSums& sums,
                                        WorstCells& worst) {
  const Discretization& disc = m_discretization;
  const auto& numbering = disc.cell_numbering();
  const bool force_norm = m_settings.residual_normalization == ResidualNormalization::force;
  const double rho = m_settings.density[solids], g = m_settings.gravity_magnitude;
  const bool mixture = m_unknowns.present(StepUnknowns::pressure);
  const bool solids_rows = m_unknowns.present(StepUnknowns::fraction);
  worst.reset(mixture_continuity);
  worst.reset(solids_continuity);
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    const int l = numbering.owned_locals[r];
    const auto ul = static_cast<std::size_t>(l);
    double volume_flux = 0.0, volume_throughput = 0.0, solids_flux = 0.0, solids_throughput = 0.0;
    for_each_cell_face(disc, l, [&](const CellFace& face) {
      const double eps_g = face.of(m_carried.value[gas]), eps_s = face.of(m_carried.value[solids]);
      const double gas_out = face.sign * face.area * eps_g * face.of(state.gas_velocity);
      const double solids_out = face.sign * face.area * eps_s * face.of(state.solids_velocity);
      volume_flux += gas_out + solids_out;
      volume_throughput += 0.5 * std::abs(gas_out + solids_out);
      solids_flux += solids_out;
      solids_throughput += 0.5 * std::abs(solids_out);
    });
    if (mixture) {
      sums.continuity[0][0] += std::abs(volume_flux);
      sums.continuity[0][1] += volume_throughput;
      worst.record(mixture_continuity, std::abs(volume_flux), l);
      const auto at = m_unknowns.block_offset(StepUnknowns::pressure) + static_cast<std::int64_t>(r);
      f[at] = volume_flux;
      m_scale[static_cast<std::size_t>(at)] = 1.0;
      if (m_pin_pressure && r == 0) {
        // The level of a closed domain's pressure (step_equations.hpp).
        f[at] = state.gas_pressure[ul] - m_pinned_pressure;
        m_scale[static_cast<std::size_t>(at)] = -pinned_pressure_scale;
      }
    }
    if (solids_rows) {
      const double volume = disc.volume(l);
      const double imbalance = (state.solids_fraction[ul] - m_old->solids_fraction[ul]) * volume / m_dt + solids_flux;
      const auto at = m_unknowns.block_offset(StepUnknowns::fraction) + static_cast<std::int64_t>(r);
      f[at] = imbalance;
      if (force_norm) {
        const double force = std::abs(imbalance) * m_fraction_force[ul];
        sums.continuity[1][0] += force;
        sums.continuity[1][1] += rho * volume * (std::max(state.solids_fraction[ul], 0.0) * g + m_settings.least_acceleration);
        worst.record(solids_continuity, force, l);
        m_scale[static_cast<std::size_t>(at)] = m_fraction_force[ul];
      } else {
        sums.continuity[1][0] += std::abs(imbalance);
        sums.continuity[1][1] += solids_throughput;
        worst.record(solids_continuity, std::abs(imbalance), l);
        m_scale[static_cast<std::size_t>(at)] = 1.0;
      }
    }
  }
}

void StepEquations::update_stress_direction() {
  const auto& f = m_fields;
  const std::size_t local = f.flow_index.size();
  auto& S = m_stress_direction;
  if (S[0].size() != local) {
    S = f.strain_direction;  // the first linearization: S = N
  } else {
    for (std::size_t i = 0; i < local; ++i) {
      const double rate = m_updated_rate[i];
      if (!(rate > 0.0)) {
        for (int c = 0; c < 6; ++c) S[static_cast<std::size_t>(c)][i] = f.strain_direction[static_cast<std::size_t>(c)][i];
        continue;
      }
      // 2 N:δD, an off-diagonal pair counted twice.
      double projection = 0.0;
      std::array<double, 6> change{};
      for (int c = 0; c < 6; ++c) {
        const auto uc = static_cast<std::size_t>(c);
        change[uc] = f.strain_direction[uc][i] * f.strain_rate[i] - m_updated_tensor[uc][i];
        projection += (c < 3 ? 2.0 : 4.0) * m_updated_tensor[uc][i] / rate * change[uc];
      }
      double norm = 0.0;
      for (int c = 0; c < 6; ++c) {
        const auto uc = static_cast<std::size_t>(c);
        S[uc][i] += (change[uc] - S[uc][i] * projection) / rate;
        norm += (c < 3 ? 2.0 : 4.0) * S[uc][i] * S[uc][i];
      }
      if (norm > 1.0)
        for (int c = 0; c < 6; ++c) S[static_cast<std::size_t>(c)][i] /= std::sqrt(norm);
    }
  }
  m_updated_rate = f.strain_rate;
  for (int c = 0; c < 6; ++c) {
    const auto uc = static_cast<std::size_t>(c);
    m_updated_tensor[uc].resize(local);
    for (std::size_t i = 0; i < local; ++i) m_updated_tensor[uc][i] = f.strain_direction[uc][i] * f.strain_rate[i];
  }
}

void StepEquations::assemble_tangent_rows(const run::FlowState& state,
                                          const std::array<std::vector<double>, 6>& direction,
                                          std::array<std::vector<MomentumRow>, 3>& rows) {
  tangent_factors(m_fields, direction, m_fields.tangent_factor);
  const MomentumAssemblyInputs inputs{m_discretization, m_settings, *m_old, m_dt, m_fields, m_carried, m_gas_source};
  for (int d = 0; d < 3; ++d)
    if (m_discretization.velocity_numbering(d).total_rows > 0)
      assemble_momentum_rows(inputs, solids, d, state, m_walls, false, rows[static_cast<std::size_t>(d)], m_scratch);
}

void StepEquations::jacobian(const run::FlowState& state, Mat J, Mat Q, bool stress_velocity) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& moves = m_settings.moves;
  const StepUnknowns& x = m_unknowns;
  petsc_check(MatZeroEntries(J), "MatZeroEntries");
  petsc_check(MatZeroEntries(Q), "MatZeroEntries");
  JacobianRow row;
  stress_velocity = stress_velocity && moves[solids] && m_closures.stress();
  if (stress_velocity) {
    // The solids rows with S's tangent (into m_rows, which the preconditioner takes) and with
    // N's (m_tangent_rows); Q is their difference. The residual's rows are Picard's again after.
    const auto picard = m_fields.tangent_factor;
    m_closures.evaluate_flow_index(m_fields);
    update_stress_direction();
    assemble_tangent_rows(state, m_fields.strain_direction, m_tangent_rows);
    assemble_tangent_rows(state, m_stress_direction, m_rows[solids]);
    m_fields.tangent_factor = picard;
    for (int d = 0; d < 3; ++d) {
      const auto ud = static_cast<std::size_t>(d);
      const auto& numbering = disc.velocity_numbering(d);
      if (numbering.total_rows == 0) continue;
      const auto& local_of = m_local_of[ud];
      const Block block = StepUnknowns::velocity_block(solids, d);
      for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
        const MomentumRow& with_s = m_rows[solids][ud][r];
        const MomentumRow& with_n = m_tangent_rows[ud][r];
        if (!with_s.active) continue;
        const int l = numbering.owned_locals[r];
        row.start(x.index(block, l));
        row.add(x.index(block, l), with_s.a - with_n.a);
        for (int k = 0; k < with_s.count; ++k)
          row.add(x.index(block, local_of.at(with_s.columns[k])), with_s.values[k] - with_n.values[k]);
        row.insert(Q, m_scale[static_cast<std::size_t>(x.block_offset(block) + static_cast<std::int64_t>(r))]);
      }
    }
  }
  petsc_check(MatAssemblyBegin(Q, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(Q, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const auto& numbering = disc.velocity_numbering(d);
    if (numbering.total_rows == 0) continue;
    const auto& local_of = m_local_of[ud];
    for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
      const int l = numbering.owned_locals[r];
      const auto ul = static_cast<std::size_t>(l);
      const int n = layout.neighbour(l, 2 * d + 1);
      const bool solids_active = moves[solids] && m_rows[solids][ud][r].active;
      for (const Phase phase : {gas, solids}) {
        if (!moves[phase]) continue;
        const MomentumRow& m = m_rows[phase][ud][r];
        const Block block = StepUnknowns::velocity_block(phase, d);
        const auto at = x.block_offset(block) + static_cast<std::int64_t>(r);
        row.start(x.index(block, l));
        if (phase == solids && !solids_active) {
          row.add(x.index(block, l), 1.0);
          row.insert(J, m_scale[static_cast<std::size_t>(at)]);
          continue;
        }
        const double beta_v = face_drag(l, d, m.volume);
        row.add(x.index(block, l), m.a + beta_v);
        for (int k = 0; k < m.count; ++k) row.add(x.index(block, local_of.at(m.columns[k])), m.values[k]);
        // The other phase's velocity through the drag.
        const Phase other = phase == gas ? solids : gas;
        if (phase == gas ? solids_active : moves[gas]) row.add(x.index(StepUnknowns::velocity_block(other, d), l), -beta_v);
        // The transpose's cross part, which b holds at the iterate.
        for (int k = 0; k < m.cross_count; ++k)
          row.add(x.index(StepUnknowns::velocity_block(phase, m.cross_component[k]), m.cross_cell[k]),
                  -m.cross_coefficient[k]);
        // The gas pressure gradient, ε (P_c − P_n) A in b.
        const bool pressure_force = phase == gas || moves[gas];
        if (pressure_force) {
          row.add(x.index(StepUnknowns::pressure, l), -m.fraction * m.area);
          row.add(x.index(StepUnknowns::pressure, n), m.fraction * m.area);
        }
        // The solids pressure gradient through each cell's dP_s/dε_s.
        if (phase == solids) {
          const auto& stiffness = m_fields.pressure_derivative;
          if (is_fluid(layout, l)) row.add(x.index(StepUnknowns::fraction, l), -stiffness[ul] * m.area);
          if (is_fluid(layout, n)) row.add(x.index(StepUnknowns::fraction, n), stiffness[static_cast<std::size_t>(n)] * m.area);
        }
        // The fraction the row's pressure, weight and transient terms carry (linear between two
        // fluid cells; ε_g = 1 − ε_s).
        if (moves[solids] && is_fluid(layout, l) && is_fluid(layout, n)) {
          const auto& u = (phase == gas ? state.gas_velocity : state.solids_velocity)[ud];
          const auto& u_old = (phase == gas ? m_old->gas_velocity : m_old->solids_velocity)[ud];
          const double rho = m_settings.density[phase];
          double per_fraction = -rho * m_settings.gravity[ud] * m.volume + rho * m.volume / m_dt * (u[ul] - u_old[ul]);
          if (pressure_force) per_fraction -= (state.gas_pressure[ul] - state.gas_pressure[static_cast<std::size_t>(n)]) * m.area;
          const double sign = phase == gas ? -1.0 : 1.0;
          const auto [w_l, w_n] = interpolation_weights(disc, l, n, d);
          row.add(x.index(StepUnknowns::fraction, l), sign * w_l * per_fraction);
          row.add(x.index(StepUnknowns::fraction, n), sign * w_n * per_fraction);
        }
        row.insert(J, m_scale[static_cast<std::size_t>(at)]);
      }
    }
  }

  const auto& numbering = disc.cell_numbering();
  const bool mixture = x.present(StepUnknowns::pressure);
  const bool solids_rows = x.present(StepUnknowns::fraction);
  JacobianRow fraction_row;
  for (std::size_t r = 0; r < numbering.owned_locals.size(); ++r) {
    const int l = numbering.owned_locals[r];
    row.start(mixture ? x.index(StepUnknowns::pressure, l) : -1);
    fraction_row.start(solids_rows ? x.index(StepUnknowns::fraction, l) : -1);
    fraction_row.add(x.index(StepUnknowns::fraction, l), disc.volume(l) / m_dt);
    for_each_cell_face(disc, l, [&](const CellFace& face) {
      const int d = face.direction, o = face.owner;
      const double u_g = face.of(state.gas_velocity), u_s = face.of(state.solids_velocity);
      const double eps_g = face.of(m_carried.value[gas]), eps_s = face.of(m_carried.value[solids]);
      const double sa = face.sign * face.area;
      const auto ud = static_cast<std::size_t>(d), uo = static_cast<std::size_t>(o);
      if (moves[gas] && disc.faces(gas).kind[ud][uo] == FaceClass::unknown)
        row.add(x.index(StepUnknowns::velocity_block(gas, d), o), sa * eps_g);
      if (moves[solids] && disc.faces(solids).kind[ud][uo] == FaceClass::unknown) {
        row.add(x.index(StepUnknowns::velocity_block(solids, d), o), sa * eps_s);
        fraction_row.add(x.index(StepUnknowns::velocity_block(solids, d), o), sa * eps_s);
      }
      if (!moves[solids]) return;
      // The solids' upwind fraction (carried_fraction), the gas's linear one between fluid cells.
      const int p = layout.neighbour(o, 2 * d + 1);
      const int upwind = (u_s >= 0.0 || p < 0) ? o : p;
      if (is_fluid(layout, upwind)) {
        row.add(x.index(StepUnknowns::fraction, upwind), sa * u_s);
        fraction_row.add(x.index(StepUnknowns::fraction, upwind), sa * u_s);
      }
      if (is_fluid(layout, o) && is_fluid(layout, p)) {
        const auto [w_o, w_p] = interpolation_weights(disc, o, p, d);
        row.add(x.index(StepUnknowns::fraction, o), -sa * u_g * w_o);
        row.add(x.index(StepUnknowns::fraction, p), -sa * u_g * w_p);
      }
    });
    if (mixture) {
      const auto at = x.block_offset(StepUnknowns::pressure) + static_cast<std::int64_t>(r);
      if (m_pin_pressure && r == 0) {
        row.start(x.index(StepUnknowns::pressure, l));
        row.add(x.index(StepUnknowns::pressure, l), 1.0);
        row.insert(J, pinned_pressure_scale);
      } else {
        row.insert(J, m_scale[static_cast<std::size_t>(at)]);
      }
    }
    if (solids_rows)
      fraction_row.insert(J, m_scale[static_cast<std::size_t>(x.block_offset(StepUnknowns::fraction) + static_cast<std::int64_t>(r))]);
  }
  petsc_check(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

}  // namespace bagnold::solver

