// io::agree: an action that fails on one rank makes every rank throw, with that rank's message;
// one that fails nowhere returns on all. On 1, 2 and 3 ranks.
#include <gtest/gtest.h>

#include <stdexcept>

#include "src/io/io_error.hpp"
#include "src/io/agree.hpp"

namespace bagnold::tests {
namespace {

TEST(Agree, AFailureOnTheLastRankStopsEveryRankWithItsMessage) {
  const parallel::Communicator comm;
  const int last = comm.size() - 1;
  try {
    io::agree(comm, [&] {
      if (comm.rank() == last) throw std::runtime_error("cannot append to the monitor m.csv (disk full?)");
    });
    FAIL() << "rank " << comm.rank() << " did not throw";
  } catch (const io::Hdf5Error& e) {
    EXPECT_STREQ(e.what(), "cannot append to the monitor m.csv (disk full?)");
  }
  // Every rank is still in step: a collective after the failure completes.
  EXPECT_EQ(comm.sum(1.0), static_cast<double>(comm.size()));
}

TEST(Agree, TheLowestFailingRanksMessageWinsAndSuccessReturns) {
  const parallel::Communicator comm;
  EXPECT_NO_THROW(io::agree(comm, [] {}));
  try {
    io::agree(comm, [&] { throw std::runtime_error("rank " + std::to_string(comm.rank())); });
    FAIL();
  } catch (const io::Hdf5Error& e) {
    EXPECT_STREQ(e.what(), "rank 0");
  }
}

}  // namespace
}  // namespace bagnold::tests
