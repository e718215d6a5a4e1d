#include "src/grid/shapes.hpp"

#include <cmath>
#include <limits>

namespace bagnold::grid {

namespace {
double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
}  // namespace

bool inside_box(const Point& x, const Point& min, const Point& max) {
  for (int d = 0; d < 3; ++d)
    if (x[d] < min[d] || x[d] > max[d]) return false;
  return true;
}

bool inside_half_space(const Point& x, const Point& point, const Point& normal) {
  return dot({x[0] - point[0], x[1] - point[1], x[2] - point[2]}, normal) > 0.0;
}

FrustumSide frustum_side(const Point& x, const Point& base, const Point& axis, double length,
                         double radius, double top_radius) {
  const double norm = std::sqrt(dot(axis, axis));
  if (norm == 0.0) return FrustumSide::beyond_ends;
  const Point a{axis[0] / norm, axis[1] / norm, axis[2] / norm};
  const Point r{x[0] - base[0], x[1] - base[1], x[2] - base[2]};
  const double t = dot(r, a);
  if (t < 0.0 || t > length) return FrustumSide::beyond_ends;
  const Point radial{r[0] - t * a[0], r[1] - t * a[1], r[2] - t * a[2]};
  const double local_radius = radius + (top_radius - radius) * t / length;
  return dot(radial, radial) <= local_radius * local_radius ? FrustumSide::inside
                                                            : FrustumSide::outside;
}

double QuadricPiece::value(const Point& x) const {
  const Point r{x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
  double f = constant + dot(linear, r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) f += r[i] * matrix[3 * i + j] * r[j];
  return f;
}

Point QuadricPiece::gradient(const Point& x) const {
  const Point r{x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
  Point g = linear;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) g[i] += (matrix[3 * i + j] + matrix[3 * j + i]) * r[j];
  return g;
}

double QuadricPiece::distance_estimate(const Point& x) const {
  const Point g = gradient(x);
  const double norm = std::sqrt(dot(g, g));
  const double f = value(x);
  if (norm == 0.0) return f < 0.0 ? -std::numeric_limits<double>::infinity()
                                  : std::numeric_limits<double>::infinity();
  return f / norm;
}

QuadricPiece quadric_of(const deck::Block& b) {
  QuadricPiece q;
  q.centre = b.centre;
  if (b.matrix.size() == 3) {
    for (int i = 0; i < 3; ++i) q.matrix[4 * i] = b.matrix[i];
  } else {
    for (std::size_t k = 0; k < 9 && k < b.matrix.size(); ++k) q.matrix[k] = b.matrix[k];
  }
  q.linear = b.linear;
  q.constant = b.constant;
  q.along = b.along == "x" ? 0 : b.along == "y" ? 1 : 2;
  q.lower = b.range.size() == 2 ? b.range[0] : -std::numeric_limits<double>::infinity();
  q.upper = b.range.size() == 2 ? b.range[1] : std::numeric_limits<double>::infinity();
  return q;
}

bool blocks_point(const deck::Block& b, const Point& x) {
  const bool block_inside = b.blocks == "inside";
  if (b.shape == "box") return inside_box(x, b.min, b.max) == block_inside;
  if (b.shape == "half_space") return inside_half_space(x, b.point, b.normal) == block_inside;
  if (b.shape == "quadric") {
    const QuadricPiece q = quadric_of(b);
    if (!q.in_range(x)) return false;
    return (q.value(x) < 0.0) == block_inside;
  }
  // Cylinder and cone: "outside" is the wall around the shape over its length (a hopper).
  const double top = b.shape == "cone" ? b.top_radius : b.radius;
  const auto side = frustum_side(x, b.base, b.axis, b.length, b.radius, top);
  return block_inside ? side == FrustumSide::inside : side == FrustumSide::outside;
}

}  // namespace bagnold::grid
