// The conservative solids update after convergence, and boundary fluxes (solids_conservation.hpp).
#include "solver/simple/solids_conservation.hpp"

#include "solver/simple/face_fractions.hpp"
#include "solver/simple/volume_fraction_correction.hpp"

namespace bagnold::solver {

std::vector<double> boundary_mass_flux(const Discretization& discretization,
                                       const run::FlowState& state, Phase phase, double density) {
  const auto& layout = discretization.layout();
  std::vector<double> flux(discretization.domain().regions.regions.size(), 0.0);
  const auto& velocity = phase == gas ? state.gas_velocity : state.solids_velocity;
  // Each boundary face is counted by the rank owning its fluid cell.
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    for_each_cell_face(discretization, l, [&](const CellFace& f) {
      if (f.neighbour < 0 || layout.kind(f.neighbour) != grid::CellKind::boundary) return;
      const double u = velocity[static_cast<std::size_t>(f.direction)][static_cast<std::size_t>(f.owner)];
      flux[static_cast<std::size_t>(layout.region(f.neighbour))] +=
          f.sign * density * carried_fraction(discretization, state, phase, f.owner, f.direction) * u * f.area;
    });
  }
  layout.comm().sum_in_place(flux);
  return flux;
}

std::vector<double> conserve_solids(const Discretization& discretization, const CarriedFractions& carried,
                                    double density, const run::FlowState& old, double dt,
                                    run::FlowState& state) {
  const auto& layout = discretization.layout();
  const auto& numbering = discretization.cell_numbering();
  const auto& u = state.solids_velocity;
  std::vector<double> stepped = boundary_mass_flux(discretization, state, solids, density);
  std::vector<double> conserved(numbering.owned_locals.size());
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row) {
    const int l = numbering.owned_locals[row];
    double outflow = 0.0;  // net solids volume outflow; each face's flux as its neighbour sees it
    for_each_cell_face(discretization, l, [&](const CellFace& f) {
      outflow += f.sign * f.area * carried(solids, f.direction)[static_cast<std::size_t>(f.owner)] *
                 u[static_cast<std::size_t>(f.direction)][static_cast<std::size_t>(f.owner)];
    });
    conserved[row] = old.solids_fraction[static_cast<std::size_t>(l)] - dt / discretization.volume(l) * outflow;
  }
  for (std::size_t row = 0; row < numbering.owned_locals.size(); ++row)
    state.solids_fraction[static_cast<std::size_t>(numbering.owned_locals[row])] = conserved[row];
  parallel::exchange_halo<double>(layout, state.solids_fraction);
  update_gas_fraction(discretization, state);
  return stepped;
}

}  // namespace bagnold::solver
