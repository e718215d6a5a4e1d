// Jacobian-free Newton-Krylov with flexible GMRES and backtracking (newton_krylov.hpp).
#include "solver/simple/newton_krylov.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

namespace bagnold::solver {

namespace {
using Vector = std::vector<double>;

void axpy(double a, const Vector& x, Vector& y) {
  for (std::size_t i = 0; i < y.size(); ++i) y[i] += a * x[i];
}

// Flexible GMRES on J δ = rhs from δ = 0, J v by a forward difference of F about u (f = F(u)).
// Returns false if F or the preconditioner failed.
bool flexible_gmres(const NewtonKrylovProblem& problem, const NewtonKrylovSettings& settings,
                    const Vector& u, const Vector& f, const Vector& rhs, Vector& delta,
                    NewtonKrylovReport& report) {
  const std::size_t n = u.size();
  const int m = settings.krylov_dimension;
  const double beta = std::sqrt(problem.dot(rhs, rhs));
  delta.assign(n, 0.0);
  if (!(beta > 0.0)) return true;
  const double u_norm = std::sqrt(problem.dot(u, u));
  std::vector<Vector> v(static_cast<std::size_t>(m + 1), Vector(n)), z(static_cast<std::size_t>(m), Vector(n));
  std::vector<std::vector<double>> h(static_cast<std::size_t>(m + 1), std::vector<double>(static_cast<std::size_t>(m), 0.0));
  std::vector<double> cs(static_cast<std::size_t>(m)), sn(static_cast<std::size_t>(m)), g(static_cast<std::size_t>(m + 1), 0.0);
  for (std::size_t i = 0; i < n; ++i) v[0][i] = rhs[i] / beta;
  g[0] = beta;
  Vector shifted(n), f_shifted(n);
  int k = 0;
  for (; k < m; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    if (!problem.precondition(v[uk], z[uk])) return false;
    // J z by a forward difference, h as PETSc's MatMFFD "wp": √ε (1 + ||u||) / ||z||.
    const double z_norm = std::sqrt(problem.dot(z[uk], z[uk]));
    if (!(z_norm > 0.0)) break;
    const double step = std::sqrt(std::numeric_limits<double>::epsilon()) * (1.0 + u_norm) / z_norm;
    for (std::size_t i = 0; i < n; ++i) shifted[i] = u[i] + step * z[uk][i];
    ++report.residual_evaluations;
    if (!problem.residual(shifted, f_shifted)) return false;
    Vector& w = v[uk + 1];
    for (std::size_t i = 0; i < n; ++i) w[i] = (f_shifted[i] - f[i]) / step;
    // Modified Gram-Schmidt.
    for (int i = 0; i <= k; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      h[ui][uk] = problem.dot(w, v[ui]);
      axpy(-h[ui][uk], v[ui], w);
    }
    h[uk + 1][uk] = std::sqrt(problem.dot(w, w));
    if (h[uk + 1][uk] > 0.0)
      for (double& x : w) x /= h[uk + 1][uk];
    // Givens rotations keep H upper triangular and g the residual's components.
    for (int i = 0; i < k; ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const double t = cs[ui] * h[ui][uk] + sn[ui] * h[ui + 1][uk];
      h[ui + 1][uk] = -sn[ui] * h[ui][uk] + cs[ui] * h[ui + 1][uk];
      h[ui][uk] = t;
    }
    const double r = std::hypot(h[uk][uk], h[uk + 1][uk]);
    cs[uk] = r > 0.0 ? h[uk][uk] / r : 1.0;
    sn[uk] = r > 0.0 ? h[uk + 1][uk] / r : 0.0;
    h[uk][uk] = r;
    h[uk + 1][uk] = 0.0;
    g[uk + 1] = -sn[uk] * g[uk];
    g[uk] = cs[uk] * g[uk];
    ++report.krylov_iterations;
    if (std::abs(g[uk + 1]) <= settings.krylov_tolerance * beta) {
      ++k;
      break;
    }
  }
  // H y = g, δ = Σ y_i z_i.
  std::vector<double> y(static_cast<std::size_t>(k), 0.0);
  for (int i = k - 1; i >= 0; --i) {
    const auto ui = static_cast<std::size_t>(i);
    double s = g[ui];
    for (int j = i + 1; j < k; ++j) s -= h[ui][static_cast<std::size_t>(j)] * y[static_cast<std::size_t>(j)];
    y[ui] = h[ui][ui] != 0.0 ? s / h[ui][ui] : 0.0;
  }
  for (int i = 0; i < k; ++i) axpy(y[static_cast<std::size_t>(i)], z[static_cast<std::size_t>(i)], delta);
  return true;
}
}  // namespace

NewtonKrylovReport newton_krylov(const NewtonKrylovProblem& problem, const NewtonKrylovSettings& settings,
                                 std::vector<double>& u) {
  NewtonKrylovReport report;
  const std::size_t n = u.size();
  Vector f(n), rhs(n), delta(n), trial(n), f_trial(n);
  auto norm = [&](const Vector& x) { return std::sqrt(problem.dot(x, x)); };
  ++report.residual_evaluations;
  if (!problem.residual(u, f)) {
    report.evaluated = false;
    return report;
  }
  report.first = report.last = norm(f);
  bool state_at_u = true;  // the last F evaluated was at u
  for (int step = 0; step < settings.newton_steps && report.last > settings.target; ++step) {
    for (std::size_t i = 0; i < n; ++i) rhs[i] = -f[i];
    if (!flexible_gmres(problem, settings, u, f, rhs, delta, report)) {
      report.evaluated = false;
      return report;
    }
    state_at_u = false;
    ++report.newton_steps;
    // Backtracking: the longest of 1, ½, ¼, ..., 1/64 that lowers ||F|| (Armijo, 10⁻⁴).
    bool accepted = false;
    for (double lambda = 1.0; lambda >= 1.0 / 64.0 && !accepted; lambda *= 0.5) {
      for (std::size_t i = 0; i < n; ++i) trial[i] = u[i] + lambda * delta[i];
      ++report.residual_evaluations;
      if (!problem.residual(trial, f_trial)) continue;
      const double trial_norm = norm(f_trial);
      if (std::isfinite(trial_norm) && trial_norm <= (1.0 - 1e-4 * lambda) * report.last) {
        u.swap(trial);
        f.swap(f_trial);
        report.last = trial_norm;
        accepted = true;
        state_at_u = true;
      }
    }
    if (!accepted) break;
  }
  if (!state_at_u) {
    ++report.residual_evaluations;
    if (!problem.residual(u, f)) report.evaluated = false;
  }
  return report;
}

}  // namespace bagnold::solver
