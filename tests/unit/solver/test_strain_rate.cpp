// Strain-rate invariants from staggered velocities: exact for linear velocity fields, on uniform
// and stretched grids, with walls (one-sided differences, no-slip and free-slip ghosts), on 1
// and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/strain_rate.hpp"
#include "src/deck/load.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

// Fills face velocities with u = A x (A a constant 3 × 3 matrix), evaluated at each face centre.
std::array<std::vector<double>, 3> linear_field(const parallel::Domain& domain, const double (&a)[3][3]) {
  const auto& layout = domain.layout;
  std::array<std::vector<double>, 3> u;
  for (int d = 0; d < 3; ++d) {
    u[static_cast<std::size_t>(d)].assign(static_cast<std::size_t>(layout.local_count()), 0.0);
    for (int l = 0; l < layout.local_count(); ++l) {
      auto x = domain.grid.centre(layout.index3(l));
      x[static_cast<std::size_t>(d)] = domain.grid.axis(d).upper_face(layout.index3(l)[static_cast<std::size_t>(d)]);
      double value = 0.0;
      for (int b = 0; b < 3; ++b) value += a[d][b] * x[static_cast<std::size_t>(b)];
      u[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = value;
    }
  }
  return u;
}

void expect_exact(const std::string& deck_text, const double (&a)[3][3],
                  const std::vector<std::string>& overrides = {}) {
  const auto deck = deck::load_deck_text(deck_text, "strain.toml", overrides);
  const parallel::Domain domain(deck, parallel::Communicator());
  std::vector<double> gamma_dot, divergence;
  solver::compute_strain_rate(solver::Discretization(domain), linear_field(domain, a), gamma_dot, divergence);
  double dd = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) dd += 0.25 * (a[i][j] + a[j][i]) * (a[i][j] + a[j][i]);
  const double expected_rate = std::sqrt(2.0 * dd);
  const double expected_divergence = a[0][0] + a[1][1] + a[2][2];
  for (int l = 0; l < domain.layout.owned_fluid_count(); ++l) {
    // Round-off of differences of O(1) values over 1 cm cells.
    EXPECT_NEAR(gamma_dot[static_cast<std::size_t>(l)], expected_rate, 1e-9) << "cell " << l;
    EXPECT_NEAR(divergence[static_cast<std::size_t>(l)], expected_divergence, 1e-9);
  }
}

TEST(StrainRate, SimpleShearGivesTheShearRate) {
  // u_x = γ̇ z: γ̇ = sqrt(2 D:D) must return γ̇ itself (model-notes.md, shear-rate convention).
  const double a[3][3] = {{0, 0, 3.0}, {0, 0, 0}, {0, 0, 0}};
  expect_exact(box_deck(5, 4, 6), a);
}

TEST(StrainRate, GeneralLinearFieldIsExactOnAStretchedGrid) {
  const double a[3][3] = {{0.5, -1.0, 2.0}, {0.3, -0.2, 0.7}, {-1.5, 0.4, 0.9}};
  expect_exact(box_deck(6, 5, 7), a, {"grid.z.ratio=3.0", "grid.x.ratio=0.5"});
}

TEST(StrainRate, ExactNextToBlockedCells) {
  const double a[3][3] = {{0, 1.0, 2.0}, {0, 0, 0}, {-2.0, 0, 0}};
  expect_exact(box_deck(6, 4, 6, "[[geometry.block]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\n"
                                 "max = [0.02, 0.04, 0.02]\n"),
               a);
}

// A plug sliding along x: u_x = speed on every face, the other components 0.
std::array<std::vector<double>, 3> plug(const parallel::Domain& domain, double speed) {
  const double still[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  auto u = linear_field(domain, still);
  for (auto& value : u[0]) value = speed;
  return u;
}

// numerics.wall_shear_in_strain_rate: a plug u_x = U sliding over a flagged no-slip wall has the
// wall's shear in the wall cells' γ̇ (the ghost value −u_c a width away, as MFIX's ghost cells):
// γ̇ = (U − (−U)) / (2 w) = U/w in a cell with one wall along z, 0 inside; unflagged, 0 everywhere.
TEST(StrainRate, FlaggedNoSlipWallPutsItsShearIntoTheWallCells) {
  const auto deck = deck::load_deck_text(box_deck(3, 3, 4), "strain.toml", {});
  const parallel::Domain domain(deck, parallel::Communicator());
  const double speed = 0.2, width = 0.01;
  const auto u = plug(domain, speed);
  const solver::Discretization discretization(domain);
  const auto flagged = solver::strain_rate_ghosts(domain, std::vector<bool>(domain.regions.regions.size(), true), true);
  std::vector<double> with_wall, without_wall, divergence;
  solver::compute_strain_rate(discretization, u, with_wall, divergence, flagged);
  solver::compute_strain_rate(discretization, u, without_wall, divergence);
  for (int l = 0; l < domain.layout.owned_fluid_count(); ++l) {
    const auto ijk = domain.layout.index3(l);
    const bool z_wall = ijk[2] == 0 || ijk[2] == 3, y_wall = ijk[1] == 0 || ijk[1] == 2;
    // One wall along z (and one along y at the y walls): each adds (U/w)² to 2 D:D.
    const double expected = speed / width * std::sqrt((z_wall ? 1.0 : 0.0) + (y_wall ? 1.0 : 0.0));
    EXPECT_NEAR(with_wall[static_cast<std::size_t>(l)], expected, 1e-9) << "cell " << l;
    EXPECT_NEAR(without_wall[static_cast<std::size_t>(l)], 0.0, 1e-9) << "cell " << l;
  }
}

// A 4 × 3 × 4 box of 1 cm cells whose floor has a pressure outflow under its first column
// (x < 1 cm), every other boundary the no-slip default walls, flagged for γ̇ in `walls`.
struct OrificeFloor {
  OrificeFloor()
      : deck(deck::load_deck_text(
            box_deck(4, 3, 4,
                     "[[boundary]]\nname = \"orifice\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
                     "min = [0.0, 0.0, -1.0]\nmax = [0.01, 0.03, 0.0]\npressure = 101325.0\n"),
            "strain.toml", {})),
        domain(deck, parallel::Communicator()),
        discretization(domain),
        walls(domain.regions.regions.size(), false) {
    walls[static_cast<std::size_t>(domain.regions.default_region())] = true;
  }
  deck::Deck deck;
  parallel::Domain domain;
  solver::Discretization discretization;
  std::vector<bool> walls;
};

// numerics.wall_shear_beside_openings = false (MFIX's SET_FLAGS): a floor with a pressure outflow
// under its first column (x < 1 cm). A plug u_x = U: the floor cells under x in [1, 2) cm touch
// the outflow cell beside them and put no shear into γ̇ of the fluid cells above; the floor
// under x ≥ 2 cm does, as before; above the outflow there is no wall at all. With the default
// (true) the floor under [1, 2) cm is a wall like the rest.
TEST(StrainRate, WallCellsBesideAnOpeningCanLeaveTheirShearOut) {
  const OrificeFloor box;
  const auto& domain = box.domain;
  const double speed = 0.2, width = 0.01;
  const auto u = plug(domain, speed);
  const auto& discretization = box.discretization;
  const auto& walls = box.walls;
  for (const bool beside_openings : {true, false}) {
    const auto flagged = solver::strain_rate_ghosts(domain, walls, beside_openings);
    std::vector<double> gamma_dot, divergence;
    solver::compute_strain_rate(discretization, u, gamma_dot, divergence, flagged);
    for (int l = 0; l < domain.layout.owned_fluid_count(); ++l) {
      const auto ijk = domain.layout.index3(l);
      const bool floor = ijk[2] == 0 && (ijk[0] >= 2 || (ijk[0] == 1 && beside_openings));
      const bool lid = ijk[2] == 3, y_wall = ijk[1] == 0 || ijk[1] == 2;
      const double expected =
          speed / width * std::sqrt((floor || lid ? 1.0 : 0.0) + (y_wall ? 1.0 : 0.0));
      EXPECT_NEAR(gamma_dot[static_cast<std::size_t>(l)], expected, 1e-9)
          << "cell " << ijk[0] << ", " << ijk[1] << ", " << ijk[2] << ", beside_openings " << beside_openings;
    }
  }
}

// The same floor under a shear u_x = G z (the profile vanishes at the floor, z = 0): a no-slip
// ghost (−u_c a width away) gives the fluid cell above the wall the exact G, and so does the
// one-sided difference above the outflow cell, where there is no wall. With
// wall_shear_beside_openings = false the floor cell beside the outflow holds MFIX's free-slip
// ghost (+u_c a width away): G/2 in the fluid cell above it, half the one-sided G; with
// copy_velocity_into_openings the outflow cell holds the same (MFIX's SET_OUTFLOW): G/2 above it.
TEST(StrainRate, WallCellsBesideAnOpeningHoldAFreeSlipGhost) {
  const OrificeFloor box;
  const auto& domain = box.domain;
  const double shear = 3.0;
  const double a[3][3] = {{0, 0, shear}, {0, 0, 0}, {0, 0, 0}};
  const auto u = linear_field(domain, a);
  const auto& discretization = box.discretization;
  const auto& walls = box.walls;
  for (const bool beside_openings : {true, false})
    for (const bool copy : {false, true}) {
      const auto ghosts = solver::strain_rate_ghosts(domain, walls, beside_openings, copy);
      std::vector<double> gamma_dot, divergence;
      solver::compute_strain_rate(discretization, u, gamma_dot, divergence, ghosts);
      for (int l = 0; l < domain.layout.owned_fluid_count(); ++l) {
        const auto ijk = domain.layout.index3(l);
        if (ijk[2] != 0 || ijk[1] != 1) continue;  // the bottom row, away from the y walls
        const bool halved = (ijk[0] == 1 && !beside_openings) || (ijk[0] == 0 && copy);
        EXPECT_NEAR(gamma_dot[static_cast<std::size_t>(l)], halved ? 0.5 * shear : shear, 1e-9)
            << "cell " << ijk[0] << ", beside_openings " << beside_openings << ", copy " << copy;
      }
    }
}

}  // namespace
}  // namespace bagnold::tests
