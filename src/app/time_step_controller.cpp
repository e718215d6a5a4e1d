#include "src/app/time_step_controller.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace bagnold::app {

namespace {
// Hard steps (numerics.hard_outer_iterations) shrink dt down to this fraction of run.dt_max
// (and never below run.dt_min): far below it a step is hard for other reasons (a bed
// compacting from rest takes 10-15 outer iterations at any dt) and shrinking only adds steps.
constexpr double hard_step_floor = 0.25;
// How many steps a dt's recorded cost is trusted. Long enough to hold dt through a discharge's
// slow change (the bin's 0.1 s at 1 ms steps), short enough that dt probes upwards again when
// the flow has changed.
constexpr long cost_memory_steps = 100;
// Two dt values within this relative distance are the same level of the growth ladder.
constexpr double same_level = 1e-9;
// A Courant-limited dt within this fraction of the current one keeps the current one (the
// Courant number may then exceed numerics.max_courant by as much), so a slowly changing
// velocity does not change dt, and log a line, at every step.
constexpr double courant_dead_band = 0.02;
}  // namespace

TimeStepController::TimeStepController(const deck::RunControl& run, const deck::Numerics& numerics,
                                       double dt)
    : m_dt(dt),
      m_dt_max(run.dt_max),
      m_dt_min(run.dt_min),
      m_growth(numerics.dt_growth),
      m_max_courant(numerics.max_courant),
      m_easy(numerics.easy_outer_iterations),
      m_hard(numerics.hard_outer_iterations) {}

const TimeStepController::Cost* TimeStepController::recorded(double dt, long step) const {
  for (const auto& c : m_costs)
    if (!c.failed() && std::abs(c.dt - dt) <= same_level * dt &&
        step - c.step <= cost_memory_steps)
      return &c;
  return nullptr;
}

bool TimeStepController::failed_at_or_below(double dt, long step) const {
  return std::any_of(m_costs.begin(), m_costs.end(), [&](const Cost& c) {
    return c.failed() && c.dt <= dt * (1 + same_level) && step - c.step <= c.memory();
  });
}

void TimeStepController::failed(double taken, long step) {
  // A first failure does not hold dt back: a start-up drives dt down through failures that
  // later steps need not respect (the hourglass from rest fails six times in its first 0.6 ms,
  // at dt falling to 1.6e-5 s; holding dt below each for 20 steps cost it 4 % more outer
  // iterations to 0.6 s, for 100 steps 30 %). It is kept cost_memory_steps steps to recognize a
  // repeat, a failure within a growth factor below it: that is the flow's limit (the 10 mm MKT
  // bin at onset_smoothing 1e-4 failed at 0.6-0.7 ms for the whole discharge), and it holds
  // dt below it for cost_memory_steps steps.
  const bool again = std::any_of(m_costs.begin(), m_costs.end(), [&](const Cost& c) {
    return c.failed() && taken * m_growth >= c.dt * (1 - same_level) &&
           step - c.step <= c.memory() + cost_memory_steps;
  });
  record(taken, -1.0 - static_cast<double>(again ? cost_memory_steps : 0), step);
  m_dt = 0.5 * taken;
}

void TimeStepController::record(double dt, double per_second, long step) {
  // Records never read again are dropped, so the memory (written into every snapshot) stays
  // small: a cost after cost_memory_steps, a failure that long after it is forgotten.
  std::erase_if(m_costs, [&](const Cost& c) {
    return step - c.step > (c.failed() ? c.memory() : 0) + cost_memory_steps;
  });
  for (auto& c : m_costs)
    if (std::abs(c.dt - dt) <= same_level * dt) {
      c = {dt, per_second, step};
      return;
    }
  m_costs.push_back({dt, per_second, step});
}

std::vector<double> TimeStepController::memory() const {
  std::vector<double> out;
  for (const auto& c : m_costs) out.insert(out.end(), {c.dt, c.per_second, static_cast<double>(c.step)});
  return out;
}

void TimeStepController::restore(const std::vector<double>& memory) {
  m_costs.clear();
  for (std::size_t i = 0; i + 2 < memory.size(); i += 3)
    m_costs.push_back({memory[i], memory[i + 1], static_cast<long>(memory[i + 2])});
}

std::string TimeStepController::converged(double taken, int iterations, double courant, long step) {
  const double dt = m_dt;
  const bool full = taken >= dt * (1 - 1e-12);
  const double cost = iterations / dt;
  if (full) record(dt, cost, step);

  double next = dt;
  std::string why;
  if (iterations <= m_easy && full && dt < m_dt_max) {
    const double up = std::min(dt * m_growth, m_dt_max);
    const Cost* above = recorded(up, step);
    if ((!above || above->per_second < cost) && !failed_at_or_below(up, step)) {
      next = up;
      why = fmt::format("converged in {} outer iterations", iterations);
    }
  } else if (m_hard > 0 && iterations > m_hard &&
             dt / m_growth >= std::max(hard_step_floor * m_dt_max, m_dt_min)) {
    // The outer iterations per step grow faster than dt near the coupling's limit (the 2.5 mm
    // bin: 5.75 at 1 ms, 16.3 at 1.53 ms), so a hard step is cheaper done as two easier ones.
    next = dt / m_growth;
    why = fmt::format("converged in {} outer iterations", iterations);
  }
  // The Courant limit, on the step just taken scaled to the next dt.
  if (courant > 0.0 && taken > 0.0) {
    const double limit = std::max(taken * m_max_courant / courant, m_dt_min);
    if (next > limit) {
      why = fmt::format("Courant number {:.3g} at dt {:.3g} s (numerics.max_courant {:.3g})",
                        courant * next / taken, next, m_max_courant);
      next = limit >= dt * (1 - courant_dead_band) && limit < dt ? dt : limit;
    }
  }
  if (next == dt) return {};
  m_dt = next;
  return fmt::format("{}; dt {:.3g} s -> {:.3g} s", why, dt, next);
}

}  // namespace bagnold::app
