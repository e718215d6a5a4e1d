// Step 0 of the outer iteration: drag and solids stress at cell centres (closures.hpp).
#include "solver/simple/closures.hpp"

#include <algorithm>
#include <cmath>

#include "solver/simple/solids_wall.hpp"
#include "src/deck/choices.hpp"
#include "solver/strain_rate.hpp"

namespace bagnold::solver {

double centre_slip_speed(const parallel::Layout& layout, const run::FlowState& state, int l) {
  double slip2 = 0.0;
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const double relative = centre_velocity(layout, state.gas_velocity[ud], l, d) -
                            centre_velocity(layout, state.solids_velocity[ud], l, d);
    slip2 += relative * relative;
  }
  return std::sqrt(slip2);
}

Closures::Closures(const deck::Deck& deck, const Discretization& discretization)
    : m_material(deck.solids.material),
      m_drag_properties{deck.gas.density, deck.gas.viscosity, deck.solids.material.diameter,
                        deck.solids.material.density},
      m_gas_viscosity(deck.gas.viscosity),
      m_relaxation_time(deck.numerics.pressure_shear_rate_relaxation_time),
      m_bulk_viscosity_ratio(deck.numerics.solids_bulk_viscosity_ratio),
      m_bulk_viscosity_until(deck.numerics.solids_bulk_viscosity_until),
      m_gas_moves(deck.gas.enabled),
      m_newton(deck::choice_value(deck::viscosity_linearization_choices,
                                  deck.numerics.viscosity_linearization, "viscosity linearization") ==
               deck::ViscosityLinearization::newton),
      m_keep_tensor(m_newton || deck.numerics.step_solver == "newton") {
  const auto& domain = discretization.domain();
  if (deck.solids.enabled && deck.gas.enabled)
    m_drag = models::drag_registry().create(deck.models.drag.name, deck.models.drag.coefficients);
  if (deck.solids.enabled && deck.solids.momentum) {
    m_stress = models::stress_registry().create(deck.models.solids_stress.name,
                                                deck.models.solids_stress.coefficients);
    // A stationary wall whose law does not let the solids slip puts its shear into γ̇.
    const auto laws = solids_wall_laws(deck, domain.regions, *m_stress);
    std::vector<bool> regions;
    for (std::size_t r = 0; r < laws.size(); ++r)
      regions.push_back(deck.numerics.wall_shear_in_strain_rate &&
                        domain.regions.types[r] == grid::BoundaryType::no_slip_wall && !laws[r]->slips());
    m_strain_rate_ghosts = strain_rate_ghosts(domain, regions, deck.numerics.wall_shear_beside_openings,
                                          deck.numerics.copy_velocity_into_openings);
  }
  // Outflow cells whose P_s is their fluid neighbour's (solids_pressure = "zero-gradient").
  const auto& layout = discretization.layout();
  for (int b = 0; b < layout.local_count(); ++b) {
    if (layout.kind(b) != grid::CellKind::boundary) continue;
    const auto r = static_cast<std::size_t>(layout.region(b));
    if (domain.regions.types[r] != grid::BoundaryType::pressure_outflow ||
        domain.regions.regions[r].solids_pressure != "zero-gradient")
      continue;
    for (int face = 0; face < 6; ++face) {
      const int f = layout.neighbour(b, face);
      if (f >= 0 && layout.kind(f) == grid::CellKind::fluid) {
        m_outflow_copies.emplace_back(b, f);
        break;
      }
    }
  }
  const auto local = static_cast<std::size_t>(layout.local_count());
  m_cells.reserve(local);
  for (auto* v : {&m_fraction, &m_rate, &m_pressure_rate, &m_divergence, &m_slip, &m_pressure,
                  &m_derivative, &m_shear, &m_bulk, &m_temperature, &m_transported, &m_drag_at,
                  &m_unused[0], &m_unused[1], &m_unused[2]})
    v->resize(local);
  if (m_keep_tensor)
    for (auto* v : {&m_probe_rate, &m_probe_divergence, &m_probe_shear}) v->resize(local);
}

void Closures::evaluate(const Discretization& discretization, run::FlowState& state,
                        const run::FlowState& old, double dt, ClosureFields& fields) {
  if (m_drag) evaluate_drag(discretization, state, fields);
  evaluate_solids_stress(discretization, state, old, dt, fields);
}

void Closures::evaluate_drag(const Discretization& discretization, const run::FlowState& state,
                             ClosureFields& fields) {
  const auto& layout = discretization.layout();
  m_cells.clear();
  for (int l = 0; l < layout.local_count(); ++l) {
    fields.drag[static_cast<std::size_t>(l)] = 0.0;
    if (layout.kind(l) != grid::CellKind::fluid) continue;
    const std::size_t k = m_cells.size();
    m_cells.push_back(l);
    m_fraction[k] = state.gas_fraction[static_cast<std::size_t>(l)];
    m_slip[k] = centre_slip_speed(layout, state, l);
  }
  const std::size_t n = m_cells.size();
  const std::span<double> beta(m_pressure.data(), n);
  m_drag->evaluate(m_drag_properties, {std::span(m_fraction.data(), n), std::span(m_slip.data(), n)}, beta);
  for (std::size_t i = 0; i < n; ++i) fields.drag[static_cast<std::size_t>(m_cells[i])] = beta[i];
}

void Closures::evaluate_solids_stress(const Discretization& discretization, run::FlowState& state,
                                      const run::FlowState& old, double dt, ClosureFields& fields) {
  const auto& layout = discretization.layout();
  for (int l = 0; l < layout.local_count(); ++l)
    fields.viscosity[gas][static_cast<std::size_t>(l)] = state.gas_fraction[static_cast<std::size_t>(l)] * m_gas_viscosity;
  if (m_gas_moves) velocity_divergence(discretization, state.gas_velocity, fields.divergence[gas]);
  if (!m_stress) return;

  compute_strain_rate(discretization, state.solids_velocity, fields.strain_rate,
                      fields.divergence[solids], m_strain_rate_ghosts, m_keep_tensor ? &m_tensor : nullptr);
  const double weight = m_relaxation_time > 0.0 ? dt / m_relaxation_time : 0.0;
  const bool transported = m_stress->granular_energy() != nullptr;
  m_cells.clear();
  for (int l = 0; l < layout.local_count(); ++l) {
    if (layout.kind(l) != grid::CellKind::fluid) continue;
    const auto i = static_cast<std::size_t>(l);
    const std::size_t k = m_cells.size();
    m_cells.push_back(l);
    m_fraction[k] = std::max(state.solids_fraction[i], 0.0);  // round-off below 0 at an emptying cell
    if (transported) {
      m_transported[k] = state.granular_temperature[i];
      m_drag_at[k] = fields.drag[i];
    }
    m_rate[k] = fields.strain_rate[i];
    m_divergence[k] = fields.divergence[solids][i];
    const double before = old.pressure_shear_rate[i];
    m_pressure_rate[k] = m_relaxation_time > 0.0 && std::isfinite(before)
                             ? (before + weight * fields.strain_rate[i]) / (1.0 + weight)
                             : fields.strain_rate[i];
  }
  const std::size_t n = m_cells.size();
  auto part = [n](std::vector<double>& v) { return std::span<double>(v.data(), n); };
  auto input = [n](const std::vector<double>& v) { return std::span<const double>(v.data(), n); };
  models::SolidsStress out{part(m_pressure), part(m_derivative), part(m_shear), part(m_bulk),
                           part(m_temperature)};
  models::SolidsState in{input(m_fraction), input(m_rate), input(m_divergence)};
  if (transported) {
    in.temperature = input(m_transported);
    in.drag = input(m_drag_at);
  }
  m_stress->evaluate(m_material, in, out);
  if (m_relaxation_time > 0.0) {
    // P_s and dP_s/dε_s at γ̇_P; the other outputs of this call are not used.
    models::SolidsStress at_relaxed_rate{part(m_pressure), part(m_derivative), part(m_unused[0]),
                                         part(m_unused[1]), part(m_unused[2])};
    models::SolidsState relaxed = in;
    relaxed.strain_rate = input(m_pressure_rate);
    m_stress->evaluate(m_material, relaxed, at_relaxed_rate);
  }
  const double ratio = m_step_start < m_bulk_viscosity_until ? m_bulk_viscosity_ratio : 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(m_cells[k]);
    state.solids_pressure[i] = m_pressure[k];
    state.pressure_shear_rate[i] = m_pressure_rate[k];
    state.granular_temperature[i] = m_temperature[k];
    fields.pressure_derivative[i] = m_derivative[k];
    fields.viscosity[solids][i] = m_shear[k];
    fields.bulk_viscosity[i] = m_bulk[k] + ratio * m_shear[k];
  }
  for (const auto& [outflow, fluid] : m_outflow_copies)
    state.solids_pressure[static_cast<std::size_t>(outflow)] = state.solids_pressure[static_cast<std::size_t>(fluid)];
  m_last_input = in;
  if (m_newton) evaluate_tangent_factors(fields);
}

void Closures::evaluate_flow_index(ClosureFields& fields) {
  // μ_s at the same state with D scaled by 1 + h: n − 1 = dln μ_s/dln γ̇ by a forward difference
  // (the closures have kinks, a cap among them; n is then that of the side the iterate is on).
  constexpr double h = 1e-4;
  const models::SolidsState& in = m_last_input;
  const std::size_t n = m_cells.size();
  auto part = [n](std::vector<double>& v) { return std::span<double>(v.data(), n); };
  for (std::size_t k = 0; k < n; ++k) {
    m_probe_rate[k] = (1.0 + h) * m_rate[k];
    m_probe_divergence[k] = (1.0 + h) * m_divergence[k];
  }
  models::SolidsState probe = in;
  probe.strain_rate = std::span<const double>(m_probe_rate.data(), n);
  probe.divergence = std::span<const double>(m_probe_divergence.data(), n);
  // Only μ_s is read from this evaluation; the other outputs land in scratch already copied out.
  models::SolidsStress out{part(m_unused[0]), part(m_unused[1]), part(m_probe_shear),
                           part(m_unused[2]), part(m_temperature)};
  m_stress->evaluate(m_material, probe, out);
  const std::size_t local = fields.strain_rate.size();
  fields.flow_index.assign(local, 1.0);
  for (auto& component : fields.strain_direction) component.assign(local, 0.0);
  const double log_step = std::log1p(h);
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(m_cells[k]);
    const double mu = m_shear[k], mu_probe = m_probe_shear[k], rate = fields.strain_rate[i];
    if (!(mu > 0.0 && mu_probe > 0.0 && rate > 0.0)) continue;
    // n ≥ 0: a stress that falls with the rate would make the implicit viscosity negative.
    fields.flow_index[i] = std::max(1.0 + std::log(mu_probe / mu) / log_step, 0.0);
    for (int c = 0; c < 6; ++c)
      fields.strain_direction[static_cast<std::size_t>(c)][i] = m_tensor[static_cast<std::size_t>(c)][i] / rate;
  }
}

void tangent_factors(const ClosureFields& fields, const std::array<std::vector<double>, 6>& direction,
                     std::array<std::vector<double>, 6>& factors) {
  const std::size_t local = fields.flow_index.size();
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) {
      const auto c = static_cast<std::size_t>(symmetric_component(a, b));
      auto& factor = factors[c];
      factor.resize(local);
      const double weight = a == b ? 2.0 : 4.0;  // 2 N:δD counts an off-diagonal pair twice
      for (std::size_t i = 0; i < local; ++i)
        factor[i] = 1.0 + weight * (fields.flow_index[i] - 1.0) * fields.strain_direction[c][i] * direction[c][i];
    }
}

void Closures::evaluate_tangent_factors(ClosureFields& fields) {
  evaluate_flow_index(fields);
  tangent_factors(fields, fields.strain_direction, fields.tangent_factor);
}

}  // namespace bagnold::solver
