#include "models/coefficients.hpp"

#include <stdexcept>

namespace bagnold::models {

Coefficients resolve(const std::vector<CoefficientSpec>& specs, const Coefficients& given) {
  Coefficients out;
  for (const auto& spec : specs) out[spec.name] = spec.default_value;
  for (const auto& [name, value] : given) {
    if (!out.contains(name)) throw std::invalid_argument("unknown coefficient '" + name + "'");
    out[name] = value;
  }
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
