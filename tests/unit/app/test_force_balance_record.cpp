// The run's force-balance record: the largest value with its equation and time, and the count of
// steps above the tolerance, over steps and over the segments a repartitioned run is made of.
#include <gtest/gtest.h>

#include "src/app/force_balance_record.hpp"

namespace bagnold::tests {
namespace {

TEST(ForceBalanceRecord, KeepsTheLargestAndCountsStepsAboveTheTolerance) {
  app::ForceBalanceRecord record;
  EXPECT_LT(record.largest, 0.0);  // nothing recorded yet
  record.add(2e-5, 3, 0.1, 1e-4);
  record.add(0.3, 4, 0.2, 1e-4);
  record.add(0.1, 5, 0.3, 1e-4);
  record.add(1e-4, 0, 0.4, 1e-4);  // at the tolerance: not above it
  EXPECT_EQ(record.largest, 0.3);
  EXPECT_EQ(record.largest_equation, 4);
  EXPECT_EQ(record.largest_at, 0.2);
  EXPECT_EQ(record.above_tolerance, 2);
}

TEST(ForceBalanceRecord, MergesALaterSegment) {
  app::ForceBalanceRecord first, later;
  first.add(0.05, 3, 0.1, 1e-4);
  later.add(0.5, 5, 0.7, 1e-4);
  later.add(5e-5, 3, 0.8, 1e-4);
  first.add(later);
  EXPECT_EQ(first.largest, 0.5);
  EXPECT_EQ(first.largest_equation, 5);
  EXPECT_EQ(first.largest_at, 0.7);
  EXPECT_EQ(first.above_tolerance, 2);
  app::ForceBalanceRecord smaller;
  smaller.add(0.01, 0, 0.9, 1e-4);
  first.add(smaller);  // a smaller largest keeps the earlier one
  EXPECT_EQ(first.largest_equation, 5);
  EXPECT_EQ(first.above_tolerance, 3);
}

}  // namespace
}  // namespace bagnold::tests
