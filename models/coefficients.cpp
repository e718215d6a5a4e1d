#include "models/coefficients.hpp"

#include <stdexcept>
#include <utility>

namespace bagnold::models {

CoefficientSpec real_spec(std::string name, std::string unit, double default_value, double min,
                          double max, std::string doc) {
  CoefficientSpec s;
  s.name = std::move(name);
  s.unit = std::move(unit);
  s.default_value = default_value;
  s.min = min;
  s.max = max;
  s.doc = std::move(doc);
  return s;
}

CoefficientSpec choice_spec(std::string name, std::string default_value,
                            std::vector<std::string> choices, std::string doc) {
  CoefficientSpec s;
  s.name = std::move(name);
  s.unit = std::string(1, '-');
  s.default_value = std::move(default_value);
  s.choices = std::move(choices);
  s.doc = std::move(doc);
  return s;
}

std::vector<CoefficientSpec> concatenate(
    std::initializer_list<std::vector<CoefficientSpec>> parts) {
  std::vector<CoefficientSpec> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

CoefficientSpec required(CoefficientSpec spec) {
  spec.required = true;
  return spec;
}

Coefficients resolve(const std::vector<CoefficientSpec>& specs, const Coefficients& given) {
  Coefficients out;
  for (const auto& spec : specs) out[spec.name] = spec.default_value;
  for (const auto& [name, value] : given) {
    if (!out.contains(name)) throw std::invalid_argument("unknown coefficient '" + name + "'");
    out[name] = value;
  }
  for (const auto& spec : specs)
    if (spec.required && !given.contains(spec.name))
      throw std::invalid_argument("coefficient '" + spec.name + "' has no default and must be given");
  return out;
}

double real_coefficient(const Coefficients& c, const std::string& name) {
  const auto it = c.find(name);
  if (it == c.end() || !std::holds_alternative<double>(it->second))
    throw std::invalid_argument("missing real coefficient '" + name + "'");
  return std::get<double>(it->second);
}

const std::string& string_coefficient(const Coefficients& c, const std::string& name) {
  const auto it = c.find(name);
  if (it == c.end() || !std::holds_alternative<std::string>(it->second))
    throw std::invalid_argument("missing string coefficient '" + name + "'");
  return std::get<std::string>(it->second);
}

}  // namespace bagnold::models
