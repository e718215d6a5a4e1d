#pragma once
// Blocking primitives of the deck ([[geometry.block]]): whether a point is inside each shape.
// Walls are staircase approximations at the grid scale (a cell is blocked when its centre is);
// this file is the one place a cut-cell treatment would replace.

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

// Whether the block makes the cell whose centre is `x` solid. For cylinders and cones,
// blocks = "outside" blocks what lies around the shape between its end planes only.
bool blocks_point(const deck::Block& block, const Point& x);

}  // namespace bagnold::grid
