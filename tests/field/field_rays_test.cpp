// FieldRays::blockRays (a block's 64 rays as vector loops) against ray() one pixel at a time, bit
// for bit: perspective and orthographic projections, rays parallel to a box face inside and
// outside it, rays missing the box, and matrices with zeros, infinities and NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "raster/field/field_rays.h"

namespace pf::field {
namespace {

void expectBlockRaysAreRays(const FieldRays& fr, int bx, int by, const char* what) {
  PixelRay block[64];
  fr.blockRays(bx, by, block);
  for (int i = 0; i < 64; ++i) {
    const PixelRay one = fr.ray(bx + i % 8 + 0.5, by + i / 8 + 0.5);
    ASSERT_EQ(std::memcmp(&one, &block[i], sizeof(PixelRay)), 0)
        << what << ": block (" << bx << ", " << by << "), lane " << i << ": entry " << one.entry << " / "
        << block[i].entry << ", exit " << one.exit << " / " << block[i].exit;
  }
}

// An orthographic view down -z of [-1, 1]^3 in a w x h window: window (x, y, z) to object.
FieldRays ortho(int w, int h) {
  FieldRays fr;
  fr.window_to_object = {2.0 / w, 0, 0, 0, 0, 2.0 / h, 0, 0, 0, 0, -2.0, 0, -1, -1, 1, 1};
  fr.box_min = {-1, -1, -1};
  fr.box_max = {1, 1, 1};
  return fr;
}

TEST(FieldRays, BlockRaysAreRaysBitForBit) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int empty = 0, clipped = 0;
  for (int trial = 0; trial < 400; ++trial) {
    FieldRays fr = ortho(256, 256);
    if (trial % 4 != 0) {  // a random projective map: perspective rays, some behind or degenerate
      for (double& v : fr.window_to_object) v = u(rng) * (trial % 3 == 0 ? 0.01 : 1.0);
      if (trial % 5 == 0) fr.window_to_object[3] = fr.window_to_object[7] = 0.0;  // affine
    }
    if (trial % 7 == 0) {  // rays parallel to some faces: a zero column for x or y
      fr.window_to_object[trial % 2] = fr.window_to_object[4 + trial % 2] = 0.0;
      fr.window_to_object[8 + trial % 2] = 0.0;
    }
    if (trial % 11 == 0) fr.window_to_object[trial % 16] = std::numeric_limits<double>::infinity();
    if (trial % 13 == 0) fr.window_to_object[trial % 16] = std::nan("");
    for (int k = 0; k < 3; ++k) {
      const double a = u(rng), b = u(rng);
      fr.box_min[k] = std::min(a, b);
      fr.box_max[k] = std::max(a, b) + (trial % 17 == 0 ? 0.0 : 0.1);
    }
    fr.depth_near = trial % 6 == 0 ? 0.25 : 0.0;
    fr.depth_far = 1.0;
    const int bx = 8 * static_cast<int>(rng() % 32), by = 8 * static_cast<int>(rng() % 32);
    expectBlockRaysAreRays(fr, bx, by, "random");
    PixelRay block[64];
    fr.blockRays(bx, by, block);
    for (const PixelRay& r : block) {
      empty += r.empty();
      clipped += !r.empty() && (r.entry > 0.0 || r.exit < 1.0);
    }
  }
  EXPECT_GT(empty, 1000);    // the cases above really miss the box ...
  EXPECT_GT(clipped, 500);   // ... and really clip
  // An orthographic view whose rays lie in the planes of the box's faces and outside them.
  FieldRays fr = ortho(64, 64);
  fr.box_min = {-0.5, -1.0, -1.0};
  fr.box_max = {0.5, 1.0, 1.0};
  for (int by = 0; by < 64; by += 8)
    for (int bx = 0; bx < 64; bx += 8) expectBlockRaysAreRays(fr, bx, by, "ortho");
}

}  // namespace
}  // namespace pf::field
