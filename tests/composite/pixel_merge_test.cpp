// The compositor's per-pixel work without MPI (composite/src/pixel_merge.h): the depth merge
// and its tie rule, and the run-length code -- exact round trips, the size of a cleared band,
// and malformed codes refused, never read past their end. After PixelFlow's compositors
// (Molnar et al. 1992, cited in seed 003 section 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "composite/src/pixel_merge.h"

using namespace pf::composite;

namespace {

struct Band {
  std::vector<uint32_t> color;
  std::vector<float> depth;
  explicit Band(size_t n, uint32_t c = 0, float d = 1.0f) : color(n, c), depth(n, d) {}
  PixelSpan span() { return {color.data(), depth.data(), color.size()}; }
  ConstPixelSpan view() const { return {color.data(), depth.data(), color.size()}; }
};

TEST(PixelMerge, NearerWinsAndTiesFollowTheRule) {
  Band dst(4), src(4);
  dst.depth = {0.5f, 0.5f, 0.5f, -0.0f};
  dst.color = {1, 1, 1, 1};
  src.depth = {0.25f, 0.5f, 0.75f, 0.0f};
  src.color = {2, 2, 2, 2};
  Band a = dst;
  mergeByDepth(a.span(), src.view(), false);
  EXPECT_EQ(a.color, (std::vector<uint32_t>{2, 1, 1, 1}));
  Band b = dst;
  mergeByDepth(b.span(), src.view(), true);
  EXPECT_EQ(b.color, (std::vector<uint32_t>{2, 2, 1, 2}));  // 0 equals -0: a tie
  EXPECT_EQ(b.depth[0], 0.25f);
}

TEST(PixelMerge, NaNNeverWins) {
  Band dst(1, 1, 0.5f), src(1, 2, std::numeric_limits<float>::quiet_NaN());
  mergeByDepth(dst.span(), src.view(), true);
  EXPECT_EQ(dst.color[0], 1u);
}

std::vector<uint32_t> encode(const Band& b) {
  std::vector<uint32_t> code(maxEncodedWords(b.color.size()));
  code.resize(encodeRuns(b.view(), code.data()));
  return code;
}

TEST(PixelMerge, ClearedBandIsOneRun) {
  Band cleared(100000, 0xff332211u, 1.0f);
  EXPECT_EQ(encode(cleared).size(), 3u);
}

TEST(PixelMerge, CodeRoundTripsEveryBit) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const size_t n = 1 + rng() % 3000;
    Band b(n, 0x10203040u, 1.0f);
    // Runs of background, single pixels, short runs, -0 and NaN depths.
    for (size_t i = 0; i < n; ++i) {
      const unsigned kind = rng() % 10;
      if (kind < 4) continue;
      b.color[i] = kind < 7 ? static_cast<uint32_t>(rng()) : 0x55u;
      b.depth[i] = kind == 7 ? -0.0f : kind == 8 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(rng()) / 4e9f;
    }
    const std::vector<uint32_t> code = encode(b);
    EXPECT_LE(code.size(), maxEncodedWords(n));
    Band out(n, 0, 0.0f);
    ASSERT_TRUE(decodeRuns(out.span(), code.data(), code.size()));
    EXPECT_EQ(out.color, b.color);
    EXPECT_EQ(std::memcmp(out.depth.data(), b.depth.data(), n * 4), 0);
    // Merging the code is merging the band.
    Band dst(n, 7, 0.5f), dst2(n, 7, 0.5f);
    for (bool ties : {false, true}) {
      ASSERT_TRUE(mergeRuns(dst.span(), code.data(), code.size(), ties));
      mergeByDepth(dst2.span(), b.view(), ties);
      EXPECT_EQ(dst.color, dst2.color);
    }
  }
}

TEST(PixelMerge, MalformedCodesAreRefused) {
  Band b(10, 1, 0.5f);
  b.color[3] = 2;
  std::vector<uint32_t> code = encode(b);
  Band out(10);
  // Truncated anywhere, one word too many, or for a band of another size.
  for (size_t cut = 0; cut < code.size(); ++cut) EXPECT_FALSE(decodeRuns(out.span(), code.data(), cut)) << cut;
  std::vector<uint32_t> longer = code;
  longer.push_back(1);
  EXPECT_FALSE(decodeRuns(out.span(), longer.data(), longer.size()));
  Band other(11);
  EXPECT_FALSE(decodeRuns(other.span(), code.data(), code.size()));
  // A zero count, and a count past the band.
  const uint32_t zero[] = {0x80000000u, 1, 0};
  EXPECT_FALSE(mergeRuns(out.span(), zero, 3, false));
  const uint32_t huge[] = {0x7fffffffu, 1, 2};
  EXPECT_FALSE(mergeRuns(out.span(), huge, 3, false));
}

}  // namespace
