#pragma once
// Blocking primitives of the deck ([[geometry.block]]): whether a point is inside each shape.
// Walls are staircase approximations at the grid scale (a cell is blocked when its centre is);
// this file is the one place a cut-cell treatment would replace. For that, the curved shapes
// also give their implicit function and its gradient (the quadric below), from which a cut-cell
// code can find where the wall crosses a cell edge (f = 0) and its normal (∇f / |∇f|).

#include <array>

#include "src/deck/deck.hpp"

namespace bagnold::grid {

using Point = std::array<double, 3>;

bool inside_box(const Point& x, const Point& min, const Point& max);
bool inside_half_space(const Point& x, const Point& point, const Point& normal);
// A frustum: a disc of `radius` at `base`, of `top_radius` at base + length * axis/|axis|.
// A point is inside it, outside it (radially, between its end planes) or beyond its ends.
enum class FrustumSide { inside, outside, beyond_ends };
FrustumSide frustum_side(const Point& x, const Point& base, const Point& axis, double length,
                         double radius, double top_radius);

// One piece of a piecewise quadric wall, the form in which MFIX's cut-cell geometry describes
// its hoppers (its 2-D hourglass is a hyperbola between two circles): the implicit function
//   f(x) = (x − c)ᵀ A (x − c) + bᵀ (x − c) + f0,
// inside where f < 0, valid where lower ≤ x[along] ≤ upper. Pieces over adjacent ranges make
// one wall; where two pieces meet tangentially, f = 0 at the same points on the joint plane and
// the normals ∇f agree in direction.
// Why quadrics rather than an extruded width profile w(z): they write MFIX's walls exactly (the
// same three formulas, no tabulated approximation), they are 3-D (a full A gives cones,
// cylinders, spheres and hyperboloids along any axis, so one shape serves 2-D and 3-D hoppers),
// and f with ∇f is what a cut-cell code needs: the wall's crossing of a cell edge (f = 0) and its
// normal.
struct QuadricPiece {
  Point centre{0, 0, 0};
  std::array<double, 9> matrix{};  // A, row by row
  Point linear{0, 0, 0};
  double constant = 0.0;
  int along = 2;  // 0, 1, 2: x, y, z
  double lower = 0.0, upper = 0.0;

  double value(const Point& x) const;     // f(x)
  Point gradient(const Point& x) const;   // ∇f = (A + Aᵀ)(x − c) + b
  bool in_range(const Point& x) const { return x[along] >= lower && x[along] <= upper; }
  // f / |∇f|: the signed distance to the surface to first order (negative inside), exact for a
  // plane; infinite where ∇f = 0 (the centre of a sphere, the saddle of a hyperbola).
  double distance_estimate(const Point& x) const;
};

// The quadric of a block with shape = "quadric" (its matrix of 3 entries is the diagonal).
QuadricPiece quadric_of(const deck::Block& block);

// Whether the block makes the cell whose centre is `x` solid. For cylinders and cones,
// blocks = "outside" blocks what lies around the shape between its end planes only; for a
// quadric, blocks = "outside" blocks f ≥ 0 and "inside" f < 0, within its range only.
bool blocks_point(const deck::Block& block, const Point& x);

}  // namespace bagnold::grid
