#pragma once
// An inexact Newton method with a Jacobian-free Krylov solve: F(u) = 0 for a vector u of this
// rank's unknowns, each Newton step δ from J δ = −F(u), J v ≈ (F(u + h v) − F(u)) / h, by
// right-preconditioned flexible GMRES (Saad, SIAM J. Sci. Comput. 14, 1993), then a backtracking
// line search on ||F|| (Knoll & Keyes, J. Comput. Phys. 193, 2004, Secs. 2–3, review the method).
//
// The problem gives F, a preconditioner z ≈ J⁻¹ v (which may change between calls: hence the
// flexible variant) and the global dot product; the method knows nothing of the flow.
#include <functional>
#include <vector>

namespace bagnold::solver {

struct NewtonKrylovProblem {
  // F at u into f (same size). Returns false if F could not be evaluated (e.g. not finite).
  std::function<bool(const std::vector<double>& u, std::vector<double>& f)> residual;
  // z ≈ J⁻¹ v. Returns false if the preconditioner failed.
  std::function<bool(const std::vector<double>& v, std::vector<double>& z)> precondition;
  // Σ over every rank of a · b.
  std::function<double(const std::vector<double>& a, const std::vector<double>& b)> dot;
};

struct NewtonKrylovSettings {
  int newton_steps = 4;         // at most
  int krylov_dimension = 20;    // GMRES vectors per Newton step (no restart)
  double krylov_tolerance = 0.05;  // each Newton step's linear residual, relative to ||F||
  double target = 0.0;          // stop when ||F|| is at or below this
};

struct NewtonKrylovReport {
  int newton_steps = 0, krylov_iterations = 0, residual_evaluations = 0;
  double first = 0.0, last = 0.0;  // ||F|| at the start and at the end
  bool evaluated = true;           // false: F or the preconditioner failed
};

// Improves u in place; F at the returned u was the last evaluation made (so a caller whose F
// leaves state behind holds the state of the returned u).
NewtonKrylovReport newton_krylov(const NewtonKrylovProblem& problem, const NewtonKrylovSettings& settings,
                                 std::vector<double>& u);

}  // namespace bagnold::solver
