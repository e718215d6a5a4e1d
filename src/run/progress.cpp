#include "src/run/progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace bagnold::run {

std::string progress_text(double time, double end_time, double dt, int iterations,
                          double wall_seconds_so_far, double start_time) {
  char eta[32] = "--:--:--";
  const double done = time - start_time;
  if (done > 0 && wall_seconds_so_far > 0) {
    const double left = wall_seconds_so_far * std::max(0.0, end_time - time) / done;
    const long s = std::lround(left);
    std::snprintf(eta, sizeof eta, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  }
  char line[160];
  std::snprintf(line, sizeof line, "t = %.6g s / %.6g s  dt = %.2e s  it = %d  ETA %s", time,
                end_time, dt, iterations, eta);
  return line;
}

ProgressLine::ProgressLine(const std::string& mode, bool is_root, double end_time,
                           double start_time)
    : m_enabled(is_root && (mode == "always" || (mode == "auto" && isatty(STDERR_FILENO)))),
      m_end_time(end_time),
      m_start_time(start_time),
      m_started(std::chrono::steady_clock::now()),
      m_last_draw(m_started) {}

void ProgressLine::update(double time, double dt, int iterations) {
  if (!m_enabled) return;
  const auto now = std::chrono::steady_clock::now();
  if (m_drawn && now - m_last_draw < std::chrono::milliseconds(250)) return;
  m_last_draw = now;
  m_drawn = true;
  const double wall = std::chrono::duration<double>(now - m_started).count();
  std::fprintf(stderr, "\r%s\033[K",
               progress_text(time, m_end_time, dt, iterations, wall, m_start_time).c_str());
  std::fflush(stderr);
}

void ProgressLine::finish() {
  if (m_enabled && m_drawn) std::fprintf(stderr, "\n");
}

}  // namespace bagnold::run
