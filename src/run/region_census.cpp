#include "src/run/region_census.hpp"

#include "src/run/initial_state.hpp"

namespace bagnold::run {

namespace {

// Cells shared by each pair (a, b), a < b, of n regions, summed over the ranks.
class PairCounts {
 public:
  explicit PairCounts(std::size_t n) : m_n(n), m_counts(n * n, 0) {}

  // One cell, selected by the regions listed (ascending).
  void add(const std::vector<int>& selecting) {
    for (std::size_t a = 0; a < selecting.size(); ++a)
      for (std::size_t b = a + 1; b < selecting.size(); ++b)
        ++m_counts[static_cast<std::size_t>(selecting[a]) * m_n + static_cast<std::size_t>(selecting[b])];
  }

  std::vector<RegionOverlap> overlaps(const parallel::Communicator& comm) {
    comm.sum_in_place(m_counts);
    std::vector<RegionOverlap> out;
    for (std::size_t a = 0; a < m_n; ++a)
      for (std::size_t b = a + 1; b < m_n; ++b)
        if (const auto shared = m_counts[a * m_n + b]; shared > 0)
          out.push_back({static_cast<int>(a), static_cast<int>(b), shared});
    return out;
  }

 private:
  std::size_t m_n;
  std::vector<std::int64_t> m_counts;
};

// Selected and kept counts as two vectors, summed over the ranks.
std::vector<RegionCount> summed(std::vector<std::int64_t> selected, std::vector<std::int64_t> kept,
                                const parallel::Communicator& comm) {
  comm.sum_in_place(selected);
  comm.sum_in_place(kept);
  std::vector<RegionCount> out(selected.size());
  for (std::size_t r = 0; r < out.size(); ++r) out[r] = {selected[r], kept[r]};
  return out;
}

}  // namespace

RegionCensus take_region_census(const deck::Deck& deck, const parallel::Domain& domain) {
  const auto& layout = domain.layout;
  const auto& grid = domain.grid;
  const auto& comm = layout.comm();
  RegionCensus census;
  census.block_cells = domain.flags.block_cells;

  // Boundary regions, over the owned boundary cells.
  const std::size_t n_boundary = deck.boundaries.size();
  std::vector<std::int64_t> selected(n_boundary, 0), kept(n_boundary, 0);
  PairCounts boundary_pairs(n_boundary);
  std::vector<int> selecting;
  for (int l = layout.owned_fluid_count(); l < layout.owned_count(); ++l) {
    const auto ijk = layout.index3(l);
    selecting.clear();
    for (std::size_t r = 0; r < n_boundary; ++r)
      if (grid::region_selects(grid, ijk, deck.boundaries[r])) {
        selecting.push_back(static_cast<int>(r));
        ++selected[r];
      }
    if (const int held = layout.region(l); held >= 0 && static_cast<std::size_t>(held) < n_boundary)
      ++kept[static_cast<std::size_t>(held)];
    else
      ++census.walls;
    boundary_pairs.add(selecting);
  }
  census.walls = comm.sum(census.walls);
  census.boundaries = summed(selected, kept, comm);
  census.boundary_overlaps = boundary_pairs.overlaps(comm);

  // Initial regions, over the owned fluid cells.
  const std::size_t n_initial = deck.initial.size();
  selected.assign(n_initial, 0);
  kept.assign(n_initial, 0);
  census.initial_solids_mass.assign(n_initial, 0.0);
  PairCounts initial_pairs(n_initial);
  for (int l = 0; l < layout.owned_fluid_count(); ++l) {
    const auto ijk = layout.index3(l);
    const auto x = grid.centre(ijk);
    selecting.clear();
    for (std::size_t r = 0; r < n_initial; ++r)
      if (initial_region_selects(deck.initial[r], layout.kind(l), x)) {
        selecting.push_back(static_cast<int>(r));
        ++selected[r];
      }
    if (selecting.empty()) continue;
    const auto winner = static_cast<std::size_t>(selecting.back());
    ++kept[winner];
    census.initial_solids_mass[winner] +=
        deck.solids.material.density * deck.initial[winner].solids_fraction * grid.volume(ijk);
    initial_pairs.add(selecting);
  }
  census.initial = summed(selected, kept, comm);
  census.initial_overlaps = initial_pairs.overlaps(comm);
  comm.sum_in_place(census.initial_solids_mass);
  if (!deck.solids.enabled) census.initial_solids_mass.assign(n_initial, 0.0);
  return census;
}

}  // namespace bagnold::run
