// What the time loop logs per snapshot interval: the snapshot's line, then at most one line
// summarizing the interval's changes of dt (their range and count), none when dt did not
// change; with --verbose each change as it comes and no summary.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "src/app/run_log.hpp"

namespace bagnold::tests {
namespace {

struct Logged {
  std::vector<std::string> lines;
  app::RunLog log(bool verbose, double dt) {
    return app::RunLog([this](const std::string& l) { lines.push_back(l); }, verbose, dt);
  }
};

TEST(RunLog, OneSummaryPerSnapshotIntervalWithTheRangeAndCount) {
  Logged out;
  auto log = out.log(false, 1e-3);
  log.stepped(0.001, 1e-3, "");
  log.stepped(0.002, 1.2e-3, "converged in 3 outer iterations; dt 0.001 s -> 0.0012 s");
  log.stepped(0.0032, 0.74e-3, "converged in 20 outer iterations; dt 0.0012 s -> 0.00074 s");
  log.stepped(0.00394, 1.07e-3, "converged in 4 outer iterations; dt 0.00074 s -> 0.00107 s");
  EXPECT_TRUE(out.lines.empty());
  log.snapshot(0.005, "runs/bin/snapshot_000001.h5");
  EXPECT_EQ(out.lines, (std::vector<std::string>{
                           "t = 0.005 s: snapshot snapshot_000001.h5 written",
                           "t = 0.005 s: dt 0.74–1.2 ms over the last snapshot interval, 3 changes"}));
  // The next interval starts at the dt in effect; without a change it has no summary.
  out.lines.clear();
  log.stepped(0.006, 1.07e-3, "");
  log.snapshot(0.01, "snapshot_000002.h5");
  EXPECT_EQ(out.lines, (std::vector<std::string>{"t = 0.01 s: snapshot snapshot_000002.h5 written"}));
  out.lines.clear();
  log.stepped(0.011, 2e-6, "Courant number 2 at dt 0.00107 s (numerics.max_courant 1)");
  log.snapshot(0.02, "snapshot_000003.h5");
  EXPECT_EQ(out.lines.at(1), "t = 0.02 s: dt 0.002–1.07 ms over the last snapshot interval, 1 change");
  // Both ends in the unit of the larger: microseconds below a millisecond.
  out.lines.clear();
  log.stepped(0.02001, 3e-6, "converged in 3 outer iterations; dt 2e-06 s -> 3e-06 s");
  log.snapshot(0.03, "snapshot_000004.h5");
  EXPECT_EQ(out.lines.at(1), "t = 0.03 s: dt 2–3 µs over the last snapshot interval, 1 change");
}

TEST(RunLog, VerboseLogsEveryChangeAndNoSummary) {
  Logged out;
  auto log = out.log(true, 0.5);
  log.stepped(1.0, 0.25, "converged in 9 outer iterations; dt 0.5 s -> 0.25 s");
  log.stepped(1.25, 0.25, "");
  log.stepped(1.5, 0.3, "converged in 2 outer iterations; dt 0.25 s -> 0.3 s");
  log.snapshot(1.5, "snapshot_000004.h5");
  EXPECT_EQ(out.lines, (std::vector<std::string>{
                           "t = 1 s: converged in 9 outer iterations; dt 0.5 s -> 0.25 s",
                           "t = 1.5 s: converged in 2 outer iterations; dt 0.25 s -> 0.3 s",
                           "t = 1.5 s: snapshot snapshot_000004.h5 written"}));
}

}  // namespace
}  // namespace bagnold::tests
