// Grid indexing and coordinates: the natural numbering of the extended box, stepping with
// periodic wrap and the ring limits, uniform and geometrically stretched axes, cell volumes.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "src/grid/structured_grid.hpp"

namespace bagnold::tests {
namespace {

using grid::Index3;
using grid::StructuredGrid;

deck::Axis axis(double min, double max, int cells, double ratio = 1.0) {
  deck::Axis a;
  a.min = min;
  a.max = max;
  a.cells = cells;
  a.ratio = ratio;
  return a;
}

deck::Grid grid_of(int nx, int ny, int nz, std::vector<std::string> periodic = {}) {
  deck::Grid g;
  g.x = axis(0.0, 0.1 * nx, nx);
  g.y = axis(0.0, 0.1 * ny, ny);
  g.z = axis(0.0, 0.1 * nz, nz);
  g.periodic = std::move(periodic);
  return g;
}

TEST(StructuredGrid, CountsOfDomainAndExtendedBox) {
  const StructuredGrid g(grid_of(3, 4, 5));
  EXPECT_EQ(g.cells(0), 3);
  EXPECT_EQ(g.cells(1), 4);
  EXPECT_EQ(g.cells(2), 5);
  EXPECT_EQ(g.domain_cell_count(), 60);
  EXPECT_EQ(g.extended_cell_count(), 5 * 6 * 7);
  // The ring exists in periodic directions too (it is never used, but the numbering is fixed).
  EXPECT_EQ(StructuredGrid(grid_of(3, 4, 5, {"x"})).extended_cell_count(), 5 * 6 * 7);
}

TEST(StructuredGrid, NaturalNumbersTheExtendedBoxXFastest) {
  const StructuredGrid g(grid_of(3, 4, 5));
  EXPECT_EQ(g.natural({-1, -1, -1}), 0);
  EXPECT_EQ(g.natural({0, -1, -1}), 1);
  EXPECT_EQ(g.natural({3, -1, -1}), 4);
  EXPECT_EQ(g.natural({-1, 0, -1}), 5);
  EXPECT_EQ(g.natural({-1, -1, 0}), 5 * 6);
  EXPECT_EQ(g.natural({0, 0, 0}), 1 + 5 + 30);
  EXPECT_EQ(g.natural({3, 4, 5}), g.extended_cell_count() - 1);
}

TEST(StructuredGrid, NaturalAndIndex3RoundTripOverTheExtendedBox) {
  const StructuredGrid g(grid_of(3, 4, 5));
  std::set<grid::Natural> seen;
  int in_domain = 0;
  for (int k = -1; k <= 5; ++k)
    for (int j = -1; j <= 4; ++j)
      for (int i = -1; i <= 3; ++i) {
        const Index3 ijk{i, j, k};
        const auto n = g.natural(ijk);
        ASSERT_GE(n, 0);
        ASSERT_LT(n, g.extended_cell_count());
        EXPECT_EQ(g.index3(n), ijk);
        EXPECT_TRUE(g.in_extended_box(ijk));
        in_domain += g.in_domain(ijk);
        seen.insert(n);
      }
  EXPECT_EQ(static_cast<std::int64_t>(seen.size()), g.extended_cell_count());
  EXPECT_EQ(in_domain, 60);
  for (grid::Natural n = 0; n < g.extended_cell_count(); ++n) EXPECT_EQ(g.natural(g.index3(n)), n);
  EXPECT_FALSE(g.in_extended_box({-2, 0, 0}));
  EXPECT_FALSE(g.in_extended_box({0, 5, 0}));
  EXPECT_FALSE(g.in_domain({-1, 0, 0}));
  EXPECT_FALSE(g.in_domain({0, 0, 5}));
}

TEST(StructuredGrid, StepStopsAtTheRingOfNonPeriodicDirections) {
  const StructuredGrid g(grid_of(3, 4, 5));
  Index3 to{};
  ASSERT_TRUE(g.step({0, 0, 0}, {-1, 0, 0}, to));
  EXPECT_EQ(to, (Index3{-1, 0, 0}));
  EXPECT_FALSE(g.step({0, 0, 0}, {-2, 0, 0}, to));
  ASSERT_TRUE(g.step({2, 3, 4}, {1, 1, 1}, to));
  EXPECT_EQ(to, (Index3{3, 4, 5}));
  EXPECT_FALSE(g.step({2, 3, 4}, {0, 2, 0}, to));
  EXPECT_FALSE(g.step({-1, 0, 0}, {0, 0, -2}, to));
  ASSERT_TRUE(g.step({1, 1, 1}, {-2, 2, 1}, to));
  EXPECT_EQ(to, (Index3{-1, 3, 2}));
}

TEST(StructuredGrid, StepWrapsPeriodicDirections) {
  const StructuredGrid g(grid_of(3, 4, 5, {"y"}));
  Index3 to{};
  ASSERT_TRUE(g.step({0, 0, 0}, {0, -1, 0}, to));
  EXPECT_EQ(to, (Index3{0, 3, 0}));
  ASSERT_TRUE(g.step({0, 3, 0}, {0, 1, 0}, to));
  EXPECT_EQ(to, (Index3{0, 0, 0}));
  ASSERT_TRUE(g.step({0, 1, 0}, {0, -2, 0}, to));
  EXPECT_EQ(to, (Index3{0, 3, 0}));
  ASSERT_TRUE(g.step({0, 2, 0}, {0, 2, 0}, to));
  EXPECT_EQ(to, (Index3{0, 0, 0}));
  ASSERT_TRUE(g.step({0, 3, 0}, {0, 6, 0}, to));  // more than one period
  EXPECT_EQ(to, (Index3{0, 1, 0}));
  // Other directions still stop at their ring, wrap or not.
  ASSERT_TRUE(g.step({0, 0, 0}, {-1, -1, -1}, to));
  EXPECT_EQ(to, (Index3{-1, 3, -1}));
  EXPECT_FALSE(g.step({0, 0, 0}, {-2, -1, 0}, to));
  EXPECT_TRUE(g.periodic(1));
  EXPECT_FALSE(g.periodic(0));
  EXPECT_FALSE(g.periodic(2));
}

TEST(AxisCoordinates, Uniform) {
  const grid::AxisCoordinates a(axis(-0.2, 0.6, 8));
  ASSERT_EQ(a.cells(), 8);
  ASSERT_EQ(a.faces().size(), 9u);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(a.width(i), 0.1, 1e-15) << i;
    EXPECT_NEAR(a.lower_face(i), -0.2 + 0.1 * i, 1e-15) << i;
    EXPECT_NEAR(a.upper_face(i), -0.2 + 0.1 * (i + 1), 1e-15) << i;
    EXPECT_NEAR(a.centre(i), -0.15 + 0.1 * i, 1e-15) << i;
  }
  EXPECT_EQ(a.faces().front(), -0.2);
  EXPECT_EQ(a.faces().back(), 0.6);
  // The ring cells mirror the first and last cells.
  EXPECT_NEAR(a.width(-1), 0.1, 1e-15);
  EXPECT_NEAR(a.width(8), 0.1, 1e-15);
  EXPECT_NEAR(a.centre(-1), -0.25, 1e-15);
  EXPECT_NEAR(a.centre(8), 0.65, 1e-15);
  EXPECT_NEAR(a.lower_face(-1), -0.3, 1e-15);
  EXPECT_NEAR(a.upper_face(-1), -0.2, 1e-15);
  EXPECT_NEAR(a.lower_face(8), 0.6, 1e-15);
}

void expect_stretched(double ratio, int n) {
  const double min = 0.25, max = 2.25;
  const grid::AxisCoordinates a(axis(min, max, n, ratio));
  ASSERT_EQ(a.cells(), n);
  EXPECT_EQ(a.faces().front(), min);
  EXPECT_EQ(a.faces().back(), max);
  // Last over first is the ratio; neighbours grow by the same factor q = ratio^(1/(n-1)).
  EXPECT_NEAR(a.width(n - 1) / a.width(0), ratio, 1e-12 * ratio);
  const double q = std::pow(ratio, 1.0 / (n - 1));
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    sum += a.width(i);
    if (i > 0) {
      EXPECT_NEAR(a.width(i) / a.width(i - 1), q, 1e-12) << i;
    }
    EXPECT_NEAR(a.centre(i), 0.5 * (a.faces()[i] + a.faces()[i + 1]), 1e-15) << i;
    EXPECT_GT(a.width(i), 0.0);
  }
  EXPECT_NEAR(sum, max - min, 1e-14);
  // First width from the geometric series: w0 (q^n - 1)/(q - 1) = L.
  EXPECT_NEAR(a.width(0), (max - min) * (q - 1) / (std::pow(q, n) - 1), 1e-14);
  EXPECT_NEAR(a.width(-1), a.width(0), 1e-15);
  EXPECT_NEAR(a.width(n), a.width(n - 1), 1e-15);
  EXPECT_NEAR(a.centre(-1), min - 0.5 * a.width(0), 1e-15);
  EXPECT_NEAR(a.centre(n), max + 0.5 * a.width(n - 1), 1e-15);
}

TEST(AxisCoordinates, StretchedGrowing) { expect_stretched(4.0, 10); }
TEST(AxisCoordinates, StretchedShrinking) { expect_stretched(0.2, 7); }
TEST(AxisCoordinates, StretchedTwoCells) { expect_stretched(3.0, 2); }

TEST(AxisCoordinates, OneCellIgnoresTheRatio) {
  const grid::AxisCoordinates a(axis(1.0, 3.0, 1, 5.0));
  EXPECT_EQ(a.width(0), 2.0);
  EXPECT_EQ(a.centre(0), 2.0);
  EXPECT_EQ(a.centre(-1), 0.0);
  EXPECT_EQ(a.centre(1), 4.0);
}

TEST(StructuredGrid, CentreAndVolume) {
  deck::Grid d = grid_of(4, 3, 2);
  d.z = axis(0.0, 1.0, 5, 2.0);
  const StructuredGrid g(d);
  double total = 0.0;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        const Index3 ijk{i, j, k};
        EXPECT_NEAR(g.volume(ijk), 0.1 * 0.1 * g.axis(2).width(k), 1e-15);
        const auto c = g.centre(ijk);
        EXPECT_NEAR(c[0], 0.05 + 0.1 * i, 1e-15);
        EXPECT_NEAR(c[1], 0.05 + 0.1 * j, 1e-15);
        EXPECT_EQ(c[2], g.axis(2).centre(k));
        total += g.volume(ijk);
      }
  EXPECT_NEAR(total, 0.4 * 0.3 * 1.0, 1e-14);
  // A ring cell has the volume of the cell it mirrors.
  EXPECT_NEAR(g.volume({-1, 0, 4}), g.volume({0, 0, 4}), 1e-16);
  EXPECT_NEAR(g.volume({0, 3, 5}), g.volume({0, 2, 4}), 1e-16);
  EXPECT_NEAR(g.centre({-1, -1, -1})[0], -0.05, 1e-15);
}

}  // namespace
}  // namespace bagnold::tests
