#include "src/run/console.hpp"

namespace bagnold::run {

namespace {
constexpr const char* erase_line = "\r\033[K";  // carriage return, erase to the end of the line
}

void Console::line(const std::string& text, bool error) {
  clear();
  std::FILE* stream = error ? m_err : m_out;
  std::fputs(text.c_str(), stream);
  if (!text.empty() && text.back() != '\n') std::fputc('\n', stream);
  std::fflush(stream);
  draw();
}

void Console::show_progress(const std::string& text) {
  m_progress = text;
  draw();
}

void Console::end_progress() {
  if (m_progress.empty()) return;
  std::fputc('\n', m_err);
  std::fflush(m_err);
  m_progress.clear();
}

void Console::draw() const {
  if (m_progress.empty()) return;
  std::fprintf(m_err, "\r%s\033[K", m_progress.c_str());
  std::fflush(m_err);
}

void Console::clear() const {
  if (m_progress.empty()) return;
  std::fputs(erase_line, m_err);
  std::fflush(m_err);
}

Console& console() {
  static Console c(stdout, stderr);
  return c;
}

}  // namespace bagnold::run
