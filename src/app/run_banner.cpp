#include "src/app/run_banner.hpp"

#include <fmt/format.h>

#include "src/deck/schema.hpp"

namespace bagnold::app {

namespace {

std::string coefficients_text(const models::Coefficients& coefficients) {
  std::string out;
  for (const auto& [name, value] : coefficients) {
    out += out.empty() ? " (" : ", ";
    out += name + " = " +
           (std::holds_alternative<double>(value) ? deck::to_toml_text(std::get<double>(value))
                                                  : deck::to_toml_text(std::get<std::string>(value)));
  }
  return out.empty() ? out : out + ")";
}

// "base dense-slip (wall_friction = 0.3)": the law and the parameters it takes.
std::string wall_law_text(const deck::BoundaryRegion& region) {
  std::string out = region.name + " " + region.solids_wall;
  if (region.solids_wall == "johnson-jackson")
    out += " (specularity = " + deck::to_toml_text(region.specularity) +
           ", wall_restitution = " + deck::to_toml_text(region.wall_restitution) + ")";
  else if (region.solids_wall == "dense-slip")
    out += " (wall_friction = " + deck::to_toml_text(region.wall_friction) + ")";
  return out;
}

}  // namespace

std::string run_banner(const deck::Deck& deck, const grid::BoundaryRegions& regions,
                       const run::Provenance& provenance) {
  std::string out = fmt::format("build: bagnold {}, git {}, {} rank(s), started {}\n",
                                provenance.version, provenance.git_hash, provenance.ranks,
                                provenance.start_time);
  const auto& m = deck.models;
  if (deck.solids.enabled) {
    out += "solids stress: " +
           (deck.solids.momentum ? m.solids_stress.name + coefficients_text(m.solids_stress.coefficients)
                                 : std::string("none (solids.momentum = false: frozen)")) +
           "\n";
    if (deck.gas.enabled) out += "drag: " + m.drag.name + coefficients_text(m.drag.coefficients) + "\n";
    std::string walls;
    for (std::size_t r = 0; r < regions.regions.size(); ++r)
      if (regions.types[r] == grid::BoundaryType::no_slip_wall ||
          regions.types[r] == grid::BoundaryType::moving_wall)
        walls += (walls.empty() ? "" : "; ") + wall_law_text(regions.regions[r]);
    if (!walls.empty()) out += "solids wall laws: " + walls + "\n";
  } else {
    out += "solids: none (gas only)\n";
  }
  const auto& n = deck.numerics;
  out += fmt::format("numerics: {}, convection {}, viscosity average {}, pressure preconditioner {}, momentum preconditioner {}\n",
                     n.algorithm, n.convection, n.viscosity_average, n.pressure_preconditioner,
                     n.momentum_preconditioner);
  return out;
}

}  // namespace bagnold::app
