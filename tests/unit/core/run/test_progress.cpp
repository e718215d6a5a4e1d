// The progress line: the estimated time left comes from the mean rate so far (simulated seconds
// per wall second since the start or restart); before any progress there is no estimate. Its
// style follows output.progress, the rank and whether stderr is a terminal; in place it is
// redrawn at most every 250 ms, plain it is a line without control characters per interval.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "src/run/progress.hpp"
#include "tests/unit/core/run/fake_terminal.hpp"

namespace bagnold::tests {
namespace {

TEST(Progress, TextShowsTimeStepIterationsAndEta) {
  // 0.5 s simulated in 10 s of wall time: 1.0 s left takes 20 s.
  EXPECT_EQ(run::progress_text(0.5, 1.5, 1e-4, 5, 10.0, 0.0),
            "t = 0.5 s / 1.5 s  dt = 1.00e-04 s  it = 5  ETA 00:00:20");
}

TEST(Progress, EtaUsesTheRateSinceTheRestart) {
  // Restarted at t = 1: 0.25 s in 100 s, 0.75 s left: 300 s.
  EXPECT_NE(run::progress_text(1.25, 2.0, 1e-3, 3, 100.0, 1.0).find("ETA 00:05:00"),
            std::string::npos);
  // Hours, minutes and seconds: 36 s for 1 ms, 0.999 s left: 35964 s = 9 h 59 min 24 s.
  EXPECT_NE(run::progress_text(0.001, 1.0, 1e-4, 1, 36.0, 0.0).find("ETA 09:59:24"),
            std::string::npos);
}

TEST(Progress, NoEstimateBeforeAnyProgress) {
  EXPECT_NE(run::progress_text(0.0, 1.0, 1e-4, 0, 5.0, 0.0).find("ETA --:--:--"),
            std::string::npos);
  EXPECT_NE(run::progress_text(2.0, 3.0, 1e-4, 0, 5.0, 2.0).find("ETA --:--:--"),
            std::string::npos);
  EXPECT_NE(run::progress_text(0.1, 1.0, 1e-4, 0, 0.0, 0.0).find("ETA --:--:--"),
            std::string::npos);
}

TEST(Progress, NothingLeftAtTheEnd) {
  EXPECT_NE(run::progress_text(1.0, 1.0, 1e-4, 2, 30.0, 0.0).find("ETA 00:00:00"),
            std::string::npos);
  EXPECT_NE(run::progress_text(1.1, 1.0, 1e-4, 2, 30.0, 0.0).find("ETA 00:00:00"),
            std::string::npos);
}

TEST(ProgressLine, StyleFollowsTheModeTheRankAndTheTerminal) {
  using run::ProgressStyle;
  EXPECT_EQ(run::progress_style("auto", true, true), ProgressStyle::in_place);
  EXPECT_EQ(run::progress_style("auto", true, false), ProgressStyle::plain);
  EXPECT_EQ(run::progress_style("always", true, false), ProgressStyle::in_place);
  EXPECT_EQ(run::progress_style("never", true, true), ProgressStyle::none);
  EXPECT_EQ(run::progress_style("never", true, false), ProgressStyle::none);
  EXPECT_EQ(run::progress_style("always", false, true), ProgressStyle::none);
  EXPECT_EQ(run::progress_style("auto", false, false), ProgressStyle::none);
}

// What a progress line of `style` writes for updates at `times` (dt 1e-4 s, iterations 3, 4, ...)
// and its finish, to a console on one stream.
std::string drawn(run::ProgressStyle style, double interval, const std::vector<double>& times) {
  FakeTerminal terminal;
  run::Console console(terminal.stream(), terminal.stream());
  run::ProgressLine line(style, interval, 1.0, 0.0, console);
  int iterations = 3;
  for (const double t : times) line.update(t, 1e-4, iterations++);
  line.finish();
  return terminal.bytes();
}

TEST(ProgressLine, InPlaceIsDrawnAtOnceAndAtMostEvery250ms) {
  // The second update comes within 250 ms of the first: not redrawn.
  const std::string out = drawn(run::ProgressStyle::in_place, 30.0, {0.5, 0.6});
  EXPECT_EQ(out.rfind("\rt = 0.5 s / 1 s  dt = 1.00e-04 s  it = 3  ETA ", 0), 0u) << out;
  EXPECT_EQ(out.find("t = 0.6"), std::string::npos) << out;
  EXPECT_EQ(out.back(), '\n');
}

TEST(ProgressLine, PlainLinesHaveNoControlCharactersAndWaitForTheInterval) {
  const std::string out = drawn(run::ProgressStyle::plain, 0.0, {0.5, 0.6});
  EXPECT_EQ(out.find_first_of("\r\033"), std::string::npos) << out;
  const auto second = out.find('\n') + 1;
  EXPECT_EQ(out.rfind("t = 0.5 s / 1 s  dt = 1.00e-04 s  it = 3  ETA ", 0), 0u) << out;
  EXPECT_EQ(out.find("t = 0.6 s / 1 s  dt = 1.00e-04 s  it = 4  ETA ", second), second) << out;
  EXPECT_EQ(std::count(out.begin(), out.end(), '\n'), 2) << out;
  // The first plain line comes a whole interval after the start, not at the first step.
  EXPECT_EQ(drawn(run::ProgressStyle::plain, 3600.0, {0.5}), "");
}

TEST(ProgressLine, NoneDrawsNothing) {
  EXPECT_EQ(drawn(run::ProgressStyle::none, 0.0, {0.5, 0.6}), "");
}

}  // namespace
}  // namespace bagnold::tests
