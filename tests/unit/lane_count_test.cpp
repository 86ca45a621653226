// laneCount (raster/lane_count.h) against std::popcount: every single bit, the edges, and
// random masks of every density.
#include <gtest/gtest.h>

#include <bit>
#include <random>

#include "raster/lane_count.h"

namespace pf {
namespace {

TEST(LaneCount, IsPopcount) {
  EXPECT_EQ(laneCount(0), 0);
  EXPECT_EQ(laneCount(~0ull), 64);
  for (int i = 0; i < 64; ++i) {
    EXPECT_EQ(laneCount(1ull << i), 1) << i;
    EXPECT_EQ(laneCount(~(1ull << i)), 63) << i;
    EXPECT_EQ(laneCount((1ull << i) - 1), i) << i;
  }
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 100000; ++trial) {
    // Dense or sparse: the AND or OR of a few random words.
    uint64_t m = rng();
    for (int k = trial % 4; k > 0; --k) m = trial % 2 ? (m & rng()) : (m | rng());
    ASSERT_EQ(laneCount(m), std::popcount(m)) << std::hex << m;
  }
}

}  // namespace
}  // namespace pf
