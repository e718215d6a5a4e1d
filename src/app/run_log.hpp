#pragma once
// What the time loop says between snapshots: a line per snapshot written ("t = 0.1 s: snapshot
// snapshot_000002.h5 written"), and after it one line summarizing the changes of dt over the
// interval that snapshot closes ("t = 0.1 s: dt 0.74–1.07 ms over the last snapshot interval,
// 3 changes"; none when dt did not change). With --verbose every change is logged as it
// happens, with its reason, instead of the summary. Steps that did not converge and were redone
// are the time loop's to log, always.

#include <functional>
#include <string>

namespace bagnold::app {

// "t = 0 s: snapshot snapshot_000000.h5 written" for the snapshot at `path`.
std::string snapshot_line(double time, const std::string& path);

class RunLog {
 public:
  // `dt`: the dt the first step tries.
  RunLog(std::function<void(const std::string&)> log, bool verbose, double dt);

  // After a converged step that ended at `time`: the dt the next step tries and why it changed
  // (empty when it did not: TimeStepController::converged).
  void stepped(double time, double dt_next, const std::string& change);
  // The snapshot written at `time` to `path`: its line, then the dt summary of the interval.
  void snapshot(double time, const std::string& path);

 private:
  std::function<void(const std::string&)> m_log;
  bool m_verbose;
  int m_changes = 0;             // of dt since the last snapshot
  double m_current;              // [s] the dt the next step tries
  double m_smallest, m_largest;  // [s] of the dt in effect since the last snapshot
};

}  // namespace bagnold::app
