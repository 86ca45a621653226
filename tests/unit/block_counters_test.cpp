// The renderer's block counters (raster/renderer.h, FrameStats; pfrender --stats): a triangle
// covering the whole framebuffer runs every block and covers every one it runs; a triangle of
// a pixel or two covers none; the counts are those of the geometry, for 1 and 2 threads.
#include <gtest/gtest.h>

#include <vector>

#include "raster/renderer.h"
#include "setup_batch_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {

// One `triangles` instance with clip-space vertices (x, y) (z = 0, w = 1), flat grey, into a
// kSize x kSize framebuffer with identity transforms.
FrameStats drawTriangle(const float xy[6], int threads) {
  std::vector<uint8_t> color(static_cast<size_t>(kSize) * kSize * 4, 0);
  std::vector<float> depth(static_cast<size_t>(kSize) * kSize, 1.0f);
  Renderer r(threads);
  r.setTarget(color.data(), depth.data(), kSize, kSize);
  const float black[4] = {0, 0, 0, 1};
  r.clear(true, true, black, 1.0f);
  RasterState state;
  state.vp_scale_x = state.vp_offset_x = state.vp_scale_y = state.vp_offset_y = kSize / 2.0f;
  state.vp_x1 = state.vp_y1 = kSize;
  state.depth_test = true;
  const CompiledPrimitive& prim = builtin("triangles");
  const ParamInfo* vertex = prim.findParam("vertex");
  std::vector<uint32_t> params(static_cast<size_t>(prim.paramFloats(3)), 0u);
  for (int i = 0; i < 3; ++i) {
    const size_t at = static_cast<size_t>(prim.paramOffset(*vertex, 3, i));
    params[at] = u(xy[2 * i]);
    params[at + 1] = u(xy[2 * i + 1]);
    params[at + 2] = u(0.0f);
    params[at + 3] = u(1.0f);
  }
  const ChannelLayout layout = ChannelLayout::ofKind(4, InterpKind::PerspectiveLinear);
  const std::vector<float> channels(12, 0.5f);
  ShadeState shade;
  shade.color_slot = 0;
  r.submitInstances(prim, 1, params.data(), params.size(), channels.data(), 12, layout, state, shade, 3);
  r.flush();
  return r.stats();
}

}  // namespace

TEST(BlockCounters, CoveredBlocksAreThoseEveryLaneOfWhichIsDrawn) {
  for (int threads : {1, 2}) {
    // Far beyond [-1, 1]^2 on every side: the whole framebuffer, (kSize / 8)^2 blocks.
    const float whole[6] = {-3.0f, -3.0f, 5.0f, -3.0f, -3.0f, 5.0f};
    const FrameStats w = drawTriangle(whole, threads);
    const uint64_t blocks = static_cast<uint64_t>(kSize / 8) * (kSize / 8);
    EXPECT_EQ(w.blocks_run + w.blocks_rejected, blocks) << threads;
    EXPECT_EQ(w.blocks_covered, w.blocks_run) << threads;
    // Every 32x32 region is inside all three edges: every block runs the covered program.
    EXPECT_EQ(w.blocks_accepted, w.blocks_run) << threads;
    // Every tile runs; each used the G-buffer of the layout's 4 colour channels plus the ids.
    const uint64_t tiles = static_cast<uint64_t>((kSize + 63) / 64) * ((kSize + 63) / 64);
    EXPECT_EQ(w.tiles_run, tiles) << threads;
    EXPECT_EQ(w.tiles_skipped, 0u) << threads;
    EXPECT_EQ(w.gbuffer_bytes, tiles * (4 + 1) * 64 * 64 * 4) << threads;
    EXPECT_EQ(w.lanes_committed, static_cast<uint64_t>(kSize) * kSize) << threads;
    // About two pixels (0.02 of the half-width of 64 pixels is 1.3 pixels on a side).
    const float tiny[6] = {0.1f, 0.1f, 0.12f, 0.1f, 0.1f, 0.12f};
    const FrameStats t = drawTriangle(tiny, threads);
    EXPECT_GE(t.blocks_run, 1u) << threads;
    EXPECT_EQ(t.blocks_covered, 0u) << threads;
    EXPECT_EQ(t.tiles_run, 1u) << threads;
    EXPECT_EQ(t.tiles_skipped, tiles - 1) << threads;
    EXPECT_GE(t.lanes_committed, 1u) << threads;
    EXPECT_LE(t.lanes_committed, 3u) << threads;
  }
}

TEST(BlockCounters, ABoundInsideTheTriangleRunsEveryBlockCovered) {
  // A right triangle whose legs lie on the pixel lines x = 3 and y = 3 and whose hypotenuse
  // passes far outside the framebuffer: its bound within each tile is inside all three edges,
  // and the blocks the bound cuts (columns and rows 0-2 missing) run the covered program too --
  // judged with the bound as a whole, not as 32x32 regions of which pixels 0-2 are outside.
  const float at = 3.0f / (kSize / 2.0f) - 1.0f, far = at + 6.0f;
  const float corner[6] = {at, at, far, at, at, far};
  const uint64_t blocks = static_cast<uint64_t>(kSize / 8) * (kSize / 8);
  for (int threads : {1, 2}) {
    const FrameStats s = drawTriangle(corner, threads);
    EXPECT_EQ(s.blocks_run, blocks) << threads;
    EXPECT_EQ(s.blocks_rejected, 0u) << threads;
    EXPECT_EQ(s.blocks_accepted, s.blocks_run) << threads;
    EXPECT_EQ(s.blocks_covered, static_cast<uint64_t>(kSize / 8 - 1) * (kSize / 8 - 1)) << threads;
    EXPECT_EQ(s.lanes_committed, static_cast<uint64_t>(kSize - 3) * (kSize - 3)) << threads;
  }
}
