#include "src/deck/schema.hpp"

#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "src/util/closest_match.hpp"

namespace bagnold::deck {

std::string to_toml_text(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  // Ten digits read well; when they do not give the value back, all 17 (the resolved deck must
  // load back to the same values).
  if (std::strtod(buffer, nullptr) != value) std::snprintf(buffer, sizeof buffer, "%.17g", value);
  std::string s = buffer;
  // Keep it a TOML float: 1 -> 1.0, 1e-05 stays.
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}
std::string to_toml_text(int value) { return std::to_string(value); }
std::string to_toml_text(bool value) { return value ? "true" : "false"; }
std::string node_text(const toml::node& node) {
  std::ostringstream s;
  node.visit([&](const auto& v) { s << v; });
  return s.str();
}

std::string to_toml_text(const std::string& value) {
  std::string out = "\"";
  for (char c : value) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if ((u < 0x20 && c != '\t') || u == 0x7f) {  // TOML forbids raw control characters
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(u));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}
template <class Range>
static std::string list_text(const Range& values) {
  std::string out = "[";
  bool first = true;
  for (const auto& v : values) {
    out += (first ? "" : ", ") + to_toml_text(v);
    first = false;
  }
  return out + "]";
}
std::string to_toml_text(const std::array<double, 3>& value) { return list_text(value); }
std::string to_toml_text(const std::vector<double>& value) { return list_text(value); }
std::string to_toml_text(const std::vector<std::string>& value) { return list_text(value); }

bool read_value(const toml::node& node, double& out) {
  // Integers are accepted where reals are expected: `end_time = 1` means 1.0 s.
  if (auto v = node.value_exact<double>()) { out = *v; return true; }
  if (auto i = node.value_exact<int64_t>()) { out = static_cast<double>(*i); return true; }
  return false;
}
bool read_value(const toml::node& node, int& out) {
  const auto v = node.value_exact<int64_t>();
  if (!v || *v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
    return false;
  out = static_cast<int>(*v);
  return true;
}
bool read_value(const toml::node& node, bool& out) {
  const auto v = node.value_exact<bool>();
  if (!v) return false;
  out = *v;
  return true;
}
bool read_value(const toml::node& node, std::string& out) {
  const auto v = node.value_exact<std::string>();
  if (!v) return false;
  out = *v;
  return true;
}
bool read_value(const toml::node& node, std::vector<double>& out) {
  const auto* array = node.as_array();
  if (!array) return false;
  out.clear();
  for (const auto& element : *array) {
    double x = 0;
    if (!read_value(element, x)) return false;
    out.push_back(x);
  }
  return true;
}
bool read_value(const toml::node& node, std::array<double, 3>& out) {
  std::vector<double> values;
  if (!read_value(node, values) || values.size() != 3) return false;
  std::copy(values.begin(), values.end(), out.begin());
  return true;
}
bool read_value(const toml::node& node, std::vector<std::string>& out) {
  const auto* array = node.as_array();
  if (!array) return false;
  out.clear();
  for (const auto& element : *array) {
    std::string s;
    if (!read_value(element, s)) return false;
    out.push_back(s);
  }
  return true;
}

void check_unknown_keys(const toml::table& table, const std::string& path,
                        const std::vector<std::string>& known, Diagnostics& diag) {
  for (const auto& [name, node] : table) {
    const std::string key_name(name.str());
    bool found = false;
    for (const auto& k : known) found = found || k == key_name;
    if (found) continue;
    std::string message = "unknown key";
    if (auto suggestion = closest_match(key_name, known))
      message += "; did you mean '" + *suggestion + "'?";
    message += " (valid keys here: " + join(known) + ")";
    const std::string full = path.empty() ? key_name : path + "." + key_name;
    diag.error(name.source().begin.line ? name.source() : node.source(), full, message);
  }
}

}  // namespace bagnold::deck
