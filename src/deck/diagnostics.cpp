#include "src/deck/diagnostics.hpp"

namespace bagnold::deck {

std::string Diagnostic::to_string() const {
  std::string out = file.empty() ? std::string("deck") : file;
  const bool from_command_line = file.rfind("--set", 0) == 0;
  if (line > 0 && !from_command_line) out += ":" + std::to_string(line) + ":" + std::to_string(column);
  out += ": ";
  if (!key.empty()) out += key + ": ";
  return out + message;
}

void Diagnostics::error(const toml::source_region& where, std::string key, std::string message) {
  Diagnostic d;
  d.file = where.path ? *where.path : std::string();
  d.line = static_cast<int>(where.begin.line);
  d.column = static_cast<int>(where.begin.column);
  d.key = std::move(key);
  d.message = std::move(message);
  m_errors.push_back(std::move(d));
}

std::string Diagnostics::report() const {
  std::string out;
  for (const auto& e : m_errors) out += e.to_string() + "\n";
  return out;
}

}  // namespace bagnold::deck
