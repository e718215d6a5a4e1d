// The Jacobian-free Newton-Krylov method (solver/simple/newton_krylov.hpp) on a problem whose
// answer is known: a 1-D reaction-diffusion system k (2u_i − u_{i−1} − u_{i+1}) + u_i³ = b_i,
// with b made from a chosen u*, preconditioned by the inverse of its linear part only.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/simple/newton_krylov.hpp"

namespace bagnold::tests {
namespace {

constexpr std::size_t n = 60;
constexpr double k = 50.0;

std::vector<double> operator_of(const std::vector<double>& u) {
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double left = i > 0 ? u[i - 1] : 0.0, right = i + 1 < n ? u[i + 1] : 0.0;
    out[i] = k * (2.0 * u[i] - left - right) + u[i] * u[i] * u[i];
  }
  return out;
}

// (k L + I)⁻¹ v by the Thomas algorithm: the linear part, with the cubic's slope taken as 1.
std::vector<double> linear_inverse(const std::vector<double>& v) {
  std::vector<double> c(n), d(n), x(n);
  const double diagonal = 2.0 * k + 1.0, off = -k;
  c[0] = off / diagonal;
  d[0] = v[0] / diagonal;
  for (std::size_t i = 1; i < n; ++i) {
    const double m = diagonal - off * c[i - 1];
    c[i] = off / m;
    d[i] = (v[i] - off * d[i - 1]) / m;
  }
  x[n - 1] = d[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) x[i] = d[i] - c[i] * x[i + 1];
  return x;
}

struct Problem {
  Problem() : exact(n), b(n) {
    for (std::size_t i = 0; i < n; ++i) exact[i] = 3.0 * std::sin(0.1 * static_cast<double>(i)) + 1.0;
    b = operator_of(exact);
    problem.residual = [this](const std::vector<double>& u, std::vector<double>& f) {
      last_evaluated = u;
      f = operator_of(u);
      for (std::size_t i = 0; i < n; ++i) f[i] -= b[i];
      return true;
    };
    problem.precondition = [](const std::vector<double>& v, std::vector<double>& z) {
      z = linear_inverse(v);
      return true;
    };
    problem.dot = [](const std::vector<double>& a, const std::vector<double>& c) {
      double s = 0.0;
      for (std::size_t i = 0; i < n; ++i) s += a[i] * c[i];
      return s;
    };
  }
  std::vector<double> exact, b, last_evaluated;
  solver::NewtonKrylovProblem problem;
};

TEST(NewtonKrylov, ConvergesWhereTheCubicMakesThePreconditionerPoor) {
  Problem p;
  std::vector<double> u(n, 0.0);
  solver::NewtonKrylovSettings settings;
  settings.newton_steps = 12;
  settings.krylov_dimension = 30;
  settings.krylov_tolerance = 1e-3;
  settings.target = 1e-9;
  const auto report = solver::newton_krylov(p.problem, settings, u);
  ASSERT_TRUE(report.evaluated);
  EXPECT_LE(report.last, 1e-9);
  EXPECT_GT(report.first, 100.0);  // far from the answer at the start (u³ up to 64)
  EXPECT_LE(report.newton_steps, 10);
  double error = 0.0;
  for (std::size_t i = 0; i < n; ++i) error = std::max(error, std::abs(u[i] - p.exact[i]));
  EXPECT_LT(error, 1e-9);
  // The last F evaluated was at the returned u (a caller's state follows F).
  EXPECT_EQ(p.last_evaluated, u);
}

TEST(NewtonKrylov, StopsAtTheTargetAndCountsItsWork) {
  Problem p;
  std::vector<double> u(n, 0.0);
  solver::NewtonKrylovSettings settings;
  settings.newton_steps = 12;
  settings.target = 1.0;
  const auto report = solver::newton_krylov(p.problem, settings, u);
  EXPECT_LE(report.last, 1.0);
  EXPECT_GT(report.last, 1e-9);  // stopped there, not at the answer
  EXPECT_GE(report.residual_evaluations, report.krylov_iterations + report.newton_steps + 1);
  EXPECT_EQ(p.last_evaluated, u);
}

TEST(NewtonKrylov, ReportsAFailedPreconditioner) {
  Problem p;
  p.problem.precondition = [](const std::vector<double>&, std::vector<double>&) { return false; };
  std::vector<double> u(n, 0.0);
  const auto report = solver::newton_krylov(p.problem, {}, u);
  EXPECT_FALSE(report.evaluated);
}

}  // namespace
}  // namespace bagnold::tests
