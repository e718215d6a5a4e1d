// The discretization and its two shared stencils (solver/discretization.hpp): the cell-face
// divergence Σ sign·A·q_owner / V and the face-to-centre average, exact for linear fields on
// stretched grids; the widths, areas and volumes against the box; the face classes and
// numberings. On 1 and 2 ranks (halo owners included).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/discretization.hpp"
#include "tests/unit/solver/solver_case.hpp"

namespace bagnold::tests {
namespace {

using solver::CellFace;
using solver::FaceClass;

// A closed box 5 × 4 × 6 cm, stretched in x (last/first 0.5) and z (3.0), gas only.
std::string closed_box() { return unit_deck(5, 4, 6, "", 0.0, gas_only()); }
const std::vector<std::string> stretched = {"grid.x.ratio=0.5", "grid.z.ratio=3.0"};

// u_d = Σ_b a[d][b] x_b at each face velocity's own position, in every local cell.
std::array<std::vector<double>, 3> linear_field(const Case& c, const double (&a)[3][3]) {
  std::array<std::vector<double>, 3> u;
  for (int d = 0; d < 3; ++d) {
    auto& ud = u[static_cast<std::size_t>(d)];
    ud.assign(static_cast<std::size_t>(c.local_count()), 0.0);
    for (int l = 0; l < c.local_count(); ++l) {
      const auto x = c.face_position(l, d);
      for (int b = 0; b < 3; ++b) ud[static_cast<std::size_t>(l)] += a[d][b] * x[static_cast<std::size_t>(b)];
    }
  }
  return u;
}

double divergence(const Case& c, const std::array<std::vector<double>, 3>& u, int l) {
  double sum = 0.0;
  solver::for_each_cell_face(c.disc, l, [&](const CellFace& f) {
    sum += f.sign * f.area * u[static_cast<std::size_t>(f.direction)][static_cast<std::size_t>(f.owner)];
  });
  return sum / c.disc.volume(l);
}

TEST(Stencils, DivergenceOfALinearFieldIsExactOnAStretchedGrid) {
  const Case c(closed_box(), stretched);
  const double a[3][3] = {{0.5, -1.0, 2.0}, {0.3, -0.2, 0.7}, {-1.5, 0.4, 0.9}};
  const auto u = linear_field(c, a);
  for (int l = 0; l < c.owned_fluid(); ++l) {
    // Differences of O(0.05) values over cells of ~5 mm: round-off ~1e-14 / 5e-3 ≈ 1e-12.
    EXPECT_NEAR(divergence(c, u, l), a[0][0] + a[1][1] + a[2][2], 1e-10) << "cell " << l;
  }
}

TEST(Stencils, CentreVelocityOfALinearFieldIsExactOnAStretchedGrid) {
  const Case c(closed_box(), stretched);
  const double a[3][3] = {{0.5, -1.0, 2.0}, {0.3, -0.2, 0.7}, {-1.5, 0.4, 0.9}};
  const auto u = linear_field(c, a);
  for (int l = 0; l < c.owned_fluid(); ++l) {
    const auto x = c.centre(l);
    for (int d = 0; d < 3; ++d) {
      double exact = 0.0;
      for (int b = 0; b < 3; ++b) exact += a[d][b] * x[static_cast<std::size_t>(b)];
      // The mean of two O(0.1) face values: round-off only.
      EXPECT_NEAR(solver::centre_velocity(c.layout(), u[static_cast<std::size_t>(d)], l, d), exact, 1e-14)
          << "cell " << l << " d " << d;
    }
  }
}

TEST(Stencils, CentreVelocityWithoutAStoredMinusFaceIsTheOwnFace) {
  // The documented convention: a − face that is not stored counts as the cell's own + face. The
  // ring cells at i = −1 of a closed box have no − neighbour along x on any rank.
  const Case c(closed_box(), stretched);
  std::vector<double> u(static_cast<std::size_t>(c.local_count()));
  for (int l = 0; l < c.local_count(); ++l) u[static_cast<std::size_t>(l)] = 1.0 + l;
  int checked = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    if (c.layout().neighbour(l, parallel::west) >= 0) continue;
    EXPECT_EQ(solver::centre_velocity(c.layout(), u, l, 0), u[static_cast<std::size_t>(l)]);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(Stencils, DivergenceTelescopesOverAPeriodicBox) {
  // Every face is seen by its two cells with opposite signs and the same area and owner, so
  // Σ_cells V div q vanishes for any face field q (periodic everywhere: no boundary).
  const Case c(unit_deck(4, 3, 5, "\"x\", \"y\", \"z\"", 0.0, gas_only()), {"grid.y.ratio=2.0"});
  std::array<std::vector<double>, 3> q;
  for (int d = 0; d < 3; ++d) {
    q[static_cast<std::size_t>(d)].resize(static_cast<std::size_t>(c.local_count()));
    // Keyed by the owning cell's global position, so halo copies equal their owners.
    for (int l = 0; l < c.local_count(); ++l) q[static_cast<std::size_t>(d)][static_cast<std::size_t>(l)] = wiggle(c.face_position(l, d), d);
  }
  double total = 0.0, magnitude = 0.0;
  for (int l = 0; l < c.owned_fluid(); ++l) {
    int faces = 0;
    solver::for_each_cell_face(c.disc, l, [&](const CellFace& f) {
      ++faces;
      const double term = f.sign * f.area * q[static_cast<std::size_t>(f.direction)][static_cast<std::size_t>(f.owner)];
      total += term;
      magnitude += std::abs(term);
      EXPECT_EQ(f.area, c.disc.face_area(l, f.direction));
      EXPECT_EQ(f.owner, f.sign > 0 ? l : f.neighbour);
    });
    EXPECT_EQ(faces, 6) << "cell " << l;
  }
  // A sum of ~360 terms of size ~1e-4 that cancel pairwise: round-off 1e-13 of their magnitude.
  EXPECT_LT(std::abs(c.sum(total)), 1e-13 * c.sum(magnitude));
  EXPECT_GT(c.sum(magnitude), 0.0);
}

TEST(Stencils, VolumesAndBoundaryAreasSumToTheBox) {
  const Case c(closed_box(), stretched);
  const double lx = 0.05, ly = 0.04, lz = 0.06;
  double volume = 0.0, boundary_area = 0.0, smallest = INFINITY;
  for (int l = 0; l < c.owned_fluid(); ++l) {
    volume += c.disc.volume(l);
    solver::for_each_cell_face(c.disc, l, [&](const CellFace& f) {
      if (c.layout().kind(f.neighbour) == grid::CellKind::boundary) boundary_area += f.area;
    });
  }
  for (int d = 0; d < 3; ++d) {
    const auto& faces = c.domain.grid.axis(d).faces();
    for (std::size_t i = 0; i + 1 < faces.size(); ++i) smallest = std::min(smallest, faces[i + 1] - faces[i]);
  }
  // Sums of ~120 products of O(1e-2) widths: round-off 1e-14 relative.
  EXPECT_NEAR(c.sum(volume), lx * ly * lz, 1e-14 * lx * ly * lz);
  EXPECT_NEAR(c.sum(boundary_area), 2.0 * (lx * ly + ly * lz + lx * lz), 1e-13);
  // ½ Σ_faces A over the cells: nx Ly Lz + ny Lx Lz + nz Lx Ly.
  EXPECT_NEAR(c.disc.reference_area(), 5 * ly * lz + 4 * lx * lz + 6 * lx * ly, 1e-13);
  // The smallest width: the last x cell (ratio 0.5) or the first z cell (ratio 3), whichever
  // this rank owns; over all ranks it is the grid's smallest.
  EXPECT_DOUBLE_EQ(-c.max(-c.disc.smallest_width()), smallest);
}

TEST(Discretization, FaceClassesAndNumberingsFollowTheBoundaries) {
  // 3 × 3 × 4, periodic in x; a mass inflow over the bottom (gas 0.2, solids 0.05 m/s up), a
  // pressure outflow over the top, walls on y.
  const std::string boundaries =
      "[[boundary]]\nname = \"feed\"\ntype = \"mass_inflow\"\nface = \"z-\"\n"
      "gas_velocity = [0.0, 0.0, 0.2]\nsolids_velocity = [0.0, 0.0, 0.05]\nsolids_fraction = 0.3\n"
      "[[boundary]]\nname = \"top\"\ntype = \"pressure_outflow\"\nface = \"z+\"\npressure = 101325.0\n";
  const Case c(unit_deck(3, 3, 4, "\"x\"", 0.0, two_fluid() + boundaries));
  const Case closed(unit_deck(3, 3, 4, "", 0.0, gas_only()));
  EXPECT_EQ(c.disc.cell_numbering().total_rows, 36);
  EXPECT_EQ(c.disc.velocity_numbering(0).total_rows, 36);  // periodic: every x face
  EXPECT_EQ(c.disc.velocity_numbering(1).total_rows, 3 * 2 * 4);  // walls at both y ends
  EXPECT_EQ(c.disc.velocity_numbering(2).total_rows, 3 * 3 * 4);  // 3 interior + the outlet face
  EXPECT_EQ(closed.disc.velocity_numbering(0).total_rows, 2 * 3 * 4);
  EXPECT_EQ(closed.disc.velocity_numbering(2).total_rows, 3 * 3 * 3);
  EXPECT_TRUE(c.disc.faces(solver::gas).has_pressure_boundary);
  EXPECT_FALSE(closed.disc.faces(solver::gas).has_pressure_boundary);
  int inflow_faces = 0;
  for (int l = 0; l < c.local_count(); ++l) {
    const auto ijk = c.layout().index3(l);
    if (ijk[2] != -1 || ijk[1] < 0 || ijk[1] > 2) continue;  // the ring below the domain
    EXPECT_EQ(c.disc.faces(solver::gas).kind[2][static_cast<std::size_t>(l)], FaceClass::fixed);
    EXPECT_EQ(c.disc.faces(solver::gas).fixed_value[2][static_cast<std::size_t>(l)], 0.2);
    EXPECT_EQ(c.disc.faces(solver::solids).fixed_value[2][static_cast<std::size_t>(l)], 0.05);
    ++inflow_faces;
  }
  EXPECT_GT(c.sum(inflow_faces), 8.0);  // at least the 9 faces below the domain
}

}  // namespace
}  // namespace bagnold::tests
