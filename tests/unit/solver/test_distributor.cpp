// A fluidized bed's gas distributor is a `mass_inflow` region with solids_fraction = 0 and
// solids_velocity = 0 (docs/solver.md, "Boundary conditions"): the gas comes in at its velocity
// through every face of the region, the solids see a no-slip wall there (their normal face
// velocity is fixed at 0 and their tangential velocity sees a wall at rest). Asserted on the
// faces each phase's momentum equations use, and over steps of a bed on the distributor: the
// gas brings ρ_g U A per second, no solids cross the floor and the solids inventory stays. On 1
// and 2 ranks.
#include <gtest/gtest.h>

#include "solver/simple/flow_solver.hpp"
#include "src/run/initial_state.hpp"
#include "tests/support/petsc_environment.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

const std::string distributor =
    "[[boundary]]\nname = \"distributor\"\ntype = \"mass_inflow\"\nface = \"z-\"\n"
    "gas_velocity = [0.0, 0.0, 0.25]\nsolids_velocity = [0.0, 0.0, 0.0]\nsolids_fraction = 0.0\n"
    "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\n";

// 2 × 1 × 8 cells of 1 cm, periodic in x and y: only the floor and the top are boundaries. A
// bed in the lower half, the gas pressure carrying its weight from the start.
std::string bed_column() {
  return unit_deck(2, 1, 8, "\"x\", \"y\"", -9.81,
                   two_fluid() + distributor + tight_linear_solves +
                       "[[initial]]\nmax = [1.0, 1.0, 0.04]\nsolids_fraction = 0.5\n");
}
const std::vector<std::string> bed_weight = {"gas.initial_pressure=\"bed-weight\""};

TEST(Distributor, GasComesInTheSolidsSeeAWall) {
  const Case c(bed_column(), bed_weight);
  const auto& gas = c.disc.faces(solver::gas);
  const auto& solids = c.disc.faces(solver::solids);
  const auto& layout = c.layout();
  int floor_faces = 0, tangential = 0;
  for (int l = 0; l < layout.local_count(); ++l) {
    const auto i = static_cast<std::size_t>(l);
    const auto ijk = layout.index3(l);
    if (layout.kind(l) == grid::CellKind::boundary && ijk[2] == -1) {
      // The face between the ring cell under the floor and the first fluid layer.
      EXPECT_EQ(gas.kind[2][i], solver::FaceClass::fixed);
      EXPECT_EQ(solids.kind[2][i], solver::FaceClass::fixed);
      EXPECT_EQ(gas.fixed_value[2][i], 0.25);
      EXPECT_EQ(solids.fixed_value[2][i], 0.0);
      ++floor_faces;
    }
    if (layout.kind(l) == grid::CellKind::fluid && ijk[2] == 0 && solids.kind[0][i] == solver::FaceClass::unknown) {
      // An x velocity of the first layer: across the floor (face z−, index 4), a wall at rest.
      const auto& link = solids.links[0][6 * i + 4];
      EXPECT_EQ(link.kind, solver::LinkKind::wall);
      EXPECT_EQ(link.value, 0.0);
      EXPECT_EQ(gas.links[0][6 * i + 4].kind, solver::LinkKind::wall);
      ++tangential;
    }
  }
  EXPECT_EQ(c.sum(floor_faces), 2.0);
  EXPECT_EQ(c.sum(tangential), 2.0);
}

TEST(Distributor, ABedOnItTakesTheGasAndKeepsItsSolids) {
  Case c(bed_column(), bed_weight);
  EXPECT_EQ(c.deck.gas.initial_pressure, "bed-weight");
  solver::FlowSolver flow(c.deck, c.domain);
  run::set_initial_state(c.deck, c.domain, c.state);
  flow.apply_boundary_values(c.state);
  const double before = c.solids_volume(c.state);
  ASSERT_GT(before, 0.0);
  const double area = 0.02 * 0.01;
  for (int step = 0; step < 5; ++step) {
    c.old = c.state;
    const auto result = flow.advance(c.state, c.old, 1e-3);
    ASSERT_TRUE(result.converged) << result.failure;
    const auto gas_flux = flow.boundary_mass_flux(c.state, solver::gas);
    const auto solids_flux = flow.stepped_solids_flux(c.state);
    // Region 0 is the distributor (positive out of the domain).
    EXPECT_NEAR(gas_flux[0], -1.2 * 0.25 * area, 1e-12 * 1.2 * 0.25 * area);
    EXPECT_EQ(solids_flux[0], 0.0);
  }
  EXPECT_NEAR(c.solids_volume(c.state), before, 1e-12 * before);
}

}  // namespace
}  // namespace bagnold::tests
