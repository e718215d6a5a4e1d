// Partition, local numbering and halo exchange, run on 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include "src/deck/load.hpp"
#include "src/parallel/layout.hpp"
#include "src/parallel/domain.hpp"
#include "tests/support/test_decks.hpp"

namespace bagnold::tests {
namespace {

using grid::CellKind;

// The domain of a deck, built on this communicator (as a run builds it).
struct Built {
  deck::Deck deck;
  parallel::Domain domain;
  const grid::StructuredGrid& grid = domain.grid;
  const grid::CellFlags& flags = domain.flags;
  const std::vector<int>& owner = domain.owner;
  const parallel::Layout& layout = domain.layout;

  explicit Built(const std::string& text)
      : deck(deck::load_deck_text(text, "test.toml")), domain(deck, parallel::Communicator()) {}
};

// A hopper-like geometry: a box with a blocked corner and a periodic direction.
const std::string hopper_extra =
    "[grid]\nperiodic = [\"y\"]\n"
    "[[geometry.block]]\nshape = \"half_space\"\npoint = [0.06, 0.0, 0.0]\n"
    "normal = [1.0, 0.0, -1.0]\n";

TEST(Layout, EveryStoredCellIsOwnedExactlyOnce) {
  Built s(box_deck(8, 4, 10, hopper_extra));
  const parallel::Communicator comm;
  const auto owned = comm.sum(std::int64_t{s.layout.owned_count()});
  EXPECT_EQ(owned, s.flags.fluid_count + s.flags.boundary_count);
  EXPECT_EQ(s.layout.global_fluid_count(), s.flags.fluid_count);
}

TEST(Layout, GlobalFluidNumberingIsContiguousPerRank) {
  Built s(box_deck(8, 4, 10, hopper_extra));
  const parallel::Communicator comm;
  const auto offsets = comm.all_gather(s.layout.global_fluid_offset());
  const auto counts = comm.all_gather(std::int64_t{s.layout.owned_fluid_count()});
  for (int r = 1; r < comm.size(); ++r)
    EXPECT_EQ(offsets[static_cast<std::size_t>(r)],
              offsets[static_cast<std::size_t>(r) - 1] + counts[static_cast<std::size_t>(r) - 1]);
  for (int l = 0; l < s.layout.owned_fluid_count(); ++l)
    EXPECT_EQ(s.layout.global_fluid_index(l), s.layout.global_fluid_offset() + l);
}

TEST(Layout, HaloHoldsEveryStoredCellWithinTwoCells) {
  Built s(box_deck(8, 4, 10, hopper_extra));
  const auto& g = s.grid;
  for (int l = 0; l < s.layout.owned_count(); ++l) {
    const auto ijk = s.layout.index3(l);
    for (int dk = -2; dk <= 2; ++dk)
      for (int dj = -2; dj <= 2; ++dj)
        for (int di = -2; di <= 2; ++di) {
          grid::Index3 other;
          if (!g.step(ijk, {di, dj, dk}, other)) continue;
          const auto n = g.natural(other);
          if (s.flags.kind[static_cast<std::size_t>(n)] == CellKind::excluded) continue;
          EXPECT_GE(s.layout.find(n), 0) << "missing cell " << n;
        }
  }
}

TEST(Layout, HaloValuesEqualTheOwnersValues) {
  Built s(box_deck(8, 4, 10, hopper_extra));
  // Each rank fills its owned cells with a function of the natural index, halo with garbage.
  std::vector<double> field(static_cast<std::size_t>(s.layout.local_count()), -1.0);
  std::vector<int> ranks(field.size(), -1);
  const int me = parallel::Communicator().rank();
  for (int l = 0; l < s.layout.owned_count(); ++l) {
    field[static_cast<std::size_t>(l)] = std::sin(0.1 * static_cast<double>(s.layout.natural(l)));
    ranks[static_cast<std::size_t>(l)] = me;
  }
  parallel::exchange_halo<double>(s.layout, field);
  parallel::exchange_halo<int>(s.layout, ranks);
  for (int l = 0; l < s.layout.local_count(); ++l) {
    const auto n = s.layout.natural(l);
    EXPECT_EQ(field[static_cast<std::size_t>(l)], std::sin(0.1 * static_cast<double>(n)));
    EXPECT_EQ(ranks[static_cast<std::size_t>(l)], s.owner[static_cast<std::size_t>(n)]);
  }
}

TEST(Layout, NeighbourTableFollowsTheGrid) {
  Built s(box_deck(8, 4, 10, hopper_extra));
  for (int l = 0; l < s.layout.owned_count(); ++l) {
    const auto ijk = s.layout.index3(l);
    const int east = s.layout.neighbour(l, parallel::east);
    if (east < 0) continue;
    auto expected = ijk;
    expected[0] += 1;
    EXPECT_EQ(s.layout.index3(east), expected);
    const int north = s.layout.neighbour(l, parallel::north);
    ASSERT_GE(north, 0);  // y is periodic: every cell has a north neighbour
    EXPECT_EQ(s.layout.index3(north)[1], (ijk[1] + 1) % 4);
  }
}

TEST(Partition, BalancedWithinFivePercent) {
  Built s(box_deck(12, 12, 12, hopper_extra));
  const parallel::Communicator comm;
  const auto mine = std::int64_t{s.layout.owned_fluid_count()};
  const double mean = static_cast<double>(s.flags.fluid_count) / comm.size();
  EXPECT_LE(static_cast<double>(comm.max(mine)), 1.05 * mean);
}

}  // namespace
}  // namespace bagnold::tests
