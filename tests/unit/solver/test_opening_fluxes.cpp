// numerics.copy_fluxes_into_openings (solver/simple/momentum_assembly.cpp): a pressure opening's
// outside cell carries its fluid neighbour's face fluxes in the momentum equations' convection,
// as MFIX's SET_OUTFLOW_FLUXES makes its outflow cells do. On a 3 × 3 × 3 box with a hole in the
// middle of its floor, solids sliding sideways into the cell over the hole and out through it:
// the hole face's z-row takes in, through the east face of its control volume, the cell's
// sideways flux over the whole height (half of it, the half in the fluid cell, without the key),
// and through its top face the flux of the cell's top face (the mean of the hole's and the top
// face's without it). With the material moving down no other z-row's diagonal changes (the row
// above the hole's takes the copied flux through its lower face, which is an outflow there).
// The cell's west face carries an inflow too: the hole cell's west face belongs to the wall cell
// beside it, so that flux must not be copied. On 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/simple/face_fractions.hpp"
#include "solver/simple/momentum_rows.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::solids;

constexpr double dt = 1e-3;                    // [s]
constexpr double fraction = 0.5;               // ε_s everywhere
constexpr double w_hole = -0.4, w_top = -0.2;  // w_s on the hole's face and the cell's top face [m/s]
constexpr double u_east = -0.3;                // u_s on the east face of the cell over the hole [m/s]
constexpr double u_west = 0.25;                // u_s on its west face [m/s]

bool near(const std::array<double, 3>& x, double a, double b, double c) {
  return std::abs(x[0] - a) < 1e-12 && std::abs(x[1] - b) < 1e-12 && std::abs(x[2] - c) < 1e-12;
}

// The solids z-rows of the box, with the velocities above on its unknown faces and 0 elsewhere.
struct HoleRows {
  explicit HoleRows(bool copy_fluxes)
      : c(box_with_a_hole(std::string("copy_fluxes_into_openings = ") + (copy_fluxes ? "true" : "false"))), carried(static_cast<std::size_t>(c.local_count())) {
    for (int l = 0; l < c.local_count(); ++l) {
      const auto i = static_cast<std::size_t>(l);
      c.state.solids_fraction[i] = fraction;
      for (int d = 0; d < 3; ++d) {
        const bool unknown = c.disc.faces(solids).kind[static_cast<std::size_t>(d)][i] == solver::FaceClass::unknown;
        double v = 0.0;
        if (unknown && d == 2 && near(c.face_position(l, 2), 0.015, 0.015, 0.0)) v = w_hole;
        if (unknown && d == 2 && near(c.face_position(l, 2), 0.015, 0.015, 0.01)) v = w_top;
        if (unknown && d == 0 && near(c.face_position(l, 0), 0.02, 0.015, 0.005)) v = u_east;
        if (unknown && d == 0 && near(c.face_position(l, 0), 0.01, 0.015, 0.005)) v = u_west;
        c.state.solids_velocity[static_cast<std::size_t>(d)][i] = v;
      }
    }
    c.old = c.state;
    const solver::ClosureFields fields(static_cast<std::size_t>(c.local_count()));
    const std::array<std::vector<double>, 3> no_source;
    solver::carry_all_fractions(c.disc, c.state, carried);
    const solver::MomentumAssemblyInputs in{c.disc, c.settings, c.old, dt, fields, carried, no_source};
    solver::MomentumAssemblyScratch scratch;
    solver::assemble_momentum_rows(in, solids, 2, c.state, nullptr, true, rows, scratch);
  }
  Case c;
  solver::CarriedFractions carried;
  std::vector<solver::MomentumRow> rows;
};

TEST(OpeningFluxes, TheHolesFaceTakesInTheCellsSidewaysFluxOverItsWholeHeight) {
  HoleRows own(false), copied(true);
  ASSERT_EQ(own.rows.size(), copied.rows.size());
  const double rho = own.c.settings.density[solids], width = 0.01, area = width * width;
  ASSERT_GT(rho, 0.0);
  const auto& numbering = own.c.disc.velocity_numbering(2);
  int hole_rows = 0;
  for (std::size_t r = 0; r < own.rows.size(); ++r) {
    const auto x = own.c.face_position(numbering.owned_locals[r], 2);
    const double change = copied.rows[r].a - own.rows[r].a;
    if (!near(x, 0.015, 0.015, 0.0)) {
      EXPECT_EQ(change, 0.0) << "z-row at " << x[0] << ", " << x[1] << ", " << x[2];
      continue;
    }
    ++hole_rows;
    // East face: the sideways inflow ρ ε |u| on the half of the face in the hole cell too.
    const double east = rho * fraction * -u_east * (0.5 * width) * width;
    // Top face: inflow ρ ε |w_top| A instead of ρ ε ½|w_hole + w_top| A.
    const double top = rho * fraction * area * (-w_top - 0.5 * -(w_hole + w_top));
    EXPECT_NEAR(change, east + top, 1e-12 * rho) << "east " << east << ", top " << top;
    EXPECT_GT(std::abs(east + top), 1e-3 * rho * area);
  }
  EXPECT_EQ(own.c.sum(static_cast<double>(hole_rows)), 1.0);
}

}  // namespace
}  // namespace bagnold::tests
