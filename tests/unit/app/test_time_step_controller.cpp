// The adaptive time step (src/app/time_step_controller.hpp): growth after easy steps, no cycle
// between an easy and a costlier level, a forgotten cost is probed again, the Courant limit,
// and dt / 2 after a failure.
#include <gtest/gtest.h>

#include <cmath>

#include "src/app/time_step_controller.hpp"

namespace bagnold::tests {
namespace {

struct Controls {
  deck::RunControl run;
  deck::Numerics numerics;
  Controls() {
    run.dt_max = 1e-2;
    numerics.easy_outer_iterations = 8;
    numerics.hard_outer_iterations = 12;
    numerics.dt_growth = 1.2;
    numerics.max_courant = 0.5;
  }
};

TEST(TimeStepController, EasyStepsGrowUpToDtMax) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  long step = 0;
  for (int i = 0; i < 30; ++i) dt.converged(dt.dt(), 4, 0.0, ++step);
  EXPECT_DOUBLE_EQ(dt.dt(), 1e-2);
}

// A step at 1 ms is easy (8 outer iterations), at 1.2 ms hard (22): without the cost memory dt
// alternates between them; with it dt stays at 1 ms until the record is forgotten.
TEST(TimeStepController, DoesNotCycleIntoACostlierLevel) {
  Controls c;
  c.run.dt_max = 2e-3;  // hard steps shrink dt down to dt_max / 4
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  auto iterations = [](double step) { return step < 1.1e-3 ? 8 : 22; };
  long step = 0;
  int probes = 0;
  for (int i = 0; i < 80; ++i) {
    const double taken = dt.dt();
    if (taken > 1.1e-3) ++probes;
    dt.converged(taken, iterations(taken), 0.0, ++step);
  }
  EXPECT_EQ(probes, 1);  // one step at 1.2 ms, then 1 ms throughout
  EXPECT_NEAR(dt.dt(), 1e-3, 1e-15);
  // After the memory (100 steps) the costlier level is probed once more.
  for (int i = 0; i < 60; ++i) {
    const double taken = dt.dt();
    if (taken > 1.1e-3) ++probes;
    dt.converged(taken, iterations(taken), 0.0, ++step);
  }
  EXPECT_EQ(probes, 2);
}

TEST(TimeStepController, GrowsIntoALevelThatProvedCheaper) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  // 1 ms costs 8 iterations (8,000 per s); 1.2 ms costs 9 (7,500 per s): worth growing into,
  // but 9 > easy, so dt grows again only from 1 ms.
  long step = 0;
  dt.converged(1e-3, 8, 0.0, ++step);
  EXPECT_NEAR(dt.dt(), 1.2e-3, 1e-15);
  dt.converged(1.2e-3, 9, 0.0, ++step);
  EXPECT_NEAR(dt.dt(), 1.2e-3, 1e-15);  // neither easy nor hard: kept
}

TEST(TimeStepController, CourantLimitCutsTheNextStep) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  const std::string why = dt.converged(1e-3, 4, 1.0, 1);  // easy, but C = 1 at 1 ms
  EXPECT_NEAR(dt.dt(), 0.5e-3, 1e-15);
  EXPECT_NE(why.find("Courant"), std::string::npos) << why;
  dt.converged(0.5e-3, 4, 0.45, 2);  // growth by 1.2 would give C = 0.54 > 0.5
  EXPECT_NEAR(dt.dt(), 0.5e-3 * 0.5 / 0.45, 1e-15);
}

TEST(TimeStepController, FailureHalvesTheStepAndAShortenedStepRecordsNothing) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  dt.failed(1e-3, 0);
  EXPECT_DOUBLE_EQ(dt.dt(), 0.5e-3);
  // A step shortened to land on a snapshot does not grow dt.
  dt.converged(0.2e-3, 2, 0.0, 1);
  EXPECT_DOUBLE_EQ(dt.dt(), 0.5e-3);
}

// Steps fail at 0.65 ms and above and are easy below. A first failure (1 ms) does not hold dt
// back; dt fails again at 0.72 ms (0.5 grown twice), not a repeat (0.72 is more than a growth
// factor below 1 ms), and then at 0.746 ms, a repeat that holds dt below it for 100 steps:
// dt then stays below 0.65 ms instead of failing every few steps, and probes again when the
// failure is forgotten. A restart keeps the memory.
TEST(TimeStepController, DoesNotGrowBackIntoAFailedStep) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  long step = 0;
  int failures = 0;
  auto advance = [&](app::TimeStepController& controller) {
    const double taken = controller.dt();
    if (taken >= 0.65e-3) {
      ++failures;
      controller.failed(taken, step);
    } else {
      controller.converged(taken, 3, 0.0, ++step);
    }
  };
  for (int i = 0; i < 60; ++i) advance(dt);
  EXPECT_EQ(failures, 3);
  EXPECT_LT(dt.dt(), 0.65e-3);  // the last level below the failures
  EXPECT_GT(dt.dt(), 0.5e-3);
  app::TimeStepController restarted(c.run, c.numerics, dt.dt());
  restarted.restore(dt.memory());
  for (int i = 0; i < 20; ++i) advance(restarted);
  EXPECT_EQ(failures, 3);
  for (int i = 0; i < 300; ++i) advance(restarted);
  EXPECT_GE(failures, 4);
  EXPECT_LE(failures, 9);  // without the memory: one in every 4-5 steps
}

// A start-up's failures at falling dt (each below the last by more than a growth factor) do
// not hold dt back: it grows past them.
TEST(TimeStepController, ForgetsAStartUpsFailuresSoon) {
  Controls c;
  app::TimeStepController dt(c.run, c.numerics, 1e-3);
  long step = 0;
  for (const double taken : {1e-3, 0.5e-3, 0.25e-3}) dt.failed(taken, step);
  for (int i = 0; i < 40; ++i) dt.converged(dt.dt(), 3, 0.0, ++step);
  EXPECT_GT(dt.dt(), 1e-3);
}

}  // namespace
}  // namespace bagnold::tests
