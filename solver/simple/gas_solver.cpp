#include "solver/simple/gas_solver.hpp"

#include <algorithm>
#include <cmath>

namespace bagnold::solver {

double Residuals::largest() const {
  return std::max({momentum[0], momentum[1], momentum[2], continuity});
}

GasSolver::GasSolver(const deck::Deck& deck, const parallel::Domain& domain)
    : m_deck(deck),
      m_domain(domain),
      m_faces(deck, domain),
      m_limiter(limiter_from_name(deck.numerics.convection)),
      m_simplec(deck.numerics.algorithm == "simplec") {
  const auto& layout = domain.layout;
  const auto local = static_cast<std::size_t>(layout.local_count());
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
  const char* prefixes[] = {"momentum_x_", "momentum_y_", "momentum_z_"};
  for (int d = 0; d < 3; ++d) {
    const auto& kind = m_faces.kind[static_cast<std::size_t>(d)];
    m_velocity_numbering[static_cast<std::size_t>(d)] = std::make_unique<UnknownNumbering>(
        layout, [&](int l) { return kind[static_cast<std::size_t>(l)] == FaceClass::unknown; });
    const auto& n = *m_velocity_numbering[static_cast<std::size_t>(d)];
    m_momentum_system[static_cast<std::size_t>(d)] =
        std::make_unique<LinearSystem>(comm, n.owned_rows(), n.first_row, prefixes[d], momentum);
    m_d[static_cast<std::size_t>(d)].assign(local, 0.0);
  }
  // Reference speed: the fastest boundary velocity, or the free-fall speed over the domain.
  double extent = 0.0, gravity = 0.0;
  for (int d = 0; d < 3; ++d) {
    extent = std::max(extent, domain.grid.axis(d).faces().back() - domain.grid.axis(d).faces().front());
    gravity += deck.physics.gravity[static_cast<std::size_t>(d)] * deck.physics.gravity[static_cast<std::size_t>(d)];
  }
  m_reference_speed = std::sqrt(std::sqrt(gravity) * extent);
  for (const auto& region : domain.regions.regions)
    for (int d = 0; d < 3; ++d)
      m_reference_speed = std::max({m_reference_speed, std::abs(region.wall_velocity[static_cast<std::size_t>(d)]),
                                    std::abs(region.gas_velocity[static_cast<std::size_t>(d)])});
  if (m_reference_speed <= 0.0) m_reference_speed = 1.0;
  double faces_area = 0.0;
  for (int l = 0; l < layout.owned_fluid_count(); ++l)
    for (int d = 0; d < 3; ++d) faces_area += face_area(l, d);  // ½ Σ over the 6 faces
  m_reference_flux = deck.gas.density * layout.comm().sum(faces_area);
  m_beta.assign(local, 0.0);
  if (deck.solids.enabled)
    m_drag = models::drag_registry().create(deck.models.drag.name, deck.models.drag.coefficients);
  m_pressure_numbering = std::make_unique<UnknownNumbering>(
      layout, [&](int l) { return layout.kind(l) == grid::CellKind::fluid; });
  KrylovSettings pressure;
  pressure.ksp_type = "cg";
  pressure.pc_type = deck.numerics.pressure_preconditioner;
  pressure.relative_tolerance = deck.numerics.pressure_tolerance;
  pressure.constant_null_space = !m_faces.has_pressure_boundary;
  m_pressure_system = std::make_unique<LinearSystem>(
      comm, m_pressure_numbering->owned_rows(), m_pressure_numbering->first_row, "pressure_", pressure);
}

double GasSolver::residual_velocity_scale(const run::FlowState& state) const {
  const auto& layout = m_domain.layout;
  double largest = 0.0;
  for (const auto& component : state.gas_velocity)
    for (int l = 0; l < layout.owned_count(); ++l)
      largest = std::max(largest, std::abs(component[static_cast<std::size_t>(l)]));
  return std::max(layout.comm().max(largest), 1e-3 * m_reference_speed);
}

CellLocation GasSolver::worst_cell(int equation) const {
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

double GasSolver::face_fraction(const run::FlowState& state, int local, int d) const {
  const auto& eps = state.gas_fraction;
  const int n = m_domain.layout.neighbour(local, 2 * d + 1);
  if (n < 0) return eps[static_cast<std::size_t>(local)];
  const double wc = width(local, d), wn = width(n, d);
  return (eps[static_cast<std::size_t>(local)] * wn + eps[static_cast<std::size_t>(n)] * wc) /
         (wc + wn);
}

void GasSolver::evaluate_drag(const run::FlowState& state) {
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

double GasSolver::face_area(int local, int d) const {
  return width(local, (d + 1) % 3) * width(local, (d + 2) % 3);
}

void GasSolver::apply_boundary_values(run::FlowState& state) const {
  const auto local = static_cast<std::size_t>(m_domain.layout.local_count());
  for (int d = 0; d < 3; ++d) {
    auto& u = state.gas_velocity[static_cast<std::size_t>(d)];
    const auto& kind = m_faces.kind[static_cast<std::size_t>(d)];
    for (std::size_t l = 0; l < local; ++l) {
      if (kind[l] == FaceClass::fixed) u[l] = m_faces.fixed_value[static_cast<std::size_t>(d)][l];
      if (kind[l] == FaceClass::none) u[l] = 0.0;
    }
  }
  for (std::size_t l = 0; l < local; ++l)
    if (m_faces.pressure_boundary[l]) state.gas_pressure[l] = m_faces.boundary_pressure[l];
}

std::vector<double> GasSolver::boundary_mass_flux(const run::FlowState& state) const {
  const auto& layout = m_domain.layout;
  std::vector<double> flux(m_domain.regions.regions.size(), 0.0);
  const double rho = m_deck.gas.density;
  // Each boundary face is counted by the rank owning its fluid cell.
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    for (int face = 0; face < 6; ++face) {
      const int m = layout.neighbour(l, face);
      if (m < 0 || layout.kind(m) != grid::CellKind::boundary) continue;
      const int d = parallel::face_direction(face);
      const int owner = parallel::face_sign(face) > 0 ? l : m;
      const double u = state.gas_velocity[static_cast<std::size_t>(d)][static_cast<std::size_t>(owner)];
      flux[static_cast<std::size_t>(layout.region(m))] +=
          parallel::face_sign(face) * rho * face_fraction(state, owner, d) * u * face_area(l, d);
    }
  }
  layout.comm().sum_in_place(flux);
  return flux;
}

}  // namespace bagnold::solver
