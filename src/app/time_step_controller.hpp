#pragma once
// The adaptive time step of a run (time_loop.hpp calls it after every step).
//
//   - A step that fails is redone with dt / 2 (failed()). One that fails again within a growth
//     factor below a failure of the last cost_memory_steps steps has found the flow's limit:
//     dt then does not grow back to it, or above it, for cost_memory_steps steps. Without that
//     the 10 mm bin with MKT at onset_smoothing 1e-4, which fails at 0.6-0.7 ms and converges
//     in 3-4 outer iterations below, regrew into the failing dt every few steps (128 of 582
//     steps redone to 0.2 s, 40 outer iterations lost in each). A first failure does not hold
//     dt back, so a start-up's failures at falling dt are not (the hourglass from rest).
//   - After a converged step: it grows by numerics.dt_growth (up to run.dt_max) when it took at
//     most numerics.easy_outer_iterations; it shrinks by dt_growth when it took more than
//     numerics.hard_outer_iterations (if set), not below run.dt_max / 4.
//   - Cost memory: each full step records its cost, outer iterations per simulated second, at
//     its dt. A step does not grow into a dt whose recorded cost (within the last
//     cost_memory_steps steps) is at least its own, so dt settles on the cheaper of two levels
//     instead of cycling between an easy and a hard one (the 10 mm bin cycled between 0.892 and
//     1.07 ms, 8 and 22 outer iterations, for the whole discharge). Older records are forgotten,
//     so dt probes upwards again as the flow changes.
//   - Courant limit: the next dt keeps the step's Courant number, max over both phases' face
//     velocities of |u| dt/δ, at most numerics.max_courant (within a 2 % dead band, so a
//     slowly changing velocity does not change dt at every step).

#include <string>
#include <vector>

#include "src/deck/deck.hpp"

namespace bagnold::app {

class TimeStepController {
 public:
  TimeStepController(const deck::RunControl& run, const deck::Numerics& numerics, double dt);

  double dt() const { return m_dt; }

  // A converged step of length `taken` (dt(), or less where it was shortened to land on a
  // snapshot or the end), in `iterations` outer iterations, with Courant number `courant`.
  // Returns why dt changed, or an empty string.
  std::string converged(double taken, int iterations, double courant, long step);
  // A step of length `taken` that did not converge after `step` steps: dt becomes taken / 2,
  // and dt will not grow to `taken` or above while this is remembered.
  void failed(double taken, long step);

  // The recorded costs as (dt, per second, step) triples, for a snapshot, and back: a restart
  // continues with the same memory, so it takes the same steps as the run it continues.
  std::vector<double> memory() const;
  void restore(const std::vector<double>& memory);

 private:
  struct Cost {
    double dt;             // [s]
    double per_second;     // outer iterations per simulated second; negative: the step
                           // failed, and dt stays below it for -1 - per_second steps
    long step;             // when it was measured
    bool failed() const { return per_second < 0.0; }
    long memory() const { return static_cast<long>(-1.0 - per_second); }
  };
  const Cost* recorded(double dt, long step) const;
  bool failed_at_or_below(double dt, long step) const;
  void record(double dt, double per_second, long step);

  double m_dt;
  double m_dt_max, m_dt_min, m_growth, m_max_courant;
  int m_easy, m_hard;
  std::vector<Cost> m_costs;
};

}  // namespace bagnold::app
