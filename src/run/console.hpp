#pragma once
// The one writer of what a run shows on rank 0: log lines (stdout; errors on stderr) and the
// progress line (stderr). A progress line drawn in place ("\r" text "\e[K") is cleared
// ("\r\e[K") before any log line and drawn again after it, so no log line starts after
// progress text, whether stdout and stderr are one terminal or not. Every write is flushed.
// Callers decide the rank (app/say.cpp, run/progress.hpp): a Console writes what it is given.

#include <cstdio>
#include <string>

namespace bagnold::run {

class Console {
 public:
  Console(std::FILE* out, std::FILE* err) : m_out(out), m_err(err) {}

  // A log line (a newline is added when `text` does not end in one), on the error stream when
  // `error`.
  void line(const std::string& text, bool error = false);
  // Draws `text` as the progress line in place of the one showing, and keeps it showing.
  void show_progress(const std::string& text);
  // Leaves the progress line showing as an ordinary line; nothing is redrawn after it.
  void end_progress();

 private:
  void draw() const;
  void clear() const;

  std::FILE* m_out;
  std::FILE* m_err;
  std::string m_progress;  // the progress line showing, or empty
};

// The program's: stdout and stderr.
Console& console();

}  // namespace bagnold::run
