// The two-fluid solver's set-up, boundary values and monitor fluxes (flow_solver.hpp).
#include "solver/simple/flow_solver.hpp"

#include <algorithm>
#include <cmath>

#include "solver/simple/row_location.hpp"
#include "solver/simple/solids_conservation.hpp"

namespace bagnold::solver {

FlowSolver::FlowSolver(const deck::Deck& deck, const parallel::Domain& domain)
    : m_discretization(domain),
      m_settings(deck, domain),
      m_closures(deck, m_discretization),
      m_predictor(deck, m_discretization, m_settings, m_closures.stress()),
      m_fields(static_cast<std::size_t>(domain.layout.local_count())) {
  if (m_settings.moves[gas])
    m_pressure = std::make_unique<PressureCorrection>(deck, m_discretization, m_settings);
  if (m_settings.moves[solids])
    m_fraction = std::make_unique<VolumeFractionCorrection>(m_discretization, m_settings, m_closures);
  if (m_settings.moves[solids] && m_closures.stress() && m_closures.stress()->granular_energy())
    m_energy = std::make_unique<GranularEnergyEquation>(m_discretization, m_settings, m_closures);
  if (m_settings.anderson_depth > 0)
    m_anderson = std::make_unique<AndersonMixing>(domain.layout, m_settings.anderson_depth);
  if (m_settings.step_solver == deck::StepSolver::newton) {
    if (m_energy)
      throw std::invalid_argument("numerics.step_solver = \"newton\" does not solve a transported granular energy; "
                                  "use \"outer-iteration\" or an algebraic closure");
    if (m_settings.moves[solids] && m_closures.stress())
      m_newton_walls = std::make_unique<SolidsWallCoefficients>(deck, m_discretization, *m_closures.stress());
    m_newton = std::make_unique<NewtonStep>(m_discretization, m_settings, m_closures, m_newton_walls.get(),
                                            m_predictor.gas_source(),
                                            [this](run::FlowState& s) { apply_boundary_values(s); },
                                            [this](int equation) { return worst_cell(equation); });
  }
}

double FlowSolver::residual_velocity_scale(const run::FlowState& state, double cap,
                                           IterationSums* sums) const {
  const auto& layout = m_discretization.layout();
  double largest = 0.0;
  for (const auto* velocity : {&state.gas_velocity, &state.solids_velocity})
    for (const auto& component : *velocity)
      for (int l = 0; l < layout.owned_count(); ++l)
        largest = std::max(largest, std::abs(component[static_cast<std::size_t>(l)]));
  const double measured = layout.comm().max(largest);
  const double floor = m_settings.least_speed;
  const double scale = std::max(measured, floor);
  if (sums && measured < floor) sums->interventions[velocity_scale_floored] = 1.0;
  if (sums && scale > cap) sums->interventions[velocity_scale_capped] = 1.0;
  return std::min(scale, cap);
}

CellLocation FlowSolver::worst_cell(int equation) const {
  const auto& layout = m_discretization.layout();
  const auto& domain = m_discretization.domain();
  const int local = m_fields.worst.local(equation);
  struct {
    double value;
    int rank;
  } mine{local >= 0 ? m_fields.worst.value(equation) : -1.0, layout.comm().rank()}, worst{};
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, layout.comm().get());
  // A momentum row is the face between its owning cell and the owner's + neighbour along d;
  // either may be a boundary cell (an opening's face is owned by the cell beyond it).
  const bool momentum = equation < mixture_continuity;
  const int d = equation % 3;
  const int plus = local >= 0 && momentum ? layout.neighbour(local, 2 * d + 1) : -1;
  std::int64_t naturals[2] = {local >= 0 ? layout.natural(local) : 0, plus >= 0 ? layout.natural(plus) : -1};
  MPI_Bcast(naturals, 2, MPI_INT64_T, worst.rank, layout.comm().get());
  return locate_row(domain, equation, naturals[0], naturals[1]);
}

void FlowSolver::apply_boundary_values(run::FlowState& state) const {
  const auto& layout = m_discretization.layout();
  const auto& regions = m_discretization.domain().regions;
  const auto local = static_cast<std::size_t>(layout.local_count());
  for (const Phase phase : {gas, solids}) {
    auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    const auto& f = m_discretization.faces(phase);
    for (int d = 0; d < 3; ++d) {
      auto& u = velocity[static_cast<std::size_t>(d)];
      const auto& kind = f.kind[static_cast<std::size_t>(d)];
      for (std::size_t l = 0; l < local; ++l) {
        if (kind[l] == FaceClass::fixed) u[l] = f.fixed_value[static_cast<std::size_t>(d)][l];
        if (kind[l] == FaceClass::none) u[l] = 0.0;
      }
    }
  }
  const auto& gas_faces = m_discretization.faces(gas);
  for (std::size_t l = 0; l < local; ++l) {
    if (gas_faces.pressure_boundary[l]) state.gas_pressure[l] = gas_faces.boundary_pressure[l];
    if (layout.kind(static_cast<int>(l)) != grid::CellKind::boundary) continue;
    // What a boundary cell brings in: the inflow's solids, nothing through walls or outlets.
    const auto r = static_cast<std::size_t>(layout.region(static_cast<int>(l)));
    state.solids_fraction[l] =
        regions.types[r] == grid::BoundaryType::mass_inflow ? regions.regions[r].solids_fraction : 0.0;
    state.gas_fraction[l] = 1.0 - state.solids_fraction[l];
  }
}

std::vector<double> FlowSolver::stepped_solids_flux(const run::FlowState& state) const {
  return m_stepped_solids_flux.empty() ? boundary_mass_flux(state, solids) : m_stepped_solids_flux;
}

double FlowSolver::courant_number(const run::FlowState& state, double dt) const {
  const auto& layout = m_discretization.layout();
  double largest = 0.0;
  for (const Phase phase : {gas, solids}) {
    if (!m_settings.moves[phase]) continue;
    const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    for (int d = 0; d < 3; ++d) {
      const auto& u = velocity[static_cast<std::size_t>(d)];
      for (int l = 0; l < layout.owned_count(); ++l) {
        const int n = layout.neighbour(l, 2 * d + 1);
        if (n < 0 || (layout.kind(l) != grid::CellKind::fluid && layout.kind(n) != grid::CellKind::fluid)) continue;
        const double distance = 0.5 * (m_discretization.width(l, d) + m_discretization.width(n, d));
        largest = std::max(largest, std::abs(u[static_cast<std::size_t>(l)]) / distance);
      }
    }
  }
  return layout.comm().max(largest) * dt;
}

std::vector<double> FlowSolver::boundary_mass_flux(const run::FlowState& state, Phase phase) const {
  return solver::boundary_mass_flux(m_discretization, state, phase, m_settings.density[phase]);
}

}  // namespace bagnold::solver
