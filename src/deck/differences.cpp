#include "src/deck/differences.hpp"

#include <algorithm>
#include <map>

#include "src/deck/load.hpp"
#include "src/deck/schema.hpp"

namespace bagnold::deck {

namespace {

struct Value {
  std::string exact;  // toml++'s text: doubles with 17 significant digits, equal iff the values are
  std::string shown;  // as the resolved deck writes it (shortest exact reals, "strings")
};

Value value_of(const toml::node& node) {
  const std::string exact = node_text(node);
  double x = 0;
  std::string text;
  std::vector<double> numbers;
  std::vector<std::string> words;
  if (node.is_floating_point() && read_value(node, x)) return {exact, to_toml_text(x)};
  if (read_value(node, text)) return {exact, to_toml_text(text)};
  if (node.is_array() && !node.as_array()->empty() && read_value(node, words))
    return {exact, to_toml_text(words)};
  if (node.is_array() && !node.as_array()->empty() && read_value(node, numbers))
    return {exact, to_toml_text(numbers)};
  return {exact, exact};
}

// Dotted key -> value of every leaf; arrays of tables are indexed ("boundary[0].name").
void flatten(const toml::table& table, const std::string& prefix, std::map<std::string, Value>& out) {
  for (const auto& [k, node] : table) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = node.as_table()) {
      flatten(*sub, key, out);
    } else if (const auto* array = node.as_array(); array && !array->empty() && array->is_array_of_tables()) {
      for (std::size_t i = 0; i < array->size(); ++i)
        flatten(*(*array)[i].as_table(), key + "[" + std::to_string(i) + "]", out);
    } else {
      out[key] = value_of(node);
    }
  }
}

std::map<std::string, Value> leaves(const Deck& deck) {
  std::map<std::string, Value> out;
  flatten(toml::parse(resolved_text(deck)), "", out);
  return out;
}

}  // namespace

std::vector<KeyDifference> differences(const Deck& recorded, const Deck& current) {
  const auto a = leaves(recorded);
  const auto b = leaves(current);
  std::vector<KeyDifference> out;
  const std::string absent = "(absent)";
  for (const auto& [key, value] : a) {
    const auto other = b.find(key);
    if (other == b.end())
      out.push_back({key, value.shown, absent});
    else if (other->second.exact != value.exact)
      out.push_back({key, value.shown, other->second.shown});
  }
  for (const auto& [key, value] : b)
    if (!a.contains(key)) out.push_back({key, absent, value.shown});
  std::sort(out.begin(), out.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
  return out;
}

}  // namespace bagnold::deck
