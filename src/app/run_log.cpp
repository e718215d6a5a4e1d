#include "src/app/run_log.hpp"

#include <algorithm>
#include <filesystem>
#include <utility>
#include <fmt/format.h>

namespace bagnold::app {

namespace {

// "0.74–1.07 ms": both ends in the unit of the larger (s, ms or µs), three digits.
std::string dt_range(double smallest, double largest) {
  const auto [scale, unit] = largest >= 1.0 ? std::pair{1.0, "s"}
                             : largest >= 1e-3 ? std::pair{1e3, "ms"}
                                               : std::pair{1e6, "µs"};
  if (smallest == largest) return fmt::format("{:.3g} {}", largest * scale, unit);
  return fmt::format("{:.3g}–{:.3g} {}", smallest * scale, largest * scale, unit);
}

}  // namespace

std::string snapshot_line(double time, const std::string& path) {
  return fmt::format("t = {:.6g} s: snapshot {} written", time,
                     std::filesystem::path(path).filename().string());
}

RunLog::RunLog(std::function<void(const std::string&)> log, bool verbose, double dt)
    : m_log(std::move(log)), m_verbose(verbose), m_current(dt), m_smallest(dt), m_largest(dt) {}

void RunLog::stepped(double time, double dt_next, const std::string& change) {
  // A step redone with dt / 2 (logged by the time loop) shows here as the dt that follows it.
  m_current = dt_next;
  m_smallest = std::min(m_smallest, dt_next);
  m_largest = std::max(m_largest, dt_next);
  if (change.empty()) return;
  ++m_changes;
  if (m_verbose) m_log(fmt::format("t = {:.6g} s: {}", time, change));
}

void RunLog::snapshot(double time, const std::string& path) {
  m_log(snapshot_line(time, path));
  if (m_changes > 0 && !m_verbose)
    m_log(fmt::format("t = {:.6g} s: dt {} over the last snapshot interval, {} change{}", time,
                      dt_range(m_smallest, m_largest), m_changes, m_changes == 1 ? "" : "s"));
  m_changes = 0;
  m_smallest = m_largest = m_current;
}

}  // namespace bagnold::app
