#include "src/deck/diagnostics.hpp"

namespace bagnold::deck {

std::string Diagnostic::to_string() const {
  std::string out = file.empty() ? std::string("deck") : file;
  const bool from_command_line = file.rfind("--set", 0) == 0;
  if (line > 0 && !from_command_line) {
    out += ':';
    out += std::to_string(line);
    out += ':';
    out += std::to_string(column);
  }
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
  // toml++ does not keep source positions on nodes inserted by an override.
  for (const auto& [override_key, origin] : m_overrides)
    if (d.key == override_key || d.key.rfind(override_key + ".", 0) == 0) {
      d.file = origin;
      d.line = d.column = 0;
    }
  m_errors.push_back(std::move(d));
}

void Diagnostics::note_override(const std::string& key, const std::string& origin) {
  m_overrides.emplace_back(key, origin);
}

std::string Diagnostics::report() const {
  std::string out;
  for (const auto& e : m_errors) out += e.to_string() + "\n";
  return out;
}

}  // namespace bagnold::deck
