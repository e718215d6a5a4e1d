// The granular energy equation (granular_energy_equation.hpp).
#include "solver/simple/granular_energy_equation.hpp"

#include "solver/simple/solids_wall.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bagnold::solver {

GranularEnergyEquation::GranularEnergyEquation(const Discretization& discretization,
                                               const SolverSettings& settings,
                                               const Closures& closures)
    : m_discretization(discretization),
      m_theory(*closures.stress()->granular_energy()),
      m_closure(*closures.stress()),
      m_material(closures.material()),
      m_density(settings.density[solids]),
      m_gas_viscosity(closures.gas_viscosity()),
      m_vacant_fraction(settings.vacant_fraction) {
  const auto& regions = discretization.domain().regions;
  for (std::size_t r = 0; r < regions.regions.size(); ++r) {
    const auto& region = regions.regions[r];
    const bool wall = regions.types[r] == grid::BoundaryType::no_slip_wall ||
                      regions.types[r] == grid::BoundaryType::moving_wall;
    if (wall && region.solids_wall == "johnson-jackson")
      m_walls.emplace_back(models::wall::JohnsonJacksonWall{
          region.specularity, region.wall_restitution, m_closure.packing_limit(m_material)});
    else
      m_walls.emplace_back();
  }
  const auto& numbering = discretization.cell_numbering();
  // BiCGStab with block Jacobi (KrylovSettings' defaults): convection makes it non-symmetric.
  const KrylovSettings energy{.relative_tolerance = linear_relative_tolerance,
                             .absolute_tolerance = linear_absolute_tolerance,
                             .solve_decoupled_rows_directly = true,
                             .default_options = {}};
  m_system = std::make_unique<LinearSystem>(discretization.layout().comm().get(),
                                            discretization.cell_pattern(solids),
                                            numbering.first_row, "granular_energy_", energy);
  m_x.resize(static_cast<std::size_t>(numbering.owned_rows()));
  const auto local = static_cast<std::size_t>(discretization.layout().local_count());
  for (auto* v : {&m_fraction, &m_temperature, &m_drag, &m_slip, &m_pressure_per_temperature,
                  &m_shear, &m_bulk, &m_conductivity, &m_dissipation, &m_slip_production, &m_held})
    v->assign(local, 0.0);
}

void GranularEnergyEquation::evaluate_terms(const run::FlowState& state,
                                            const ClosureFields& closures) {
  const auto& layout = m_discretization.layout();
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const bool fluid = layout.kind(l) == grid::CellKind::fluid;
    m_fraction[i] = fluid ? std::max(state.solids_fraction[i], 0.0) : 0.0;
    m_temperature[i] = fluid ? std::max(state.granular_temperature[i], 0.0) : 0.0;
    m_drag[i] = fluid ? closures.drag[i] : 0.0;
    m_slip[i] = fluid && m_gas_viscosity > 0.0 ? centre_slip_speed(layout, state, l) : 0.0;
  }
  auto span = [](std::vector<double>& v) { return std::span<double>(v); };
  const models::KineticInput in{m_fraction, m_temperature, m_drag, m_slip, m_gas_viscosity};
  models::KineticTerms out{span(m_pressure_per_temperature), span(m_shear), span(m_bulk),
                           span(m_conductivity), span(m_dissipation), span(m_slip_production),
                           span(m_held)};
  m_theory.evaluate(m_material, in, out);
}

std::array<double, 2> GranularEnergyEquation::wall_flux_coefficients(const run::FlowState& state,
                                                                   int l, int face, int r) const {
  const auto& wall = *m_walls[static_cast<std::size_t>(r)];
  const auto& layout = m_discretization.layout();
  const auto& region = m_discretization.domain().regions.regions[static_cast<std::size_t>(r)];
  const double slip = tangential_slip_speed(layout, state, l, parallel::face_direction(face), region.wall_velocity);
  const double phi = m_fraction[static_cast<std::size_t>(l)];
  const double g0 = m_closure.wall_radial_distribution(m_material, phi);
  // q_w scales as √Θ (generation) and Θ^{3/2} (loss): both from the flux at Θ = 1.
  const double loss = -models::wall::johnson_jackson_energy_flux(wall, m_material, phi, g0, 1.0, 0.0);
  const double gain = models::wall::johnson_jackson_energy_flux(wall, m_material, phi, g0, 1.0, slip) + loss;
  return {gain, loss};
}

bool GranularEnergyEquation::solve(const run::FlowState& old, double dt,
                                   const ClosureFields& closures, const CarriedFractions& carried,
                                   run::FlowState& state, IterationSums& sums, WorstCells& worst,
                                   StepResult& record) {
  const Discretization& disc = m_discretization;
  const auto& layout = disc.layout();
  const auto& numbering = disc.cell_numbering();
  const auto& kind = disc.faces(solids).kind;
  const auto& u = state.solids_velocity;
  auto& theta = state.granular_temperature;
  evaluate_terms(state, closures);
  worst.reset(granular_energy);

  double imbalance = 0.0, scale = 0.0;
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row) {
    const int l = numbering.owned_locals[row];
    const auto i = static_cast<std::size_t>(l);
    const double volume = disc.volume(l);
    const double start = std::isfinite(old.granular_temperature[i]) ? std::max(old.granular_temperature[i], 0.0) : 0.0;
    const bool empty = m_held[i] > 0.0 || m_fraction[i] <= m_vacant_fraction;
    const double accumulation = 1.5 * m_density * std::max(old.solids_fraction[i], 0.0) * volume / dt;
    double a_p = 0.0, b = 0.0, neighbours = 0.0;  // neighbours: Σ a_nb Θ*_nb
    std::int64_t columns[7];
    double values[7];
    int count = 0;
    const double t_star = m_temperature[i];
    const double sqrt_t = std::sqrt(t_star);
    for_each_cell_face(disc, l, [&](const CellFace& f) {
      if (f.neighbour >= 0 && layout.kind(f.neighbour) == grid::CellKind::boundary) {
        const int r = layout.region(f.neighbour);
        if (r >= 0 && m_walls[static_cast<std::size_t>(r)]) {
          const auto [gain, loss] = wall_flux_coefficients(state, l, f.face, r);
          b += f.area * (gain * sqrt_t + 0.5 * loss * t_star * sqrt_t);
          a_p += f.area * 1.5 * loss * sqrt_t;
        }
      }
      if (f.of(kind) != FaceClass::unknown) return;
      const double mass_out = m_density * f.area * f.of(carried.value[solids]) * f.sign * f.of(u);
      const double inflow = 1.5 * std::max(-mass_out, 0.0);
      const bool neighbour_fluid = layout.kind(f.neighbour) == grid::CellKind::fluid;
      double a_nb = 0.0;
      if (neighbour_fluid) {
        const auto n = static_cast<std::size_t>(f.neighbour);
        const double kp = m_conductivity[i], kn = m_conductivity[n];
        const double harmonic = kp + kn > 0.0 ? 2.0 * kp * kn / (kp + kn) : 0.0;
        const double distance = 0.5 * (disc.width(l, f.direction) + disc.width(f.neighbour, f.direction));
        a_nb = inflow + harmonic * f.area / distance;
        neighbours += a_nb * m_temperature[n];
        columns[count] = numbering.global[n];
        values[count++] = empty ? 0.0 : -a_nb;
      }
      a_p += neighbour_fluid ? a_nb : inflow;  // an inflow opening brings Θ = 0
    });
    const double divergence = closures.divergence[solids][i];
    const double rate2 = closures.strain_rate[i] * closures.strain_rate[i];
    const double c = m_dissipation[i];
    a_p += accumulation +
           volume * (m_pressure_per_temperature[i] * std::max(divergence, 0.0) + 1.5 * c * sqrt_t + 3.0 * m_drag[i]);
    b += accumulation * start +
         volume * (m_pressure_per_temperature[i] * t_star * std::max(-divergence, 0.0) +
                   m_shear[i] * std::max(rate2 - (2.0 / 3.0) * divergence * divergence, 0.0) +
                   m_bulk[i] * divergence * divergence + 0.5 * c * t_star * sqrt_t + m_slip_production[i]);
    if (empty) {  // Θ = 0, the row scaled like a filled cell's
      a_p = 1.5 * m_density * volume / dt;
      b = 0.0;
      neighbours = 0.0;
    }
    const double residual = std::abs(b + neighbours - a_p * t_star);
    imbalance += residual;
    scale += std::max(std::abs(a_p * t_star), std::abs(b));
    worst.record(granular_energy, residual, l);
    columns[count] = numbering.global[i];
    values[count++] = a_p;
    m_system->set_row(numbering.global[i], columns, values, count, b);
    m_x[row] = t_star;
  }
  sums.energy[0] += imbalance;
  sums.energy[1] += scale;

  const SolveReport report = m_system->solve(m_x);
  record.linear_iterations[energy_system] += report.iterations;
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row) {
    double value = m_x[row];
    if (value < 0.0) {
      sums.interventions[temperature_clamped_at_zero] += 1.0;
      value = 0.0;
    }
    theta[static_cast<std::size_t>(numbering.owned_locals[row])] = value;
  }
  parallel::exchange_halo<double>(layout, theta);
  if (!report.converged)
    record.failure = "the granular energy equation's linear solve did not converge (" + report.reason + ")";
  return report.converged;
}

}  // namespace bagnold::solver
