#include "src/deck/diagnostics.hpp"

#include <algorithm>

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

Origin Deck::origin_of(const std::string& path) const {
  const auto it = origins.find(path);
  return it != origins.end() ? it->second : Origin{source, 0, 0};
}

namespace {
bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }
// Whether `inner` names a key below the table `outer` ("boundary[1].max" below "boundary[1]"
// and below "boundary").
bool is_below(const std::string& inner, const std::string& outer) {
  return !outer.empty() && (starts_with(inner, outer + ".") || starts_with(inner, outer + "["));
}
}  // namespace

Origin Diagnostics::origin(const toml::source_region& where, const std::string& key) const {
  Origin at{where.path ? *where.path : std::string(), static_cast<int>(where.begin.line),
            static_cast<int>(where.begin.column)};
  // toml++ does not keep source positions on nodes inserted by an override.
  bool overridden = false;
  for (const auto& [override_key, origin] : m_overrides)
    if (key == override_key || is_below(key, override_key)) {
      at = {origin, 0, 0};
      overridden = true;
    }
  if (overridden) return at;
  std::vector<std::string> seen;
  std::string below;
  for (const auto& [override_key, origin] : m_overrides)
    if (is_below(override_key, key) && std::find(seen.begin(), seen.end(), origin) == seen.end()) {
      seen.push_back(origin);
      below += (below.empty() ? "" : ", ") + origin;
    }
  if (below.empty()) return at;
  if (at.line > 0) below += " (" + at.file + ":" + std::to_string(at.line) + ")";
  return {below, 0, 0};
}

void Diagnostics::error(const toml::source_region& where, std::string key, std::string message) {
  error(origin(where, key), key, std::move(message));
}

void Diagnostics::error(const Origin& where, std::string key, std::string message) {
  Diagnostic d;
  d.file = where.file;
  d.line = where.line;
  d.column = where.column;
  d.key = std::move(key);
  d.message = std::move(message);
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
