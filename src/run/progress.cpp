#include "src/run/progress.hpp"

#include <cmath>
#include <cstdio>

namespace bagnold::run {

namespace {
// In place, the line is redrawn at most this often: often enough to look live, seldom enough
// to cost nothing.
constexpr std::chrono::milliseconds in_place_redraw{250};
}  // namespace

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

ProgressStyle progress_style(const std::string& mode, bool is_root, bool stderr_is_terminal) {
  if (!is_root || mode == "never") return ProgressStyle::none;
  if (mode == "always" || stderr_is_terminal) return ProgressStyle::in_place;
  return ProgressStyle::plain;
}

ProgressLine::ProgressLine(ProgressStyle style, double plain_interval, double end_time,
                           double start_time, Console& console)
    : m_style(style),
      m_interval(style == ProgressStyle::plain ? std::chrono::duration<double>(plain_interval)
                                               : std::chrono::duration<double>(in_place_redraw)),
      m_end_time(end_time),
      m_start_time(start_time),
      m_console(console),
      m_started(std::chrono::steady_clock::now()),
      m_last_draw(m_started) {}

void ProgressLine::update(double time, double dt, int iterations) {
  if (m_style == ProgressStyle::none) return;
  const auto now = std::chrono::steady_clock::now();
  // In place the first step is drawn at once; a plain line waits for a whole interval.
  const bool first = !m_drawn && m_style == ProgressStyle::in_place;
  if (!first && now - m_last_draw < m_interval) return;
  m_last_draw = now;
  m_drawn = true;
  const double wall = std::chrono::duration<double>(now - m_started).count();
  const std::string text = progress_text(time, m_end_time, dt, iterations, wall, m_start_time);
  if (m_style == ProgressStyle::in_place)
    m_console.show_progress(text);
  else
    m_console.line(text);
}

void ProgressLine::finish() {
  if (m_style == ProgressStyle::in_place) m_console.end_progress();
}

}  // namespace bagnold::run
