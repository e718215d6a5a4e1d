// Geometry flags: which points each primitive blocks, the boundary skin (non-fluid cells that
// touch fluid across a face, edge or corner), periodic rings, boundary regions (first match wins,
// "walls" takes the rest), and the bin and hourglass decks.
#include <gtest/gtest.h>

#include <cmath>

#include "src/deck/load.hpp"
#include "src/grid/cell_flags.hpp"
#include "src/grid/shapes.hpp"
#include "tests/support/test_decks.hpp"

#ifndef BAGNOLD_SOURCE_DIR
#error "BAGNOLD_SOURCE_DIR (the project's source folder) must be defined by the build"
#endif

namespace bagnold::tests {
namespace {

using grid::CellKind;
using grid::FrustumSide;
using grid::Index3;
using grid::Point;

// ---------------------------------------------------------------------------------------------
// Primitives

TEST(Shapes, BoxIsClosed) {
  const Point lo{0.0, 0.0, 0.0}, hi{1.0, 2.0, 3.0};
  EXPECT_TRUE(grid::inside_box({0.5, 1.0, 1.5}, lo, hi));
  EXPECT_TRUE(grid::inside_box({0.0, 2.0, 3.0}, lo, hi));  // on the faces
  EXPECT_FALSE(grid::inside_box({-1e-9, 1.0, 1.5}, lo, hi));
  EXPECT_FALSE(grid::inside_box({0.5, 2.1, 1.5}, lo, hi));
  EXPECT_FALSE(grid::inside_box({0.5, 1.0, 3.5}, lo, hi));
}

TEST(Shapes, HalfSpaceIsTheSideTheNormalPointsTo) {
  const Point p{0.5, 0.0, 0.0}, n{2.0, 0.0, -2.0};  // need not be unit length
  EXPECT_TRUE(grid::inside_half_space({1.0, 0.0, 0.0}, p, n));
  EXPECT_FALSE(grid::inside_half_space({0.0, 0.0, 0.0}, p, n));
  EXPECT_FALSE(grid::inside_half_space({1.0, 0.0, 0.5}, p, n));  // on the plane: not inside
  EXPECT_TRUE(grid::inside_half_space({1.0, 5.0, 0.4}, p, n));
}

TEST(Shapes, FrustumSides) {
  // A cone along +z, radius 1 at z = 1, radius 3 at z = 3 (the axis need not be unit length).
  const Point base{0.0, 0.0, 1.0}, ax{0.0, 0.0, 5.0};
  auto side = [&](Point x) { return grid::frustum_side(x, base, ax, 2.0, 1.0, 3.0); };
  EXPECT_EQ(side({0.0, 0.0, 2.0}), FrustumSide::inside);
  EXPECT_EQ(side({1.9, 0.0, 2.0}), FrustumSide::inside);  // local radius 2
  EXPECT_EQ(side({2.1, 0.0, 2.0}), FrustumSide::outside);
  EXPECT_EQ(side({0.0, 1.4, 1.5}), FrustumSide::inside);    // local radius 1.5
  EXPECT_EQ(side({0.0, 1.4, 1.25}), FrustumSide::outside);  // local radius 1.25
  EXPECT_EQ(side({0.0, 1.2, 1.25}), FrustumSide::inside);
  EXPECT_EQ(side({0.0, 0.0, 0.9}), FrustumSide::beyond_ends);
  EXPECT_EQ(side({0.0, 0.0, 3.1}), FrustumSide::beyond_ends);
  EXPECT_EQ(side({9.0, 0.0, 0.5}), FrustumSide::beyond_ends);
  // A tilted axis: along x from the origin.
  EXPECT_EQ(grid::frustum_side({0.5, 0.2, 0.0}, {0, 0, 0}, {1, 0, 0}, 1.0, 0.3, 0.3),
            FrustumSide::inside);
  EXPECT_EQ(grid::frustum_side({0.5, 0.0, 0.4}, {0, 0, 0}, {1, 0, 0}, 1.0, 0.3, 0.3),
            FrustumSide::outside);
  EXPECT_EQ(grid::frustum_side({-0.1, 0.0, 0.0}, {0, 0, 0}, {1, 0, 0}, 1.0, 0.3, 0.3),
            FrustumSide::beyond_ends);
}

deck::Block block(std::string shape, std::string blocks) {
  deck::Block b;
  b.shape = std::move(shape);
  b.blocks = std::move(blocks);
  return b;
}

TEST(Shapes, BlocksPointInsideOrOutside) {
  auto box = block("box", "inside");
  box.min = {0, 0, 0};
  box.max = {1, 1, 1};
  EXPECT_TRUE(grid::blocks_point(box, {0.5, 0.5, 0.5}));
  EXPECT_FALSE(grid::blocks_point(box, {1.5, 0.5, 0.5}));
  box.blocks = "outside";
  EXPECT_FALSE(grid::blocks_point(box, {0.5, 0.5, 0.5}));
  EXPECT_TRUE(grid::blocks_point(box, {1.5, 0.5, 0.5}));

  auto half = block("half_space", "inside");
  half.point = {0, 0, 1};
  half.normal = {0, 0, 1};
  EXPECT_TRUE(grid::blocks_point(half, {0, 0, 2}));
  EXPECT_FALSE(grid::blocks_point(half, {0, 0, 0}));
  half.blocks = "outside";
  EXPECT_FALSE(grid::blocks_point(half, {0, 0, 2}));
  EXPECT_TRUE(grid::blocks_point(half, {0, 0, 0}));
}

TEST(Shapes, CylinderBlocksOutsideOnlyBetweenItsEnds) {
  auto c = block("cylinder", "inside");
  c.base = {0, 0, 0};
  c.axis = {0, 0, 1};
  c.length = 1.0;
  c.radius = 0.5;
  c.top_radius = 99.0;  // ignored by a cylinder
  EXPECT_TRUE(grid::blocks_point(c, {0.2, 0.2, 0.5}));
  EXPECT_FALSE(grid::blocks_point(c, {0.6, 0.0, 0.5}));
  EXPECT_FALSE(grid::blocks_point(c, {0.0, 0.0, 1.5}));
  c.blocks = "outside";
  EXPECT_FALSE(grid::blocks_point(c, {0.2, 0.2, 0.5}));
  EXPECT_TRUE(grid::blocks_point(c, {0.6, 0.0, 0.5}));
  EXPECT_FALSE(grid::blocks_point(c, {0.6, 0.0, 1.5}));   // beyond the top: open
  EXPECT_FALSE(grid::blocks_point(c, {0.6, 0.0, -0.5}));  // below the base: open
}

TEST(Shapes, ConeBlocksOutsideOnlyBetweenItsEnds) {
  auto c = block("cone", "outside");
  c.base = {0, 0, 1};
  c.axis = {0, 0, 1};
  c.length = 1.0;
  c.radius = 0.1;
  c.top_radius = 1.0;
  EXPECT_FALSE(grid::blocks_point(c, {0.0, 0.0, 1.5}));  // on the axis
  EXPECT_TRUE(grid::blocks_point(c, {0.5, 0.5, 1.1}));   // narrow part: blocked
  EXPECT_FALSE(grid::blocks_point(c, {0.5, 0.0, 1.9}));  // wide part: open
  EXPECT_FALSE(grid::blocks_point(c, {0.9, 0.9, 0.5}));  // below the base
  EXPECT_FALSE(grid::blocks_point(c, {0.9, 0.9, 2.5}));  // above the top
  c.blocks = "inside";
  EXPECT_TRUE(grid::blocks_point(c, {0.0, 0.0, 1.5}));
  EXPECT_FALSE(grid::blocks_point(c, {0.5, 0.5, 1.1}));
}

// The pieces of MFIX's hourglass wall (cases/hourglass/mfix-hourglass.toml): a hyperbola
// 1600 (x−0.1)² − 1500 (z−0.2)² − 1 between two circles of radius 0.1 m.
constexpr double lower_joint = 0.128158, upper_joint = 0.271842;
grid::QuadricPiece hourglass_throat() {
  grid::QuadricPiece q;
  q.centre = {0.10, 0.0, 0.20};
  q.matrix = {1600.0, 0, 0, 0, 0, 0, 0, 0, -1500.0};
  q.constant = -1.0;
  q.lower = lower_joint;
  q.upper = upper_joint;
  return q;
}
grid::QuadricPiece hourglass_circle(double centre_z, double lower, double upper) {
  grid::QuadricPiece q;
  q.centre = {0.10, 0.0, centre_z};
  q.matrix = {1.0, 0, 0, 0, 0, 0, 0, 0, 1.0};
  q.constant = -0.01;
  q.lower = lower;
  q.upper = upper;
  return q;
}

TEST(Shapes, QuadricIsInsideWhereItsFunctionIsNegative) {
  const auto throat = hourglass_throat();
  EXPECT_NEAR(throat.value({0.10, 0.005, 0.20}), -1.0, 1e-12);
  EXPECT_LT(throat.value({0.124, 0.0, 0.20}), 0.0);  // the throat's half width is 2.5 cm
  EXPECT_GT(throat.value({0.126, 0.0, 0.20}), 0.0);
  EXPECT_NEAR(throat.value({0.125, 0.0, 0.20}), 0.0, 1e-12);
  EXPECT_LT(throat.value({0.17, 0.0, 0.27}), 0.0);  // half width 7.39 cm at the joint
  EXPECT_GT(throat.value({0.18, 0.0, 0.27}), 0.0);
  // ∇f = (A + Aᵀ)(x − c) + b: (3200 (x − 0.1), 0, −3000 (z − 0.2)).
  const auto g = throat.gradient({0.125, 0.0, 0.21});
  EXPECT_NEAR(g[0], 80.0, 1e-9);
  EXPECT_NEAR(g[1], 0.0, 1e-12);
  EXPECT_NEAR(g[2], -30.0, 1e-9);
  // A circle's f / |∇f| is (r² − R²) / 2r: the distance to first order, exact on the wall.
  const auto circle = hourglass_circle(0.339194, upper_joint, 0.40);
  EXPECT_NEAR(circle.distance_estimate({0.19, 0.0, 0.339194}), (0.0081 - 0.01) / 0.18, 1e-12);
  EXPECT_NEAR(circle.distance_estimate({0.20, 0.0, 0.339194}), 0.0, 1e-12);
  const double at_centre = circle.distance_estimate({0.10, 0.0, 0.339194});  // ∇f = 0
  EXPECT_TRUE(std::isinf(at_centre) && at_centre < 0.0);  // −∞ inside, not NaN
}

TEST(Shapes, QuadricBlockActsOnlyOverItsRange) {
  deck::Block b;
  b.shape = "quadric";
  b.blocks = "outside";
  b.centre = {0.10, 0.0, 0.20};
  b.matrix = {1600.0, 0.0, -1500.0};  // the diagonal
  b.constant = -1.0;
  b.along = "z";
  b.range = {lower_joint, upper_joint};
  EXPECT_FALSE(grid::blocks_point(b, {0.10, 0.0, 0.20}));  // the throat's axis: fluid
  EXPECT_TRUE(grid::blocks_point(b, {0.01, 0.0, 0.20}));   // beside the throat: solid
  EXPECT_TRUE(grid::blocks_point(b, {0.1251, 0.0, 0.20}));  // just beyond the wall: solid
  EXPECT_FALSE(grid::blocks_point(b, {0.01, 0.0, 0.30}));  // beyond the range: not this block's
  EXPECT_FALSE(grid::blocks_point(b, {0.01, 0.0, 0.10}));
  b.blocks = "inside";
  EXPECT_TRUE(grid::blocks_point(b, {0.10, 0.0, 0.20}));
  EXPECT_FALSE(grid::blocks_point(b, {0.01, 0.0, 0.20}));
  EXPECT_FALSE(grid::blocks_point(b, {0.10, 0.0, 0.30}));
  // 9 entries are A row by row; a diagonal one gives the same quadric as its 3 entries.
  const auto diagonal = grid::quadric_of(b);
  b.matrix = {1600.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1500.0};
  const auto full = grid::quadric_of(b);
  EXPECT_EQ(diagonal.matrix, full.matrix);
  EXPECT_EQ(full.along, 2);
  b.along = "x";
  EXPECT_EQ(grid::quadric_of(b).along, 0);
}

TEST(Shapes, MfixHourglassPiecesMeetTangentiallyAtTheJoints) {
  const auto throat = hourglass_throat();
  const auto upper = hourglass_circle(0.339194, upper_joint, 0.40);
  const auto lower = hourglass_circle(0.060806, 0.0, lower_joint);
  for (const auto& [circle, z] : {std::pair{upper, upper_joint}, std::pair{lower, lower_joint}}) {
    // The wall's half width on the joint plane, from each piece's f = 0.
    const double dz_throat = z - 0.20, dz_circle = z - circle.centre[2];
    const double half_width_throat = std::sqrt((1.0 + 1500.0 * dz_throat * dz_throat) / 1600.0);
    const double half_width_circle = std::sqrt(0.01 - dz_circle * dz_circle);
    EXPECT_NEAR(half_width_throat, half_width_circle, 2e-6) << "z = " << z;
    const Point wall{0.10 + half_width_throat, 0.0, z};
    EXPECT_NEAR(throat.value(wall), 0.0, 1e-12);
    EXPECT_NEAR(circle.value(wall), 0.0, 1e-6);
    EXPECT_TRUE(throat.in_range(wall) && circle.in_range(wall));
    // Tangency: the two normals are parallel (their cross product's y component vanishes).
    const auto a = throat.gradient(wall), b = circle.gradient(wall);
    const double sine = (a[2] * b[0] - a[0] * b[2]) /
                        (std::hypot(a[0], a[2]) * std::hypot(b[0], b[2]));
    EXPECT_NEAR(sine, 0.0, 1e-4) << "z = " << z;
    EXPECT_GT(a[0] * b[0] + a[2] * b[2], 0.0);  // and point the same way (out of the fluid)
    // The wall's slope dx/dz there: 0.9112 outward above the throat, inward below it.
    EXPECT_NEAR(std::abs(-a[2] / a[0]), 0.9112, 1e-4);
  }
}

// ---------------------------------------------------------------------------------------------
// Cell classification

struct Classified {
  deck::Deck deck;
  grid::StructuredGrid grid;
  grid::BoundaryRegions regions;
  grid::CellFlags flags;

  explicit Classified(deck::Deck d)
      : deck(std::move(d)),
        grid(deck.grid),
        regions(grid::make_boundary_regions(deck)),
        flags(grid::classify_cells(grid, deck.geometry, regions)) {}
  explicit Classified(const std::string& text) : Classified(deck::load_deck_text(text, "t.toml")) {}

  CellKind kind(const Index3& ijk) const {
    return flags.kind[static_cast<std::size_t>(grid.natural(ijk))];
  }
  int region(const Index3& ijk) const {
    return flags.region[static_cast<std::size_t>(grid.natural(ijk))];
  }
  std::int64_t count(CellKind k) const {
    return std::count(flags.kind.begin(), flags.kind.end(), k);
  }
  int region_index(const std::string& name) const {
    for (std::size_t r = 0; r < regions.regions.size(); ++r)
      if (regions.regions[r].name == name) return static_cast<int>(r);
    ADD_FAILURE() << "no region " << name;
    return -2;
  }
  // The cell whose centre is nearest `x` (domain cells).
  Index3 cell_at(const Point& x) const {
    Index3 ijk{};
    for (int d = 0; d < 3; ++d) {
      const auto& f = grid.axis(d).faces();
      int i = 0;
      while (i + 1 < grid.cells(d) && f[static_cast<std::size_t>(i) + 1] <= x[d]) ++i;
      ijk[d] = i;
    }
    return ijk;
  }
};

TEST(CellFlags, OpenBoxIsFluidWithTheWholeRingAsBoundary) {
  const Classified c(box_deck(4, 3, 5));
  EXPECT_EQ(c.flags.fluid_count, 60);
  EXPECT_EQ(c.flags.boundary_count, c.grid.extended_cell_count() - 60);  // corners too
  EXPECT_EQ(c.count(CellKind::fluid), 60);
  EXPECT_EQ(c.count(CellKind::boundary), c.flags.boundary_count);
  EXPECT_EQ(c.count(CellKind::excluded), 0);
  for (grid::Natural n = 0; n < c.grid.extended_cell_count(); ++n) {
    const auto ijk = c.grid.index3(n);
    EXPECT_EQ(c.kind(ijk), c.grid.in_domain(ijk) ? CellKind::fluid : CellKind::boundary);
    EXPECT_EQ(c.region(ijk), c.grid.in_domain(ijk) ? -1 : c.regions.default_region());
  }
}

TEST(CellFlags, SkinIsTheBlockedCellsTouchingFluidInThe26Neighbourhood) {
  // 7³ cells; a box blocks the 5³ cells 1..5 in every direction: its outer shell (98 cells)
  // touches fluid, its 3³ core does not and is not stored.
  const Classified c(box_deck(7, 7, 7,
                              "[[geometry.block]]\nshape = \"box\"\nmin = [0.01, 0.01, 0.01]\n"
                              "max = [0.06, 0.06, 0.06]\n"));
  EXPECT_EQ(c.flags.fluid_count, 343 - 125);
  EXPECT_EQ(c.count(CellKind::excluded), 27);
  EXPECT_EQ(c.flags.boundary_count, 98 + (c.grid.extended_cell_count() - 343));
  EXPECT_EQ(c.kind({3, 3, 3}), CellKind::excluded);
  EXPECT_EQ(c.kind({2, 2, 2}), CellKind::excluded);
  EXPECT_EQ(c.kind({1, 3, 3}), CellKind::boundary);
  EXPECT_EQ(c.kind({1, 1, 1}), CellKind::boundary);
  EXPECT_EQ(c.kind({0, 3, 3}), CellKind::fluid);
  EXPECT_EQ(c.region({3, 3, 3}), -1);
}

TEST(CellFlags, CornerContactMakesABoundaryCell) {
  // Only cell (0, 0, 0) is fluid: its 26 neighbours, including (1, 1, 1) across the corner,
  // are boundary; (2, 0, 0) two cells away is excluded.
  const Classified c(box_deck(4, 4, 4,
                              "[[geometry.block]]\nshape = \"box\"\nblocks = \"outside\"\n"
                              "min = [0.0, 0.0, 0.0]\nmax = [0.01, 0.01, 0.01]\n"));
  EXPECT_EQ(c.flags.fluid_count, 1);
  EXPECT_EQ(c.flags.boundary_count, 26);
  EXPECT_EQ(c.kind({0, 0, 0}), CellKind::fluid);
  EXPECT_EQ(c.kind({1, 1, 1}), CellKind::boundary);
  EXPECT_EQ(c.kind({-1, -1, -1}), CellKind::boundary);
  EXPECT_EQ(c.kind({1, 0, -1}), CellKind::boundary);
  EXPECT_EQ(c.kind({2, 0, 0}), CellKind::excluded);
  EXPECT_EQ(c.kind({2, 2, 2}), CellKind::excluded);
  EXPECT_EQ(c.kind({4, 4, 4}), CellKind::excluded);
}

TEST(CellFlags, RingOfAPeriodicDirectionIsNeverBoundary) {
  const Classified c(box_deck(4, 3, 5, "[grid]\nperiodic = [\"y\"]\n"));
  EXPECT_EQ(c.flags.fluid_count, 60);
  // Boundary: the x and z rings over the periodic y range only.
  EXPECT_EQ(c.flags.boundary_count, (6 * 7 - 4 * 5) * 3);
  for (int k = -1; k <= 5; ++k)
    for (int i = -1; i <= 4; ++i) {
      EXPECT_EQ(c.kind({i, -1, k}), CellKind::excluded);
      EXPECT_EQ(c.kind({i, 3, k}), CellKind::excluded);
    }
  EXPECT_EQ(c.kind({-1, 0, 0}), CellKind::boundary);
  EXPECT_EQ(c.kind({4, 2, 5}), CellKind::boundary);
}

TEST(CellFlags, BlockedCellsTouchFluidAcrossAPeriodicFace) {
  // x periodic; a half-space blocks x > 0.03 (cell 3 of 4): cell 3 touches cell 2 and,
  // across the periodic face, cell 0, so it is boundary, and no x ring exists.
  const Classified c(box_deck(4, 2, 2,
                              "[grid]\nperiodic = [\"x\"]\n[[geometry.block]]\nshape = \"half_space\"\n"
                              "point = [0.03, 0.0, 0.0]\nnormal = [1.0, 0.0, 0.0]\n"));
  EXPECT_EQ(c.flags.fluid_count, 3 * 2 * 2);
  EXPECT_EQ(c.kind({3, 0, 0}), CellKind::boundary);
  EXPECT_EQ(c.kind({-1, 0, 0}), CellKind::excluded);
  EXPECT_EQ(c.kind({4, 0, 0}), CellKind::excluded);
}

TEST(CellFlags, RegionsByFaceAndBoxFirstMatchWinsRestAreWalls) {
  const Classified c(box_deck(
      4, 2, 3,
      "[geometry]\ndefault_wall = \"free_slip_wall\"\n"
      "[[boundary]]\nname = \"strip\"\ntype = \"pressure_outflow\"\nface = \"z-\"\n"
      "min = [0.0, -1.0, -1.0]\nmax = [0.02, 1.0, 1.0]\n"
      "[[boundary]]\nname = \"floor\"\ntype = \"no_slip_wall\"\nface = \"z-\"\n"
      "[[boundary]]\nname = \"high\"\ntype = \"moving_wall\"\nface = \"any\"\n"
      "min = [-1.0, -1.0, 0.02]\n"));
  ASSERT_EQ(c.regions.regions.size(), 4u);
  EXPECT_EQ(c.regions.default_region(), 3);
  EXPECT_EQ(c.regions.regions[3].name, "walls");
  EXPECT_EQ(c.regions.types[3], grid::BoundaryType::free_slip_wall);
  EXPECT_EQ(c.regions.types[0], grid::BoundaryType::pressure_outflow);
  EXPECT_EQ(c.regions.types[2], grid::BoundaryType::moving_wall);
  const int strip = 0, floor = 1, high = 2, walls = 3;
  EXPECT_EQ(c.region({0, 0, -1}), strip);  // also in "floor": the first region wins
  EXPECT_EQ(c.region({1, 1, -1}), strip);
  EXPECT_EQ(c.region({2, 0, -1}), floor);
  EXPECT_EQ(c.region({3, 1, -1}), floor);
  EXPECT_EQ(c.region({-1, 0, -1}), floor);  // x centre -0.005 is outside the strip's box
  EXPECT_EQ(c.region({0, 0, 3}), high);     // the top (z centre 0.035)
  EXPECT_EQ(c.region({-1, 0, 2}), high);    // a side cell above z = 0.02
  EXPECT_EQ(c.region({-1, 0, 1}), walls);   // a side cell below
  EXPECT_EQ(c.region({4, 1, 0}), walls);
  EXPECT_EQ(c.region({0, 0, 0}), -1);       // fluid
  std::vector<int> per_region(4, 0);
  for (grid::Natural n = 0; n < c.grid.extended_cell_count(); ++n)
    if (c.flags.kind[static_cast<std::size_t>(n)] == CellKind::boundary)
      ++per_region[static_cast<std::size_t>(c.flags.region[static_cast<std::size_t>(n)])];
  EXPECT_EQ(per_region[strip], 2 * 4);  // i = 0, 1 (centres 0.005, 0.015) by j = -1 .. 2
  EXPECT_EQ(per_region[floor], 6 * 4 - 8);
  EXPECT_EQ(per_region[high], (6 * 4 - 4 * 2) + 6 * 4);  // the ring around k = 2, the top k = 3
  EXPECT_EQ(per_region[walls], (6 * 4 - 4 * 2) * 2);      // the ring around k = 0, 1
}

// Each block's count is the domain cells whose centre it blocks, also where another block
// blocks them too; a block beside the domain blocks none.
TEST(CellFlags, EachBlockCountsTheCellsItBlocks) {
  const Classified c(box_deck(4, 4, 4,
                              "[[geometry.block]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\n"
                              "max = [0.02, 0.04, 0.01]\n"  // i = 0, 1; all j; k = 0: 8 cells
                              "[[geometry.block]]\nshape = \"half_space\"\npoint = [0.0, 0.0, 0.004]\n"
                              "normal = [0.0, 0.0, -1.0]\n"  // z < 0.004: none (centres 0.005 ...)
                              "[[geometry.block]]\nshape = \"box\"\nmin = [0.0, 0.0, 0.0]\n"
                              "max = [0.04, 0.04, 0.01]\n"  // all of k = 0: 16, 8 shared
                              "[[geometry.block]]\nshape = \"box\"\nmin = [0.05, 0.0, 0.0]\n"
                              "max = [0.08, 0.04, 0.04]\n"));  // beside the domain: none
  EXPECT_EQ(c.flags.block_cells, (std::vector<std::int64_t>{8, 0, 16, 0}));
  EXPECT_EQ(c.flags.fluid_count, 64 - 16);
}

// A region selects the boundary cells of its face whose centres are in its box: on a domain
// face those centres lie half a cell beyond the face, so a box ending on the face selects none.
TEST(CellFlags, RegionSelectsByFaceAndCentre) {
  const Classified c(box_deck(4, 4, 4));
  deck::BoundaryRegion on_face;
  on_face.face = "z-";
  on_face.min = {0.0, 0.0, 0.0};
  on_face.max = {0.01, 0.04, 0.0};
  deck::BoundaryRegion past_face = on_face;
  past_face.min[2] = -1.0;
  int on = 0, past = 0;
  for (grid::Natural n = 0; n < c.grid.extended_cell_count(); ++n) {
    const auto ijk = c.grid.index3(n);
    if (c.kind(ijk) != CellKind::boundary) continue;
    on += grid::region_selects(c.grid, ijk, on_face);
    past += grid::region_selects(c.grid, ijk, past_face);
  }
  EXPECT_EQ(on, 0);
  EXPECT_EQ(past, 4);  // i = 0 (x centre 0.005) by j = 0 .. 3 (y centres 0.005 ... 0.035)
  EXPECT_TRUE(grid::region_selects(c.grid, {0, 3, -1}, past_face));
  EXPECT_FALSE(grid::region_selects(c.grid, {0, 0, 4}, past_face));  // another face
  EXPECT_FALSE(grid::region_selects(c.grid, {1, 0, -1}, past_face));  // x centre 0.015
}

TEST(CellFlags, InternalRegionTakesOnlyBlockedCellsInsideTheDomain) {
  const Classified c(box_deck(6, 6, 6,
                              "[[geometry.block]]\nshape = \"box\"\nmin = [0.02, 0.02, 0.02]\n"
                              "max = [0.04, 0.04, 0.04]\n"
                              "[[boundary]]\nname = \"obstacle\"\ntype = \"no_slip_wall\"\n"
                              "face = \"internal\"\n"));
  const int obstacle = c.region_index("obstacle");
  EXPECT_EQ(c.region({2, 2, 2}), obstacle);
  EXPECT_EQ(c.region({3, 3, 3}), obstacle);
  EXPECT_EQ(c.region({-1, 2, 2}), c.regions.default_region());
  int internal = 0;
  for (grid::Natural n = 0; n < c.grid.extended_cell_count(); ++n)
    internal += c.flags.region[static_cast<std::size_t>(n)] == obstacle;
  EXPECT_EQ(internal, 8);  // the blocked 2³ cells all touch fluid
}

TEST(CellFlags, UnknownBoundaryTypeIsRejected) {
  EXPECT_THROW(grid::boundary_type_from_name("wall"), std::invalid_argument);
  EXPECT_EQ(grid::boundary_type_from_name("mass_inflow"), grid::BoundaryType::mass_inflow);
  EXPECT_STREQ(grid::boundary_type_name(grid::BoundaryType::pressure_inflow), "pressure_inflow");
}

// ---------------------------------------------------------------------------------------------
// The cases

TEST(CellFlags, BinOrificeIsTheFourBySixteenFloorCells) {
  const Classified c(deck::load_deck(BAGNOLD_SOURCE_DIR "/cases/bin/bin.toml"));
  ASSERT_EQ(c.grid.cells(0), 16);
  ASSERT_EQ(c.grid.cells(1), 16);
  ASSERT_EQ(c.grid.cells(2), 400);
  EXPECT_EQ(c.flags.fluid_count, 16 * 16 * 400);
  const int orifice = c.region_index("orifice");
  const int top = c.region_index("top");
  int orifice_cells = 0, top_cells = 0;
  for (grid::Natural n = 0; n < c.grid.extended_cell_count(); ++n) {
    const int r = c.flags.region[static_cast<std::size_t>(n)];
    const auto ijk = c.grid.index3(n);
    if (r == orifice) {
      ++orifice_cells;
      EXPECT_EQ(ijk[2], -1);
      EXPECT_GE(ijk[0], 0);
      EXPECT_LE(ijk[0], 3);  // x in [0, 1 cm] at 2.5 mm
      EXPECT_GE(ijk[1], 0);
      EXPECT_LE(ijk[1], 15);
    }
    top_cells += r == top;
  }
  EXPECT_EQ(orifice_cells, 4 * 16);
  EXPECT_EQ(top_cells, 18 * 18);
  EXPECT_EQ(c.region({4, 0, -1}), c.regions.default_region());
  EXPECT_EQ(c.region({-1, 0, -1}), c.regions.default_region());
}

TEST(CellFlags, HourglassBlocksAroundItsChambersAndHopper) {
  const Classified c(deck::load_deck(BAGNOLD_SOURCE_DIR "/cases/hourglass/hourglass.toml"));
  EXPECT_GT(c.flags.fluid_count, 0);
  EXPECT_LT(c.flags.fluid_count, c.grid.domain_cell_count());
  // Not a staircase of the bounding box: a cylinder of radius 4.5 cm keeps about π/4 of it.
  EXPECT_LT(c.flags.fluid_count, 0.7 * static_cast<double>(c.grid.domain_cell_count()));
  EXPECT_GT(c.count(CellKind::excluded), 0);
  EXPECT_EQ(c.kind(c.cell_at({0.05, 0.05, 0.05})), CellKind::fluid);     // lower chamber
  EXPECT_EQ(c.kind(c.cell_at({0.08, 0.05, 0.05})), CellKind::fluid);     // r = 3 cm
  EXPECT_EQ(c.kind(c.cell_at({0.05, 0.05, 0.2})), CellKind::fluid);      // upper chamber
  EXPECT_EQ(c.kind(c.cell_at({0.0025, 0.0025, 0.05})), CellKind::excluded);  // box corner
  EXPECT_NE(c.kind(c.cell_at({0.07, 0.05, 0.11})), CellKind::fluid);  // hopper wall, r = 2 cm
  EXPECT_EQ(c.kind(c.cell_at({0.05, 0.05, 0.11})), CellKind::fluid);  // the orifice
  EXPECT_EQ(c.kind(c.cell_at({0.07, 0.05, 0.09})), CellKind::fluid);  // below the hopper
  EXPECT_EQ(c.kind(c.cell_at({0.09, 0.05, 0.16})), CellKind::fluid);  // above the hopper
}

// MFIX's 2-D hourglass: 2,416 of the 40 × 80 cells are fluid (counted from the three quadrics at
// the cell centres, tests/cli/mfix_hourglass_cells.py), a 10-cell (5 cm) throat, full-width rows
// where the circles reach the side walls, no stray fluid beyond the wall.
TEST(CellFlags, MfixHourglassIsThreeTangentQuadrics) {
  const Classified c(deck::load_deck(BAGNOLD_SOURCE_DIR "/cases/hourglass/mfix-hourglass.toml"));
  EXPECT_EQ(c.grid.domain_cell_count(), 3200);
  EXPECT_EQ(c.flags.fluid_count, 2416);
  auto row_fluid = [&](int k) {
    int n = 0;
    for (int i = 0; i < 40; ++i) n += c.kind({i, 0, k}) == CellKind::fluid;
    return n;
  };
  EXPECT_EQ(row_fluid(39), 10);  // z = 0.1975 m: the throat
  EXPECT_EQ(row_fluid(40), 10);  // z = 0.2025 m
  EXPECT_EQ(row_fluid(12), 40);  // z = 0.0625 m: the lower circle's widest
  EXPECT_EQ(row_fluid(67), 40);  // z = 0.3375 m: the upper circle's widest
  EXPECT_EQ(row_fluid(0), 32);   // the floor cuts the lower circle
  EXPECT_EQ(row_fluid(79), 32);  // the top cuts the upper circle
  EXPECT_EQ(c.kind(c.cell_at({0.10, 0.005, 0.20})), CellKind::fluid);
  EXPECT_NE(c.kind(c.cell_at({0.02, 0.005, 0.20})), CellKind::fluid);
  EXPECT_NE(c.kind(c.cell_at({0.0025, 0.005, 0.3975})), CellKind::fluid);  // top corner
  EXPECT_EQ(c.kind(c.cell_at({0.0025, 0.005, 0.0625})), CellKind::fluid);
  // Each piece blocks cells; the throat's hyperbola most of them.
  ASSERT_EQ(c.flags.block_cells.size(), 3u);
  for (const auto n : c.flags.block_cells) EXPECT_GT(n, 0);
  // Symmetric about x = 0.10 m.
  for (int k = 0; k < 80; ++k)
    for (int i = 0; i < 20; ++i)
      EXPECT_EQ(c.kind({i, 0, k}) == CellKind::fluid, c.kind({39 - i, 0, k}) == CellKind::fluid);
}

}  // namespace
}  // namespace bagnold::tests
