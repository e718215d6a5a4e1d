#include "src/run/region_report.hpp"

#include <fmt/format.h>

namespace bagnold::run {

namespace {

std::string point_text(const std::array<double, 3>& p) {
  return fmt::format("[{:g}, {:g}, {:g}]", p[0], p[1], p[2]);
}

std::string box_text(const std::array<double, 3>& min, const std::array<double, 3>& max) {
  return "min = " + point_text(min) + " to max = " + point_text(max);
}

// Where the domain's cell centres lie, for a box that misses them all.
std::string centre_span(const grid::StructuredGrid& g) {
  std::string out;
  for (int d = 0; d < 3; ++d)
    out += fmt::format("{}{} in [{:g}, {:g}]", d ? ", " : "", "xyz"[d], g.axis(d).centre(0),
                       g.axis(d).centre(g.cells(d) - 1));
  return out + " m";
}

// Which boundary cells a region's face offers, and where their centres are.
std::string face_hint(const grid::StructuredGrid& g, const std::string& face) {
  const std::string ring =
      "the boundary cells of a domain face are the layer outside it, with centres half a cell "
      "beyond the face, so a box on a domain face must reach past the face";
  if (face == "internal") return "internal boundary cells are blocked cells inside the domain next to fluid";
  if (face == "any") return ring + "; internal ones are blocked cells next to fluid";
  const int d = face[0] - 'x';
  const double centre = face[1] == '-' ? g.axis(d).centre(-1) : g.axis(d).centre(g.cells(d));
  return fmt::format("the boundary cells of face {} are the layer outside it, with centres at {} = "
                     "{:g} m: the box must take them in (a box on a domain face reaches past the face)",
                     face, "xyz"[d], centre);
}

std::string boundary_name(const deck::Deck& deck, int r) {
  return fmt::format("boundary[{}] \"{}\"", r, deck.boundaries[static_cast<std::size_t>(r)].name);
}

std::string initial_name(const deck::Deck& deck, int r) {
  return fmt::format("initial[{}] ({})", r, origin_text(deck.origin_of(fmt::format("initial[{}]", r))));
}

void judge_blocks(const deck::Deck& deck, const parallel::Domain& domain, const RegionCensus& c,
                  RegionReport& report) {
  for (std::size_t b = 0; b < c.block_cells.size(); ++b) {
    const auto& block = deck.geometry.blocks[b];
    const std::string path = fmt::format("geometry.block[{}]", b);
    report.text += fmt::format("{} {} {} ({}): blocks {} cells\n", path, block.shape, block.blocks,
                               origin_text(deck.origin_of(path)), c.block_cells[b]);
    if (c.block_cells[b] == 0)
      report.errors.error(
          deck.origin_of(path), path,
          fmt::format("blocks no cell. A block makes solid each domain cell whose centre lies "
                      "inside the {} (blocks = \"inside\") or outside it (blocks = \"outside\"); "
                      "no centre of the domain's cells ({}) is {} this one",
                      block.shape, centre_span(domain.grid), block.blocks));
  }
}

void judge_boundaries(const deck::Deck& deck, const parallel::Domain& domain, const RegionCensus& c,
                      RegionReport& report) {
  for (std::size_t r = 0; r < c.boundaries.size(); ++r) {
    const auto& region = deck.boundaries[r];
    const auto& count = c.boundaries[r];
    const std::string path = fmt::format("boundary[{}]", r);
    report.text += fmt::format("{} {} ({}): {} cells", boundary_name(deck, static_cast<int>(r)),
                               region.type, origin_text(deck.origin_of(path)), count.kept);
    if (count.kept != count.selected)
      report.text += fmt::format(" (of {} it selects; an earlier region holds the others)", count.selected);
    report.text += "\n";
    if (count.selected == 0) {
      report.errors.error(
          deck.origin_of(path), path,
          fmt::format("region \"{}\" selects no cell. A [[boundary]] region holds the boundary cells "
                      "on its face (face = \"{}\") whose centres lie in its box, {}; {}",
                      region.name, region.face, box_text(region.min, region.max),
                      face_hint(domain.grid, region.face)));
    } else if (count.kept == 0) {
      std::string earlier;
      for (const auto& o : c.boundary_overlaps)
        if (o.second == static_cast<int>(r))
          earlier += (earlier.empty() ? "" : ", ") + boundary_name(deck, o.first);
      report.errors.error(
          deck.origin_of(path), path,
          fmt::format("region \"{}\" holds no cell: an earlier region holds every one of the {} "
                      "cells it selects ({}); a boundary cell belongs to the first [[boundary]] "
                      "listed that selects it",
                      region.name, count.selected, earlier));
    }
  }
  report.text += fmt::format("walls {} (geometry.default_wall, the boundary cells no region holds): "
                             "{} cells\n", deck.geometry.default_wall, c.walls);
  for (const auto& o : c.boundary_overlaps)
    report.notes.push_back(fmt::format(
        "note: {} and {} both select {} boundary cell{}; the first listed that selects a cell "
        "holds it, so {} holds none of these",
        boundary_name(deck, o.first), boundary_name(deck, o.second), o.shared,
        o.shared == 1 ? "" : "s", boundary_name(deck, o.second)));
}

void judge_initial(const deck::Deck& deck, const parallel::Domain& domain, const RegionCensus& c,
                   RegionReport& report) {
  double total_mass = 0.0;
  std::int64_t total_cells = 0;
  for (std::size_t r = 0; r < c.initial.size(); ++r) {
    const auto& region = deck.initial[r];
    const auto& count = c.initial[r];
    const std::string path = fmt::format("initial[{}]", r);
    report.text += fmt::format("{}: {} cells", initial_name(deck, static_cast<int>(r)), count.kept);
    if (count.kept != count.selected)
      report.text += fmt::format(" (of {} it selects; a later region sets the others)", count.selected);
    report.text += fmt::format(", solids_fraction {:g}", region.solids_fraction);
    if (deck.solids.enabled) report.text += fmt::format(", solids {:.6g} kg", c.initial_solids_mass[r]);
    report.text += "\n";
    total_mass += c.initial_solids_mass[r];
    total_cells += count.kept;
    if (count.selected == 0)
      report.errors.error(
          deck.origin_of(path), path,
          fmt::format("selects no cell. An [[initial]] region sets the fluid cells whose centres lie "
                      "in its box, {}; the domain's cell centres span {} (blocked cells are not set)",
                      box_text(region.min, region.max), centre_span(domain.grid)));
  }
  if (deck.solids.enabled && !c.initial.empty())
    report.text += fmt::format("initial solids: {:.6g} kg in {} cells\n", total_mass, total_cells);
  for (const auto& o : c.initial_overlaps)
    report.notes.push_back(fmt::format(
        "note: {} and {} both select {} cell{}; the last listed that selects a cell sets it, so "
        "{} sets none of these",
        initial_name(deck, o.first), initial_name(deck, o.second), o.shared,
        o.shared == 1 ? "" : "s", fmt::format("initial[{}]", o.first)));
}

}  // namespace

std::string origin_text(const deck::Origin& origin) {
  return origin.line > 0 ? fmt::format("{}:{}", origin.file, origin.line) : origin.file;
}

RegionReport report_regions(const deck::Deck& deck, const parallel::Domain& domain,
                            const RegionCensus& census) {
  RegionReport report;
  report.text = "# Regions (each selects cells by their centres: docs/deck.md, \"How regions select cells\")\n";
  judge_blocks(deck, domain, census, report);
  judge_boundaries(deck, domain, census, report);
  judge_initial(deck, domain, census, report);
  for (const auto& note : report.notes) report.text += note + "\n";
  return report;
}

}  // namespace bagnold::run
