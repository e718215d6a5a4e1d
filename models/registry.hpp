#pragma once
// Run-time selection of a model family member by name (as OpenFOAM's run-time selection tables
// and AMR-Wind's Factory, without macros). Each member registers itself at the end of its own
// .cpp; `models` is a CMake OBJECT library so no registrar is dropped by the linker.
//
// Input is what make() builds a member from: the member's resolved coefficients for the
// closures (stress, drag), or a family's own struct (the wall laws' WallLawInput).

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "models/coefficients.hpp"

namespace bagnold::models {

class UnknownModel : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

template <class Base, class Input = Coefficients>
class Registry {
 public:
  struct Entry {
    std::string name;
    std::string summary;
    std::vector<CoefficientSpec> coefficients;
    std::function<std::unique_ptr<Base>(const Input&)> make;
  };

  bool add(Entry entry) {
    m_entries.push_back(std::move(entry));
    std::sort(m_entries.begin(), m_entries.end(),
              [](const Entry& a, const Entry& b) { return a.name < b.name; });
    return true;
  }

  const Entry& find(const std::string& name) const {
    for (const auto& e : m_entries)
      if (e.name == name) return e;
    std::string known;
    for (const auto& e : m_entries) known += (known.empty() ? "" : ", ") + e.name;
    throw UnknownModel("unknown model '" + name + "' (known: " + known + ")");
  }

  // Builds the named member from `given`; coefficients are first resolved against the
  // member's declarations (defaults fill what is not given).
  std::unique_ptr<Base> create(const std::string& name, const Input& given = {}) const {
    const Entry& e = find(name);
    if constexpr (std::is_same_v<Input, Coefficients>)
      return e.make(resolve(e.coefficients, given));
    else
      return e.make(given);
  }

  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : m_entries) out.push_back(e.name);
    return out;
  }
  const std::vector<Entry>& entries() const { return m_entries; }

 private:
  std::vector<Entry> m_entries;
};

}  // namespace bagnold::models
