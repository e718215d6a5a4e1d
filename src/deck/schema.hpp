#pragma once
// The deck schema: every key declared once, with its type, unit, default, range and doc.
// One declaration drives parsing, range checks, unknown-key suggestions, the resolved
// configuration that `bagnold check` prints and the key reference in docs/deck.md.
//
//   const Section<Solids> solids_section{"solids", "Granular phase", {
//       key(&Solids::diameter, "diameter").unit("m").init().above(0.0).doc("d_p"),
//   }};
//
// A default is written once, as the member's initializer in the struct (deck.hpp,
// models/material.hpp): init() declares that the key has one and takes it from a
// default-constructed struct. A key without init() is required, or has no default to show
// (a block's shape-dependent keys, a wall law's parameters).

#include <toml++/toml.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "src/deck/diagnostics.hpp"

namespace bagnold::deck {

// Formatting of values as TOML text (for the resolved configuration and the docs).
// A deck value as written (TOML), for messages that echo it.
std::string node_text(const toml::node& node);
std::string to_toml_text(double value);
std::string to_toml_text(int value);
std::string to_toml_text(bool value);
std::string to_toml_text(const std::string& value);
std::string to_toml_text(const std::array<double, 3>& value);
std::string to_toml_text(const std::vector<double>& value);
std::string to_toml_text(const std::vector<std::string>& value);

// Reading one TOML node into a C++ value; returns false when the node has the wrong type.
bool read_value(const toml::node& node, double& out);
bool read_value(const toml::node& node, int& out);
bool read_value(const toml::node& node, bool& out);
bool read_value(const toml::node& node, std::string& out);
bool read_value(const toml::node& node, std::array<double, 3>& out);
bool read_value(const toml::node& node, std::vector<double>& out);
bool read_value(const toml::node& node, std::vector<std::string>& out);

template <class V>
constexpr const char* type_name() {
  if constexpr (std::is_same_v<V, double>) return "a real number";
  if constexpr (std::is_same_v<V, int>) return "an integer";
  if constexpr (std::is_same_v<V, bool>) return "true or false";
  if constexpr (std::is_same_v<V, std::string>) return "a string";
  if constexpr (std::is_same_v<V, std::array<double, 3>>) return "an array of 3 real numbers";
  if constexpr (std::is_same_v<V, std::vector<double>>) return "an array of real numbers";
  if constexpr (std::is_same_v<V, std::vector<std::string>>) return "an array of strings";
  return "a value";
}

// What a key's declaration says, independent of the struct it fills (for docs and messages).
struct KeyInfo {
  std::string name;
  std::string type;     // "a real number", ...
  std::string unit;     // "" when not a physical quantity, "-" when dimensionless
  std::string default_text;  // TOML text, "" when required or no default
  std::string range;    // "> 0", "in [0, 1]", "one of: a, b", ""
  std::string doc;
  bool required = false;
};

template <class T>
class KeySpec {
 public:
  using Reader = std::function<void(const toml::node&, T&, const std::string& path, Diagnostics&)>;

  KeyInfo info;
  Reader read;
  std::function<void(T&)> apply_default;
  std::function<std::string(const T&)> show;
};

// Builder for one key bound to a member of T; converts to KeySpec<T>.
template <class T, class V>
class Key {
 public:
  Key(V T::*member, std::string name) : m_member(member) { m_info.name = std::move(name); }

  Key& unit(std::string u) { m_info.unit = std::move(u); return *this; }
  Key& doc(std::string d) { m_info.doc = std::move(d); return *this; }
  // The key's default: the member's value in a default-constructed T (its initializer).
  Key& init() { return init_from(T{}); }
  // The member's value in `prototype`, for a struct that fills several tables with different
  // defaults (ModelChoice: [models.solids_stress] and [models.drag], deck.hpp's Models).
  Key& init_from(const T& prototype) { m_default = prototype.*m_member; return *this; }
  Key& required() { m_info.required = true; return *this; }
  Key& above(double lo) { m_lo = lo; m_lo_open = true; return *this; }
  Key& at_least(double lo) { m_lo = lo; m_lo_open = false; return *this; }
  Key& below(double hi) { m_hi = hi; m_hi_open = true; return *this; }
  Key& within(double lo, double hi) { m_lo = lo; m_hi = hi; m_lo_open = m_hi_open = false; return *this; }
  Key& one_of(std::vector<std::string> choices) { m_choices = std::move(choices); return *this; }

  operator KeySpec<T>() const {  // NOLINT(google-explicit-constructor): builder idiom
    KeySpec<T> spec;
    spec.info = m_info;
    spec.info.type = type_name<V>();
    spec.info.range = range_text();
    if (m_default) spec.info.default_text = to_toml_text(*m_default);
    const auto member = m_member;
    const auto def = m_default;
    spec.apply_default = [member, def](T& t) { if (def) t.*member = *def; };
    spec.show = [member](const T& t) { return to_toml_text(t.*member); };
    spec.read = [member, lo = m_lo, hi = m_hi, lo_open = m_lo_open, hi_open = m_hi_open,
                 choices = m_choices, expected = expected_text()](
                    const toml::node& node, T& t, const std::string& path, Diagnostics& diag) {
      V value{};
      if (!read_value(node, value)) {
        diag.error(node.source(), path, "expected " + expected + ", got " + node_text(node));
        return;
      }
      if (!in_range(value, lo, hi, lo_open, hi_open) || !is_choice(value, choices)) {
        diag.error(node.source(), path,
                   "value " + to_toml_text(value) + " is out of range: expected " + expected);
        return;
      }
      t.*member = std::move(value);
    };
    return spec;
  }

 private:
  std::string range_text() const {
    std::ostringstream s;
    if (!m_choices.empty()) {
      s << "one of: ";
      for (std::size_t i = 0; i < m_choices.size(); ++i) s << (i ? ", " : "") << m_choices[i];
    } else if (m_lo && m_hi) {
      s << "in " << (m_lo_open ? "(" : "[") << to_toml_text(*m_lo) << ", " << to_toml_text(*m_hi)
        << (m_hi_open ? ")" : "]");
    } else if (m_lo) {
      s << (m_lo_open ? "> " : ">= ") << to_toml_text(*m_lo);
    } else if (m_hi) {
      s << (m_hi_open ? "< " : "<= ") << to_toml_text(*m_hi);
    }
    return s.str();
  }
  std::string expected_text() const {
    std::string text = type_name<V>();
    const std::string range = range_text();
    if (!range.empty()) text += (m_choices.empty() ? " " : ", ") + range;
    if (!m_info.unit.empty() && m_info.unit != "-") text += " [" + m_info.unit + "]";
    return text;
  }
  static bool in_one(double x, const std::optional<double>& lo, const std::optional<double>& hi,
                     bool lo_open, bool hi_open) {
    // ±inf only where the range closes on it (within(0, inf): "for ever").
    const bool infinite_bound = std::isinf(x) && ((x > 0 && hi && *hi == x && !hi_open) ||
                                                  (x < 0 && lo && *lo == x && !lo_open));
    if (!std::isfinite(x) && !infinite_bound) return false;
    if (lo && (lo_open ? !(x > *lo) : !(x >= *lo))) return false;
    if (hi && (hi_open ? !(x < *hi) : !(x <= *hi))) return false;
    return true;
  }
  static bool in_range(const V& v, const std::optional<double>& lo,
                       const std::optional<double>& hi, bool lo_open, bool hi_open) {
    if constexpr (std::is_same_v<V, double> || std::is_same_v<V, int>) {
      return in_one(static_cast<double>(v), lo, hi, lo_open, hi_open);
    } else if constexpr (std::is_same_v<V, std::array<double, 3>> ||
                         std::is_same_v<V, std::vector<double>>) {
      for (double x : v)
        if (!in_one(x, lo, hi, lo_open, hi_open)) return false;
      return true;
    } else {
      return true;
    }
  }
  static bool is_choice(const V& v, const std::vector<std::string>& choices) {
    if (choices.empty()) return true;
    auto allowed = [&](const std::string& s) {
      for (const auto& c : choices)
        if (c == s) return true;
      return false;
    };
    if constexpr (std::is_same_v<V, std::string>) {
      return allowed(v);
    } else if constexpr (std::is_same_v<V, std::vector<std::string>>) {
      for (const auto& s : v)
        if (!allowed(s)) return false;
      return true;
    } else {
      return true;
    }
  }

  V T::*m_member;
  KeyInfo m_info;
  std::optional<V> m_default;
  std::optional<double> m_lo, m_hi;
  bool m_lo_open = false, m_hi_open = false;
  std::vector<std::string> m_choices;
};

template <class T, class V>
Key<T, V> key(V T::*member, std::string name) {
  return Key<T, V>(member, std::move(name));
}

// A table of the deck ([solids]) or an element of an array of tables ([[boundary]]).
template <class T>
struct Section {
  std::string name;  // dotted path, e.g. "grid.x"
  std::string title;
  std::vector<KeySpec<T>> keys;
  std::vector<std::string> also_known = {};  // nested tables or keys read by another section

  std::vector<std::string> key_names() const {
    std::vector<std::string> out;
    for (const auto& k : keys) out.push_back(k.info.name);
    for (const auto& s : also_known) out.push_back(s);
    return out;
  }
  std::vector<KeyInfo> infos() const {
    std::vector<KeyInfo> out;
    for (const auto& k : keys) out.push_back(k.info);
    return out;
  }
};

// Reports every key of `table` that `known` does not list, with the closest known name.
void check_unknown_keys(const toml::table& table, const std::string& path,
                        const std::vector<std::string>& known, Diagnostics& diag);

// Fills `out` from `table` (which may be null: all defaults). `path` is the table's dotted path
// as shown in messages ("boundary[2]").
template <class T>
void read_section(const toml::table* table, const Section<T>& section, const std::string& path,
                  T& out, Diagnostics& diag, const toml::source_region& where = {},
                  bool check_unknown = true) {
  for (const auto& k : section.keys) {
    k.apply_default(out);
    const toml::node* node = table ? table->get(k.info.name) : nullptr;
    if (node) {
      k.read(*node, out, path + "." + k.info.name, diag);
    } else if (k.info.required) {
      diag.error(table ? table->source() : where, path + "." + k.info.name,
                 "missing required key (" + k.info.type +
                     (k.info.unit.empty() || k.info.unit == "-" ? "" : " [" + k.info.unit + "]") +
                     ")");
    }
  }
  if (table && check_unknown) check_unknown_keys(*table, path, section.key_names(), diag);
}

// "name = value  # [unit]" lines of a section's resolved values.
template <class T>
std::string show_section(const Section<T>& section, const T& values) {
  std::ostringstream s;
  for (const auto& k : section.keys) {
    s << k.info.name << " = " << k.show(values);
    if (!k.info.unit.empty() && k.info.unit != "-") s << "  # [" << k.info.unit << "]";
    s << '\n';
  }
  return s.str();
}

}  // namespace bagnold::deck
