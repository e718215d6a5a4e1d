#pragma once
// Forward-mode automatic differentiation in one variable. The closures need dP_s/dε_s (the
// volume-fraction correction linearizes P_s through it, DESIGN.md step 4); writing every formula
// once as a template over the scalar type and evaluating it with Dual gives the exact derivative
// of the very expression that produces the value, so value and derivative cannot drift apart.
//
// Kinks (max, min, branch on φ) take the derivative of the branch that is selected.

#include <cmath>

namespace bagnold::models {

struct Dual {
  double value = 0.0;
  double slope = 0.0;  // d(value)/d(variable)

  constexpr Dual() = default;
  constexpr Dual(double v, double s = 0.0) : value(v), slope(s) {}  // NOLINT: constants promote
  static constexpr Dual variable(double v) { return {v, 1.0}; }
};

constexpr Dual operator+(Dual a, Dual b) { return {a.value + b.value, a.slope + b.slope}; }
constexpr Dual operator-(Dual a, Dual b) { return {a.value - b.value, a.slope - b.slope}; }
constexpr Dual operator-(Dual a) { return {-a.value, -a.slope}; }
constexpr Dual operator*(Dual a, Dual b) {
  return {a.value * b.value, a.slope * b.value + a.value * b.slope};
}
constexpr Dual operator/(Dual a, Dual b) {
  return {a.value / b.value, (a.slope * b.value - a.value * b.slope) / (b.value * b.value)};
}
constexpr Dual operator+(Dual a, double b) { return {a.value + b, a.slope}; }
constexpr Dual operator+(double a, Dual b) { return {a + b.value, b.slope}; }
constexpr Dual operator-(Dual a, double b) { return {a.value - b, a.slope}; }
constexpr Dual operator-(double a, Dual b) { return {a - b.value, -b.slope}; }
constexpr Dual operator*(Dual a, double b) { return {a.value * b, a.slope * b}; }
constexpr Dual operator*(double a, Dual b) { return {a * b.value, a * b.slope}; }
constexpr Dual operator/(Dual a, double b) { return {a.value / b, a.slope / b}; }
constexpr Dual operator/(double a, Dual b) { return Dual(a) / b; }

constexpr bool operator<(Dual a, Dual b) { return a.value < b.value; }
constexpr bool operator>(Dual a, Dual b) { return a.value > b.value; }
constexpr bool operator<=(Dual a, Dual b) { return a.value <= b.value; }
constexpr bool operator>=(Dual a, Dual b) { return a.value >= b.value; }

inline Dual sqrt(Dual a) {
  const double r = std::sqrt(a.value);
  return {r, a.slope == 0.0 ? 0.0 : a.slope / (2.0 * r)};
}
inline Dual exp(Dual a) {
  const double e = std::exp(a.value);
  return {e, e * a.slope};
}
// a^n for a real exponent; a slope of zero stays zero even where a^(n-1) is infinite, so a
// constant raised to a power never produces NaN through 0 * inf.
inline Dual pow(Dual a, double n) {
  const double p = std::pow(a.value, n);
  return {p, a.slope == 0.0 ? 0.0 : n * std::pow(a.value, n - 1.0) * a.slope};
}
inline Dual abs(Dual a) { return a.value < 0.0 ? -a : a; }

// The value of a double or a Dual, so templated formulas can branch on it.
constexpr double value_of(double x) { return x; }
constexpr double value_of(Dual x) { return x.value; }

// x^{3/2} as x √x, for a double or a Dual: several times cheaper than pow, which dominated the
// closures' cost per cell.
template <class Real>
Real three_halves_power(Real x) {
  using std::sqrt;
  return x * sqrt(x);
}

}  // namespace bagnold::models
