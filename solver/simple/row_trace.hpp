#pragma once
// BAGNOLD_TRACE_ROWS=f: every momentum row whose residual is more than f times its own weight
// (ε ρ V |g|), at every outer iteration, on stderr: which phase, component and cell, and the
// row's parts in newtons, so that a step that does not converge can be traced to the rows that
// hold it back and to what they balance (docs/troubleshooting.md, "A step does not converge").
// A row whose residual stays while its velocity keeps shrinking is a plastic row that cannot
// balance at its yield stress; one whose sources and neighbour terms are thousands of weights
// that nearly cancel is sheared through a large edge viscosity (docs/solver.md).
#include <cstdint>
#include <optional>
#include <string>

#include "src/parallel/communicator.hpp"
#include "src/parallel/domain.hpp"

namespace bagnold::solver {

class RowTrace {
 public:
  // One row's terms at the current iterate [N, kg/s, m/s].
  struct Row {
    int phase = 0;      // 0 gas, 1 solids
    int component = 0;  // d
    std::int64_t owner = 0, plus = -1;  // natural indices of the owning cell and its + neighbour along d
    double residual = 0.0;   // s − L u
    double weight = 0.0;     // ε ρ V |g|
    double force = 0.0;      // F of the force norm (momentum_residual.hpp)
    double diagonal = 0.0;   // A
    double velocity = 0.0;   // u
    double sources = 0.0;    // s: b + βV u_other
    double neighbours = 0.0; // Σ a_nb u_nb
    double viscous = 0.0;    // the viscous force on the control volume
  };

  // Reads BAGNOLD_TRACE_ROWS once: off when unset, empty or not a positive number.
  RowTrace();
  // A threshold given directly (tests): off when not positive.
  explicit RowTrace(double fraction) : m_fraction(fraction > 0.0 ? std::optional(fraction) : std::nullopt) {}

  bool on() const { return m_fraction.has_value(); }
  // Whether `row` is printed: its residual above the fraction of its weight (any residual for a
  // row without weight, as under zero gravity, is judged against its force F instead).
  bool selects(const Row& row) const;
  // The row's line, without the newline: "row solids x (i, j, k) +x: r/w = ..., ...".
  std::string line(const parallel::Domain& domain, const Row& row) const;
  // Prints the line on stderr if the row is selected (with the rank when there are several).
  void report(const parallel::Domain& domain, const parallel::Communicator& comm, const Row& row) const;

 private:
  // What a row's residual is measured against: its weight, or its force F where it has none.
  static double scale(const Row& row) { return row.weight > 0.0 ? row.weight : row.force; }

  std::optional<double> m_fraction;
};

}  // namespace bagnold::solver
