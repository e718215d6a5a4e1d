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
const std::string by_layers = "[numerics]\npartition_weights = \"layers\"\n";

// The layout's properties hold on either partition: by the fluid-cell graph (METIS) and by layers
// across gravity.
class Layout : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(Partitions, Layout, ::testing::Values("", by_layers),
                         [](const ::testing::TestParamInfo<std::string>& partition) {
                           return partition.param.empty() ? "graph" : "layers";
                         });

TEST_P(Layout, EveryStoredCellIsOwnedExactlyOnce) {
  Built s(box_deck(8, 4, 10, hopper_extra + GetParam()));
  const parallel::Communicator comm;
  const auto owned = comm.sum(std::int64_t{s.layout.owned_count()});
  EXPECT_EQ(owned, s.flags.fluid_count + s.flags.boundary_count);
  EXPECT_EQ(s.layout.global_fluid_count(), s.flags.fluid_count);
}

TEST_P(Layout, GlobalFluidNumberingIsContiguousPerRank) {
  Built s(box_deck(8, 4, 10, hopper_extra + GetParam()));
  const parallel::Communicator comm;
  const auto offsets = comm.all_gather(s.layout.global_fluid_offset());
  const auto counts = comm.all_gather(std::int64_t{s.layout.owned_fluid_count()});
  for (int r = 1; r < comm.size(); ++r)
    EXPECT_EQ(offsets[static_cast<std::size_t>(r)],
              offsets[static_cast<std::size_t>(r) - 1] + counts[static_cast<std::size_t>(r) - 1]);
  for (int l = 0; l < s.layout.owned_fluid_count(); ++l)
    EXPECT_EQ(s.layout.global_fluid_index(l), s.layout.global_fluid_offset() + l);
}

TEST_P(Layout, HaloHoldsEveryStoredCellWithinTwoCells) {
  Built s(box_deck(8, 4, 10, hopper_extra + GetParam()));
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

TEST_P(Layout, HaloValuesEqualTheOwnersValues) {
  Built s(box_deck(8, 4, 10, hopper_extra + GetParam()));
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

TEST_P(Layout, NeighbourTableFollowsTheGrid) {
  Built s(box_deck(8, 4, 10, hopper_extra + GetParam()));
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

// Per rank, the fluid cells of each layer across z (from the replicated owner table).
std::vector<std::vector<int>> fluid_cells_per_layer_and_rank(const Built& s, int ranks) {
  std::vector<std::vector<int>> count(static_cast<std::size_t>(s.grid.cells(2)),
                                      std::vector<int>(static_cast<std::size_t>(ranks), 0));
  for (std::size_t n = 0; n < s.owner.size(); ++n)
    if (s.flags.kind[n] == CellKind::fluid)
      ++count[static_cast<std::size_t>(s.grid.index3(static_cast<std::int64_t>(n))[2])]
             [static_cast<std::size_t>(s.owner[n])];
  return count;
}

TEST(Partition, ByLayersGivesEveryRankItsShareOfEveryLayerAndOfAll) {
  Built s(box_deck(9, 7, 12, hopper_extra + by_layers));  // layers of 63 cells down to 0
  const int ranks = parallel::Communicator().size();
  std::vector<int> total(static_cast<std::size_t>(ranks), 0);
  for (const auto& layer : fluid_cells_per_layer_and_rank(s, ranks)) {
    int cells = 0;
    for (const int c : layer) cells += c;
    for (int r = 0; r < ranks; ++r) {
      EXPECT_LE(std::abs(layer[static_cast<std::size_t>(r)] - static_cast<double>(cells) / ranks), 2.0);
      total[static_cast<std::size_t>(r)] += layer[static_cast<std::size_t>(r)];
    }
  }
  for (const int t : total) EXPECT_LE(std::abs(t - static_cast<double>(s.flags.fluid_count) / ranks), 2.0);
}

// Layers of 6 × 4 cells, which 1, 2 and 3 ranks cut into whole rows: the cut is a plane along
// gravity.
TEST(Partition, ByLayersCutsAlongGravityWhicheverAxisItActsAlong) {
  const char* gravity[3] = {"[-9.81, 0.0, 0.0]", "[0.0, -9.81, 0.0]", "[0.0, 0.0, -9.81]"};
  const int cells[3][3] = {{5, 6, 4}, {6, 5, 4}, {6, 4, 5}};
  for (int axis = 0; axis < 3; ++axis) {
    const auto& size = cells[axis];
    Built s(box_deck(size[0], size[1], size[2], "[physics]\ngravity = " + std::string(gravity[axis]) + "\n" + by_layers));
    grid::Index3 along{0, 0, 0};
    along[static_cast<std::size_t>(axis)] = 1;
    for (std::size_t n = 0; n < s.owner.size(); ++n) {
      if (s.flags.kind[n] != CellKind::fluid) continue;
      grid::Index3 next;
      if (!s.grid.step(s.grid.index3(static_cast<std::int64_t>(n)), along, next)) continue;
      const auto m = static_cast<std::size_t>(s.grid.natural(next));
      if (s.flags.kind[m] == CellKind::fluid) {
        EXPECT_EQ(s.owner[m], s.owner[n]) << "gravity along " << axis << ", cell " << n;
      }
    }
  }
}

// On 2 ranks, one cut across y: fluid cells with j below `last_first` on rank 0, above
// `first_second` on rank 1 (the rows between may be shared).
void expect_one_cut_across_y(const Built& s, int last_first, int first_second) {
  for (std::size_t n = 0; n < s.owner.size(); ++n)
    if (s.flags.kind[n] == CellKind::fluid) {
      const int j = s.grid.index3(static_cast<std::int64_t>(n))[1];
      if (j <= last_first) {
        EXPECT_EQ(s.owner[n], 0) << "cell " << n;
      } else if (j >= first_second) {
        EXPECT_EQ(s.owner[n], 1) << "cell " << n;
      }
    }
}

TEST(Partition, ByLayersCutsAcrossTheLongerSideOfALayer) {
  if (parallel::Communicator().size() != 2) GTEST_SKIP() << "one cut: 2 ranks";
  expect_one_cut_across_y(Built(box_deck(4, 9, 3, by_layers)), 3, 5);
}

TEST(Partition, ByLayersOnATieDoesNotCutAcrossAPeriodicAxis) {
  if (parallel::Communicator().size() != 2) GTEST_SKIP() << "one cut: 2 ranks";
  expect_one_cut_across_y(Built(box_deck(4, 4, 3, "[grid]\nperiodic = [\"x\"]\n" + by_layers)), 1, 2);
}

}  // namespace
}  // namespace bagnold::tests
