#pragma once
// A stand-in for a terminal that stdout and stderr share: a temporary file both streams of a
// run::Console write to, and what a terminal would show of it (each "\r" returns to the start of
// the line, "\e[K" erases to its end, "\n" ends it).
#include <cstdio>
#include <string>
#include <vector>

namespace bagnold::tests {

class FakeTerminal {
 public:
  FakeTerminal() : m_file(std::tmpfile()) {}
  ~FakeTerminal() { std::fclose(m_file); }
  FakeTerminal(const FakeTerminal&) = delete;
  FakeTerminal& operator=(const FakeTerminal&) = delete;

  std::FILE* stream() const { return m_file; }

  // Every byte written so far.
  std::string bytes() const {
    std::fflush(m_file);
    std::rewind(m_file);
    std::string out;
    for (int c; (c = std::fgetc(m_file)) != EOF;) out.push_back(static_cast<char>(c));
    return out;
  }

  // The lines the terminal shows, the one the cursor is on last (if it holds anything).
  std::vector<std::string> screen() const {
    const std::string raw = bytes();
    std::vector<std::string> lines;
    std::string line;
    std::size_t cursor = 0;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw.compare(i, 3, "\033[K") == 0) {
        line.resize(cursor);
        i += 2;
      } else if (raw[i] == '\r') {
        cursor = 0;
      } else if (raw[i] == '\n') {
        lines.push_back(line);
        line.clear();
        cursor = 0;
      } else {
        if (cursor < line.size()) line[cursor] = raw[i];
        else line.push_back(raw[i]);
        ++cursor;
      }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
  }

 private:
  std::FILE* m_file;
};

}  // namespace bagnold::tests
