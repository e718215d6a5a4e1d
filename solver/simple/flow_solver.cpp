#include "solver/simple/flow_solver.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

const char* equation_name(int equation) {
  static const char* names[equation_count] = {
      "gas x momentum",    "gas y momentum",    "gas z momentum",      "solids x momentum",
      "solids y momentum", "solids z momentum", "mixture continuity", "solids continuity"};
  return equation >= 0 && equation < equation_count ? names[equation] : "unknown equation";
}

double Residuals::largest() const { return value[static_cast<std::size_t>(worst())]; }

int Residuals::worst() const {
  int worst = 0;
  for (int e = 1; e < equation_count; ++e)
    if (!(value[static_cast<std::size_t>(e)] <= value[static_cast<std::size_t>(worst)])) worst = e;
  return worst;
}

FlowSolver::FlowSolver(const deck::Deck& deck, const parallel::Domain& domain)
    : m_deck(deck),
      m_domain(domain),
      m_limiter(limiter_from_name(deck.numerics.convection)),
      m_simplec(deck.numerics.algorithm == "simplec"),
      m_residual_normalization(residual_normalization_from_name(deck.numerics.residual_normalization)),
      m_bulk_viscosity_ratio(deck.numerics.solids_bulk_viscosity_ratio) {
  const auto& layout = domain.layout;
  const auto local = static_cast<std::size_t>(layout.local_count());
  m_moves[gas] = deck.gas.enabled;
  m_moves[solids] = deck.solids.enabled && deck.solids.momentum;
  m_faces[gas] = std::make_unique<VelocityFaces>(domain, false);
  m_faces[solids] = std::make_unique<VelocityFaces>(domain, true);
  m_width.resize(3 * local);
  for (std::size_t l = 0; l < local; ++l) {
    const auto ijk = layout.index3(static_cast<int>(l));
    for (int d = 0; d < 3; ++d)
      m_width[3 * l + static_cast<std::size_t>(d)] = domain.grid.axis(d).width(ijk[static_cast<std::size_t>(d)]);
  }
  const MPI_Comm comm = layout.comm().get();
  KrylovSettings momentum;
  momentum.ksp_type = "bcgs";
  momentum.pc_type = "bjacobi";
  momentum.relative_tolerance = deck.numerics.momentum_tolerance;
  const char* prefixes[2][3] = {{"momentum_x_", "momentum_y_", "momentum_z_"},
                                {"solids_momentum_x_", "solids_momentum_y_", "solids_momentum_z_"}};
  for (int d = 0; d < 3; ++d) {
    const auto ud = static_cast<std::size_t>(d);
    const auto& kind = faces(gas).kind[ud];
    m_velocity_numbering[ud] = std::make_unique<UnknownNumbering>(
        layout, [&](int l) { return kind[static_cast<std::size_t>(l)] == FaceClass::unknown; });
    const auto& n = *m_velocity_numbering[ud];
    for (int phase = 0; phase < 2; ++phase) {
      m_d[static_cast<std::size_t>(phase)][ud].assign(local, 0.0);
      if (m_moves[static_cast<std::size_t>(phase)])
        m_momentum_system[static_cast<std::size_t>(phase)][ud] = std::make_unique<LinearSystem>(
            comm, n.owned_rows(), n.first_row, prefixes[phase][d], momentum);
    }
    m_e[ud].assign(local, 0.0);
  }
  // Reference speed: the fastest boundary velocity, or the free-fall speed over the domain.
  double extent = 0.0, gravity = 0.0;
  for (int d = 0; d < 3; ++d) {
    extent = std::max(extent, domain.grid.axis(d).faces().back() - domain.grid.axis(d).faces().front());
    gravity += deck.physics.gravity[static_cast<std::size_t>(d)] * deck.physics.gravity[static_cast<std::size_t>(d)];
  }
  m_gravity = std::sqrt(gravity);
  m_reference_speed = std::sqrt(m_gravity * extent);
  for (const auto& region : domain.regions.regions)
    for (int d = 0; d < 3; ++d)
      m_reference_speed = std::max({m_reference_speed, std::abs(region.wall_velocity[static_cast<std::size_t>(d)]),
                                    std::abs(region.gas_velocity[static_cast<std::size_t>(d)]),
                                    std::abs(region.solids_velocity[static_cast<std::size_t>(d)])});
  if (m_reference_speed <= 0.0) m_reference_speed = 1.0;
  double faces_area = 0.0;
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    for (int d = 0; d < 3; ++d) faces_area += face_area(l, d);  // ½ Σ over the 6 faces
  m_reference_area = layout.comm().sum(faces_area);
  m_beta.assign(local, 0.0);
  m_viscosity[gas].assign(local, 0.0);
  m_viscosity[solids].assign(local, 0.0);
  m_pressure_derivative.assign(local, 0.0);
  if (deck.solids.enabled && deck.gas.enabled)
    m_drag = models::drag_registry().create(deck.models.drag.name, deck.models.drag.coefficients);
  if (m_moves[solids]) {
    m_stress = models::stress_registry().create(deck.models.solids_stress.name,
                                                deck.models.solids_stress.coefficients);
    m_solids_walls = std::make_unique<SolidsWalls>(deck, domain.regions.regions,
                                                   m_stress->defines_temperature());
    if (m_solids_walls->any_partial())
      for (auto& held : m_wall_coefficients) held.assign(6 * local, 0.0);
    if (deck.numerics.wall_shear_in_strain_rate) {
      const auto& regions = domain.regions;
      for (std::size_t r = 0; r < regions.regions.size(); ++r)
        m_no_slip_strain_regions.push_back(regions.types[r] == grid::BoundaryType::no_slip_wall &&
                                           !m_solids_walls->partial(static_cast<int>(r)));
    }
  }
  m_pressure_numbering = std::make_unique<UnknownNumbering>(
      layout, [&](int l) { return layout.kind(l) == grid::CellKind::fluid; });
  if (m_moves[gas]) {
    KrylovSettings pressure;
    pressure.ksp_type = "cg";
    pressure.pc_type = deck.numerics.pressure_preconditioner;
    pressure.relative_tolerance = deck.numerics.pressure_tolerance;
    pressure.constant_null_space = !faces(gas).has_pressure_boundary;
    m_pressure_system = std::make_unique<LinearSystem>(
        comm, m_pressure_numbering->owned_rows(), m_pressure_numbering->first_row, "pressure_", pressure);
  }
  if (m_moves[solids]) {
    KrylovSettings fraction;  // convection makes it non-symmetric
    fraction.ksp_type = "bcgs";
    fraction.pc_type = "bjacobi";
    fraction.relative_tolerance = 1e-8;
    fraction.absolute_tolerance = 1e-14;
    m_fraction_system = std::make_unique<LinearSystem>(
        comm, m_pressure_numbering->owned_rows(), m_pressure_numbering->first_row, "solids_fraction_", fraction);
  }
}

double FlowSolver::density(Phase phase) const {
  return phase == gas ? m_deck.gas.density : m_deck.solids.material.density;
}

double FlowSolver::residual_velocity_scale(const run::FlowState& state) const {
  const auto& layout = m_domain.layout;
  double largest = 0.0;
  for (const auto* velocity : {&state.gas_velocity, &state.solids_velocity})
    for (const auto& component : *velocity)
      for (int l = 0; l < layout.owned_count(); ++l)
        largest = std::max(largest, std::abs(component[static_cast<std::size_t>(l)]));
  return std::max(layout.comm().max(largest), 1e-3 * m_reference_speed);
}

void FlowSolver::record_worst(int equation, double row_residual, int local) {
  const auto e = static_cast<std::size_t>(equation);
  if (!(row_residual <= m_worst_value[e])) {  // NaN is the worst
    m_worst_value[e] = std::isnan(row_residual) ? INFINITY : row_residual;
    m_worst_local[e] = local;
  }
}

CellLocation FlowSolver::worst_cell(int equation) const {
  const auto& layout = m_domain.layout;
  const auto e = static_cast<std::size_t>(equation);
  struct {
    double value;
    int rank;
  } mine{m_worst_local[e] >= 0 ? m_worst_value[e] : -1.0, layout.comm().rank()}, worst{};
  MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, layout.comm().get());
  std::int64_t natural = m_worst_local[e] >= 0 ? layout.natural(m_worst_local[e]) : 0;
  MPI_Bcast(&natural, 1, MPI_INT64_T, worst.rank, layout.comm().get());
  CellLocation where;
  where.cell = m_domain.grid.index3(natural);
  where.position = m_domain.grid.centre(where.cell);
  return where;
}

double FlowSolver::face_fraction(const run::FlowState& state, Phase phase, int local, int d) const {
  const auto& eps = phase == gas ? state.gas_fraction : state.solids_fraction;
  const int n = m_domain.layout.neighbour(local, 2 * d + 1);
  if (n < 0) return eps[static_cast<std::size_t>(local)];
  const auto& layout = m_domain.layout;
  if (layout.kind(local) == grid::CellKind::boundary || layout.kind(n) == grid::CellKind::boundary) {
    // A boundary face carries what flows through it: an inlet's own fraction coming in, the
    // fluid cell's going out (the mean of the two would feed a bed only half its inflow's gas).
    const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    const double u = velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
    const bool local_is_fluid = layout.kind(local) != grid::CellKind::boundary;
    const bool from_local = u > 0.0 || (u == 0.0 && local_is_fluid);
    return eps[static_cast<std::size_t>(from_local ? local : n)];
  }
  const double wc = width(local, d), wn = width(n, d);
  return (eps[static_cast<std::size_t>(local)] * wn + eps[static_cast<std::size_t>(n)] * wc) /
         (wc + wn);
}

double FlowSolver::flux_fraction(const run::FlowState& state, Phase phase, int local, int d) const {
  if (phase == gas) return face_fraction(state, gas, local, d);
  const int n = m_domain.layout.neighbour(local, 2 * d + 1);
  const double u = state.solids_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(local)];
  const int upwind = (u >= 0.0 || n < 0) ? local : n;
  return state.solids_fraction[static_cast<std::size_t>(upwind)];
}

bool FlowSolver::solids_present(const run::FlowState& state, int local, int d) const {
  const int n = m_domain.layout.neighbour(local, 2 * d + 1);
  const auto& eps = state.solids_fraction;
  return eps[static_cast<std::size_t>(local)] > solids_threshold ||
         (n >= 0 && eps[static_cast<std::size_t>(n)] > solids_threshold);
}

void FlowSolver::evaluate_drag(const run::FlowState& state) {
  if (!m_drag) return;
  const auto& layout = m_domain.layout;
  std::vector<double> fraction, slip;
  std::vector<int> cells;
  for (int l = 0; l < layout.local_count(); ++l) {
    m_beta[static_cast<std::size_t>(l)] = 0.0;
    if (layout.kind(l) != grid::CellKind::fluid) continue;
    double slip2 = 0.0;  // |u_g − u_s|² at the centre, from the two faces of each direction
    for (int d = 0; d < 3; ++d) {
      const int minus = layout.neighbour(l, 2 * d);
      auto centred = [&](const std::vector<double>& u) {
        return 0.5 * (u[static_cast<std::size_t>(l)] + (minus >= 0 ? u[static_cast<std::size_t>(minus)] : 0.0));
      };
      const double relative = centred(state.gas_velocity[static_cast<std::size_t>(d)]) -
                              centred(state.solids_velocity[static_cast<std::size_t>(d)]);
      slip2 += relative * relative;
    }
    cells.push_back(l);
    fraction.push_back(state.gas_fraction[static_cast<std::size_t>(l)]);
    slip.push_back(std::sqrt(slip2));
  }
  std::vector<double> beta(cells.size());
  const models::DragProperties properties{m_deck.gas.density, m_deck.gas.viscosity,
                                          m_deck.solids.material.diameter,
                                          m_deck.solids.material.density};
  m_drag->evaluate(properties, {fraction, slip}, beta);
  for (std::size_t i = 0; i < cells.size(); ++i) m_beta[static_cast<std::size_t>(cells[i])] = beta[i];
}

double FlowSolver::face_area(int local, int d) const {
  return width(local, (d + 1) % 3) * width(local, (d + 2) % 3);
}

void FlowSolver::apply_boundary_values(run::FlowState& state) const {
  const auto& layout = m_domain.layout;
  const auto local = static_cast<std::size_t>(layout.local_count());
  for (int phase = 0; phase < 2; ++phase) {
    auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
    const auto& f = faces(static_cast<Phase>(phase));
    for (int d = 0; d < 3; ++d) {
      auto& u = velocity[static_cast<std::size_t>(d)];
      const auto& kind = f.kind[static_cast<std::size_t>(d)];
      for (std::size_t l = 0; l < local; ++l) {
        if (kind[l] == FaceClass::fixed) u[l] = f.fixed_value[static_cast<std::size_t>(d)][l];
        if (kind[l] == FaceClass::none) u[l] = 0.0;
      }
    }
  }
  for (std::size_t l = 0; l < local; ++l) {
    if (faces(gas).pressure_boundary[l]) state.gas_pressure[l] = faces(gas).boundary_pressure[l];
    if (layout.kind(static_cast<int>(l)) != grid::CellKind::boundary) continue;
    // What a boundary cell brings in: the inflow's solids, nothing through walls or outlets.
    const auto& region = m_domain.regions.regions[static_cast<std::size_t>(layout.region(static_cast<int>(l)))];
    const auto type = m_domain.regions.types[static_cast<std::size_t>(layout.region(static_cast<int>(l)))];
    state.solids_fraction[l] = type == grid::BoundaryType::mass_inflow ? region.solids_fraction : 0.0;
    state.gas_fraction[l] = 1.0 - state.solids_fraction[l];
  }
}

std::vector<double> FlowSolver::stepped_solids_flux(const run::FlowState& state) const {
  return m_stepped_solids_flux.empty() ? boundary_mass_flux(state, solids) : m_stepped_solids_flux;
}

std::vector<double> FlowSolver::boundary_mass_flux(const run::FlowState& state, Phase phase) const {
  const auto& layout = m_domain.layout;
  std::vector<double> flux(m_domain.regions.regions.size(), 0.0);
  const double rho = density(phase);
  const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
  // Each boundary face is counted by the rank owning its fluid cell.
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    for (int face = 0; face < 6; ++face) {
      const int m = layout.neighbour(l, face);
      if (m < 0 || layout.kind(m) != grid::CellKind::boundary) continue;
      const int d = parallel::face_direction(face);
      const int owner = parallel::face_sign(face) > 0 ? l : m;
      const double u = velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(owner)];
      flux[static_cast<std::size_t>(layout.region(m))] +=
          parallel::face_sign(face) * rho * flux_fraction(state, phase, owner, d) * u * face_area(l, d);
    }
  }
  layout.comm().sum_in_place(flux);
  return flux;
}

}  // namespace bagnold::solver
