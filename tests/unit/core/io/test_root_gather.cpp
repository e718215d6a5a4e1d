// io::RootGather: every rank's values land on rank 0 at their points, the fill where no rank owns
// one, for one and three values per point; the other ranks get nothing. On 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "src/io/root_gather.hpp"

namespace bagnold::tests {
namespace {

// Rank r owns the points p < 2·size (of 2·size + 1) with p % size == r, read backwards; the
// last point is nobody's.
std::vector<std::uint64_t> points_of(const parallel::Communicator& comm) {
  std::vector<std::uint64_t> points;
  for (int p = 2 * comm.size() - 1; p >= 0; --p)
    if (p % comm.size() == comm.rank()) points.push_back(static_cast<std::uint64_t>(p));
  return points;
}

TEST(RootGather, PlacesEveryRanksValuesAndFillsTheRest) {
  const parallel::Communicator comm;
  const auto points = points_of(comm);
  const std::uint64_t size = 2 * static_cast<std::uint64_t>(comm.size()) + 1;
  const io::RootGather gather(comm, points, size);
  std::vector<double> scalars, vectors;
  for (const auto p : points) {
    scalars.push_back(10.0 * static_cast<double>(p));
    for (int c = 0; c < 3; ++c) vectors.push_back(10.0 * static_cast<double>(p) + c);
  }
  const auto whole = gather.gather(scalars, 1, -1.0);
  const auto whole3 = gather.gather(vectors, 3, std::nan(""));
  if (!comm.is_root()) {
    EXPECT_TRUE(whole.empty());
    EXPECT_TRUE(whole3.empty());
    return;
  }
  ASSERT_EQ(whole.size(), size);
  ASSERT_EQ(whole3.size(), 3 * size);
  for (std::uint64_t p = 0; p + 1 < size; ++p) {
    EXPECT_EQ(whole[p], 10.0 * static_cast<double>(p)) << p;
    for (std::uint64_t c = 0; c < 3; ++c)
      EXPECT_EQ(whole3[3 * p + c], 10.0 * static_cast<double>(p) + static_cast<double>(c)) << p;
  }
  EXPECT_EQ(whole[size - 1], -1.0);
  for (std::uint64_t c = 0; c < 3; ++c) EXPECT_TRUE(std::isnan(whole3[3 * (size - 1) + c]));
}

TEST(RootGather, ARankWithoutPointsTakesPart) {
  const parallel::Communicator comm;
  std::vector<std::uint64_t> points;
  if (comm.rank() == comm.size() - 1) points = {0, 1};
  const io::RootGather gather(comm, points, 2);
  const std::vector<double> values(points.size(), 7.0);
  const auto whole = gather.gather(values, 1, 0.0);
  if (comm.is_root()) {
    EXPECT_EQ(whole, (std::vector<double>{7.0, 7.0}));
  }
}

}  // namespace
}  // namespace bagnold::tests
