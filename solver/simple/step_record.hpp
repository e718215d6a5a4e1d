#pragma once
// What one outer iteration records besides the new iterate: the local partial sums of every
// residual (reduced over the ranks in one Allreduce at the end of the iteration), where each
// equation's residual is largest, how often a numerical limiter changed a value, and the
// linear solvers' iteration counts. StepResult carries the sums of a step to the monitor.

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "solver/simple/momentum_residual.hpp"
#include "src/grid/structured_grid.hpp"
#include "src/parallel/communicator.hpp"

namespace bagnold::solver {

// The equations whose residuals a step watches, in this order.
enum Equation : int {
  gas_momentum_x, gas_momentum_y, gas_momentum_z,
  solids_momentum_x, solids_momentum_y, solids_momentum_z,
  mixture_continuity, solids_continuity,
  granular_energy,  // 0 unless Θ is transported
  equation_count
};
const char* equation_name(int equation);
inline int momentum_equation(int phase, int d) { return (phase == 0 ? gas_momentum_x : solids_momentum_x) + d; }

struct Residuals {
  std::array<double, equation_count> value{};  // normalized, per Equation
  double largest() const;
  int worst() const;  // the Equation with the largest (NaN counts as largest)
};

// Each numerical limiter that can change a value in an outer iteration, counted per cell (or
// per iteration for the velocity scale) each time it acts. The monitor has a column for each.
enum Intervention : int {
  compression_damped,        // CompressionLimit halved a compressing ε' (cells)
  fraction_clamped_at_zero,  // a correction would have made ε_s negative (cells)
  negative_stiffness,        // dP_s/dε_s < 0 kept explicit in e (unknown faces)
  velocity_scale_capped,     // the residual velocity scale held at 10× the step start's (iterations)
  velocity_scale_floored,    // the residual velocity scale raised to 1e-3 of the reference speed (iterations)
  anderson_clipped,          // an Anderson mixture's ε_s clipped into the images' range (cells)
  temperature_clamped_at_zero,  // the Θ solve left Θ < 0 (linear-solver round-off), set to 0 (cells)
  intervention_count
};
const char* intervention_name(int intervention);  // the monitor column

// The linear systems of an outer iteration.
enum LinearSystemKind : int {
  momentum_systems, pressure_system, fraction_system, energy_system, linear_system_count
};
const char* linear_system_name(int kind);  // the monitor column

// Local partial sums of one outer iteration; reduce() adds them over the ranks at once.
struct IterationSums {
  std::array<MomentumResidual::Sums, 6> momentum{};      // per momentum Equation
  std::array<MomentumResidual, 6> normalization{};       // how each turns into a residual
  // mixture, solids: {Σ|R|, Σ ½|Q|}; the solids' in forces under the "force" norm
  // (volume_fraction_correction.cpp)
  std::array<std::array<double, 2>, 2> continuity{};
  std::array<double, 2> energy{};                        // granular energy: {Σ|R|, its scale}
  std::array<double, intervention_count> interventions{};
  std::array<std::array<double, 3>, 2> wall_shear{};    // the walls' tangential force [N], per phase and d
  double stop = 0.0;  // > 0 on a rank asked to stop (a signal): every rank learns it in reduce()
  void reduce(const parallel::Communicator& comm);
};

// Whether an outer iteration, its sums reduced over the ranks, ends the step: its largest
// normalized residual is below the tolerance and no correction of the iteration was truncated.
// Where CompressionLimit damped ε', that cell's solids continuity does not hold, however small
// the residual summed over the domain (a few cells' imbalance hides in the sum), and the
// conservative update after convergence (solids_conservation.hpp) would put the whole compression
// back, into the closure's stiffest range: the next step then starts from a P_s orders of
// magnitude too high (docs/solver.md, step 5).
bool iteration_converged(double largest, double tolerance, const IterationSums& sums);

// The normalized momentum residuals of reduced `sums` into result.residuals, and the largest force
// balance (MomentumResidual::force_balance) with its equation into result.force_balance(_equation).
struct StepResult;
void judge_momentum(const IterationSums& sums, StepResult& result);

// Where an equation's residual is largest: for the message when a run cannot continue. Always a
// fluid cell; for a momentum equation also which of its faces carries the velocity and, when
// that face is on the domain's boundary, the boundary region beyond it.
struct CellLocation {
  grid::Index3 cell{0, 0, 0};
  std::array<double, 3> position{0, 0, 0};  // cell centre [m]
  std::string face;    // "+z", "-x", ...: the face of a momentum equation's row; empty otherwise
  std::string region;  // the boundary region beyond that face, empty inside the fluid
  std::string text() const;  // "cell (i, j, k) at (x, y, z) m[, its +z face (on region 'r')]"
};

// The local cell of each equation's largest row residual in the current outer iteration.
class WorstCells {
 public:
  void reset(int equation);
  void record(int equation, double row_residual, int local) {
    const auto e = static_cast<std::size_t>(equation);
    if (!(row_residual <= m_value[e])) {  // NaN is the worst
      m_value[e] = row_residual != row_residual ? INFINITY : row_residual;
      m_local[e] = local;
    }
  }
  double value(int equation) const { return m_value[static_cast<std::size_t>(equation)]; }
  int local(int equation) const { return m_local[static_cast<std::size_t>(equation)]; }

 private:
  std::array<double, equation_count> m_value{};
  std::array<int, equation_count> m_local{};
};

// numerics.detect_stall, MFIX's DETECT_STALL (CHECK_CONVERGENCE in MFIX 21.3): every
// stall_interval outer iterations the largest residual is compared with its value that many
// iterations before; from the third comparison on (iteration 15), one that has not fallen means
// the step has stalled, and it is redone with a smaller dt instead of running on to
// numerics.max_outer_iterations.
class StallWatch {
 public:
  static constexpr int stall_interval = 5;
  // Whether the step has stalled, given the largest residual of outer iteration `iteration`
  // (1, 2, ...; called once per iteration, in order).
  bool has_stalled_after(int iteration, double largest) {
    if (iteration % stall_interval != 0) return false;
    const bool stalled = iteration > 2 * stall_interval && !(largest < m_checkpoint);
    m_checkpoint = largest;
    return stalled;
  }

 private:
  double m_checkpoint = INFINITY;
};

struct StepResult {
  bool converged = false;
  bool stalled = false;  // stopped by numerics.detect_stall (StallWatch)
  int iterations = 0;
  Residuals residuals;  // of the last outer iteration
  double first_largest = 0.0;  // the largest residual of the first outer iteration
  // What the last outer iteration was judged by against numerics.tolerance: the largest
  // normalized residual, or under numerics.residual_normalization = "mfix" their sum.
  double judged = 0.0;
  // The momentum residuals of the state the last outer iteration judged (the iterate it started
  // from, as every residual here) against the forces that act, whatever
  // numerics.residual_normalization judged it by: the largest over both phases and the three
  // components of MomentumResidual::force_balance (the "force" norm's momentum residual).
  double force_balance = 0.0;
  int force_balance_equation = 0;  // the momentum Equation it is of
  // "diverged" when a residual became non-finite or the largest grew over the step's outer
  // iterations; "stalled" when it fell but not below the tolerance.
  bool diverged() const;
  // Summed over the step's outer iterations and all ranks.
  std::array<double, intervention_count> interventions{};
  std::array<double, linear_system_count> linear_iterations{};
  // The tangential force the walls exert on each phase [N] (gas, solids; x, y, z), from the last
  // outer iteration's momentum rows, summed over all ranks.
  std::array<std::array<double, 3>, 2> wall_shear{};
  std::string failure;  // why the step stopped early (a linear solve that failed), else empty
  bool abandoned = false;  // stopped on request (a signal) between two outer iterations
};

}  // namespace bagnold::solver
