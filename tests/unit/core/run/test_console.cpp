// The one writer of a run's output: a log line clears the progress line first and the progress
// line is drawn again after it, so on a terminal that stdout and stderr share no log line starts
// after progress text; without a progress line showing, a log line is written as it is.
#include <gtest/gtest.h>

#include "src/run/console.hpp"
#include "tests/unit/core/run/fake_terminal.hpp"

namespace bagnold::tests {
namespace {

const std::string progress = "t = 0.5 s / 1 s  dt = 1.00e-04 s  it = 3  ETA 00:00:10";
const std::string later = "t = 0.6 s / 1 s  dt = 1.00e-04 s  it = 4  ETA 00:00:08";
const std::string logged = "t = 0.5 s: snapshot snapshot_000001.h5 written";

TEST(Console, ALogLineClearsTheProgressLineFirstAndItIsRedrawnAfter) {
  FakeTerminal terminal;
  run::Console console(terminal.stream(), terminal.stream());
  console.show_progress(progress);
  console.line(logged);
  const std::string raw = terminal.bytes();
  const auto at = raw.find(logged);
  ASSERT_NE(at, std::string::npos) << raw;
  ASSERT_GE(at, 4u);
  EXPECT_EQ(raw.substr(at - 4, 4), "\r\033[K") << "no clear sequence before the log line: " << raw;
  EXPECT_EQ(raw.substr(at + logged.size()), "\n\r" + progress + "\033[K") << "not redrawn: " << raw;
  console.show_progress(later);
  console.line("second\nand third line", true);  // an error, several lines
  console.end_progress();
  // What the terminal shows: each log line alone on its line, the last progress line last.
  EXPECT_EQ(terminal.screen(),
            (std::vector<std::string>{logged, "second", "and third line", later}));
}

TEST(Console, NoLogLineStartsAfterProgressText) {
  FakeTerminal terminal;
  run::Console console(terminal.stream(), terminal.stream());
  for (int i = 0; i < 5; ++i) {
    console.show_progress(progress);
    console.line(logged, i % 2 == 1);
  }
  console.end_progress();
  int shown_logged = 0;
  for (const auto& shown : terminal.screen()) {
    if (shown.find(logged) == std::string::npos) continue;
    EXPECT_EQ(shown, logged);
    ++shown_logged;
  }
  EXPECT_EQ(shown_logged, 5);
}

TEST(Console, WithoutAProgressLineLinesAreWrittenAsTheyAre) {
  FakeTerminal terminal;
  run::Console console(terminal.stream(), terminal.stream());
  console.line(logged);
  console.line("ends in a newline\n", true);
  console.line("");
  console.end_progress();  // nothing showing: nothing written
  EXPECT_EQ(terminal.bytes(), logged + "\nends in a newline\n");
}

TEST(Console, AfterTheEndThereIsNothingToRedraw) {
  FakeTerminal terminal;
  run::Console console(terminal.stream(), terminal.stream());
  console.show_progress(progress);
  console.end_progress();
  console.line(logged);
  EXPECT_EQ(terminal.bytes(), "\r" + progress + "\033[K\n" + logged + "\n");
}

}  // namespace
}  // namespace bagnold::tests
