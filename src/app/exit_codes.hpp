#pragma once
// What `bagnold` returns, so scripts can tell bad input from a failed run.

namespace bagnold::app {

enum ExitCode : int {
  success = 0,
  run_failed = 1,    // the run started but could not finish (solver failure, I/O error)
  bad_input = 2,     // invalid command line or deck; nothing was run
  interrupted = 3,   // stopped by SIGINT/SIGTERM after writing a final snapshot
};

}  // namespace bagnold::app
