#pragma once
// The progress line of a long run, on stderr: simulated time, dt, outer iterations, and the
// estimated wall time left. Redrawn in place at most every `min_interval` seconds; silent when
// stderr is not a terminal (unless forced by output.progress = "always").

#include <chrono>
#include <string>

namespace bagnold::run {

// "t = 0.1234 s / 1.5 s  dt = 1.0e-04 s  it = 5  ETA 00:12:34" (ETA from the mean rate so far).
std::string progress_text(double time, double end_time, double dt, int iterations,
                          double wall_seconds_so_far, double start_time);

class ProgressLine {
 public:
  ProgressLine(const std::string& mode, bool is_root, double end_time, double start_time);
  void update(double time, double dt, int iterations);
  void finish();

 private:
  bool m_enabled;
  double m_end_time;
  double m_start_time;
  std::chrono::steady_clock::time_point m_started;
  std::chrono::steady_clock::time_point m_last_draw;
  bool m_drawn = false;
};

}  // namespace bagnold::run
