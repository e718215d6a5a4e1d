// The progress line: the estimated time left comes from the mean rate so far (simulated seconds
// per wall second since the start or restart); before any progress there is no estimate.
#include <gtest/gtest.h>

#include "src/run/progress.hpp"

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

TEST(ProgressLine, DrawsOnlyWhenAskedAndOnRoot) {
  // Under ctest stderr is not a terminal: "auto" stays quiet, as do "never" and other ranks.
  for (const auto& [mode, root] : {std::pair{"never", true}, std::pair{"auto", true},
                                   std::pair{"always", false}}) {
    testing::internal::CaptureStderr();
    run::ProgressLine line(mode, root, 1.0, 0.0);
    line.update(0.5, 1e-4, 3);
    line.finish();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << mode;
  }
  testing::internal::CaptureStderr();
  run::ProgressLine line("always", true, 1.0, 0.0);
  line.update(0.5, 1e-4, 3);
  line.update(0.6, 1e-4, 3);  // within 250 ms of the last draw: not redrawn
  line.finish();
  const std::string out = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out.rfind("\rt = 0.5 s / 1 s  dt = 1.00e-04 s  it = 3  ETA ", 0), 0u) << out;
  EXPECT_EQ(out.find("t = 0.6"), std::string::npos) << out;
  EXPECT_EQ(out.back(), '\n');
}

}  // namespace
}  // namespace bagnold::tests
