#pragma once
// The progress line of a long run: simulated time, dt, outer iterations, and the estimated wall
// time left, drawn through the Console (console.hpp), which clears it before every log line.
// In place on stderr (redrawn at most every 250 ms) when stderr is a terminal or
// output.progress = "always"; otherwise, with output.progress = "auto", a plain line (no "\r",
// no escape sequences) on stdout every output.progress_interval seconds of wall time; nothing
// with "never" or on ranks other than 0.

#include <chrono>
#include <string>

#include "src/run/console.hpp"

namespace bagnold::run {

// "t = 0.1234 s / 1.5 s  dt = 1.0e-04 s  it = 5  ETA 00:12:34" (ETA from the mean rate so far).
std::string progress_text(double time, double end_time, double dt, int iterations,
                          double wall_seconds_so_far, double start_time);

enum class ProgressStyle { none, in_place, plain };
// output.progress ("auto", "always", "never") on rank 0 (`is_root`) with stderr a terminal or
// not: the style of the progress line.
ProgressStyle progress_style(const std::string& mode, bool is_root, bool stderr_is_terminal);

class ProgressLine {
 public:
  // `plain_interval`: wall seconds between plain lines (output.progress_interval).
  ProgressLine(ProgressStyle style, double plain_interval, double end_time, double start_time,
               Console& console = run::console());
  // Leaves a line drawn in place as it is, so what follows (an error too) starts below it.
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void update(double time, double dt, int iterations);
  void finish();

 private:
  ProgressStyle m_style;
  std::chrono::duration<double> m_interval;  // between draws
  double m_end_time;
  double m_start_time;
  Console& m_console;
  std::chrono::steady_clock::time_point m_started;
  std::chrono::steady_clock::time_point m_last_draw;
  bool m_drawn = false;
};

}  // namespace bagnold::run
