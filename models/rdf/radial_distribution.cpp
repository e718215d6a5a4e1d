// The radial distribution functions the deck can name: one table, in the order the deck lists
// them. Adding a member is one row here (and its formula in its own file). A table built on
// first use, not self-registration: the stress models read the names while they register
// themselves, before any other file's registrar may have run.
#include "models/rdf/radial_distribution.hpp"

#include "models/dual.hpp"
#include "models/registry.hpp"

namespace bagnold::models::rdf {

const std::vector<RadialDistribution>& radial_distributions() {
  static const std::vector<RadialDistribution> table{
      {.name = "carnahan-starling",
       .summary = "App. B Eq. 11",
       .value = [](double phi, double) { return carnahan_starling(phi); },
       .dual = [](Dual phi, double) { return carnahan_starling(phi); }},
      {.name = "torquato",
       .summary = "Eq. 12, product form, φ_c(μ)",
       .value = [](double phi, double critical) { return torquato(phi, critical); },
       .dual = [](Dual phi, double critical) { return torquato(phi, critical); }},
      {.name = "mkt",
       .summary = "Eq. 31, φ_c(μ)",
       .value = [](double phi, double critical) { return chialvo_sundaresan(phi, critical); },
       .dual = [](Dual phi, double critical) { return chialvo_sundaresan(phi, critical); }},
  };
  return table;
}

const RadialDistribution& radial_distribution(const std::string& name) {
  for (const auto& g : radial_distributions())
    if (g.name == name) return g;
  std::string known;
  for (const auto& g : radial_distributions()) known += (known.empty() ? "" : ", ") + g.name;
  throw UnknownModel("unknown radial distribution '" + name + "' (known: " + known + ")");
}

std::vector<std::string> radial_distribution_names() {
  std::vector<std::string> names;
  for (const auto& g : radial_distributions()) names.push_back(g.name);
  return names;
}

}  // namespace bagnold::models::rdf
