#pragma once
// A model's own constants, declared once with their unit, default, range and doc. The deck
// layer turns these declarations into the keys of [models.<family>.<model>] (so the models stay
// free of TOML), and hands the resolved values back as a Coefficients map.

#include <initializer_list>
#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace bagnold::models {

struct CoefficientSpec {
  std::string name;  // deck key, snake_case
  std::string unit;  // "-" for dimensionless
  std::variant<double, std::string> default_value;
  double min = -std::numeric_limits<double>::infinity();  // inclusive, for real values
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  // allowed values, for string options
  std::string doc;
  bool required = false;  // no default: the deck must give it
};

// Builders for the two kinds of declaration (designated initializers of CoefficientSpec would
// trip -Wmissing-field-initializers for the members a kind does not use).
CoefficientSpec real_spec(std::string name, std::string unit, double default_value, double min,
                          double max, std::string doc);
CoefficientSpec choice_spec(std::string name, std::string default_value,
                            std::vector<std::string> choices, std::string doc);

// The same declaration without a default: a deck that selects the model must give the value.
CoefficientSpec required(CoefficientSpec spec);

// The declarations of several parts (a model's own, then shared groups), in order.
std::vector<CoefficientSpec> concatenate(std::initializer_list<std::vector<CoefficientSpec>> parts);

using CoefficientValue = std::variant<double, std::string>;
using Coefficients = std::map<std::string, CoefficientValue>;

// Defaults of every declared coefficient, overridden by the given values; std::invalid_argument
// naming a required coefficient that is not given.
Coefficients resolve(const std::vector<CoefficientSpec>& specs, const Coefficients& given);
double real_coefficient(const Coefficients& c, const std::string& name);
const std::string& string_coefficient(const Coefficients& c, const std::string& name);

}  // namespace bagnold::models
