// A frame drawn into a fresh context with the renderer's switches set, and the bit-for-bit
// comparison of two frames: for the raster tests that check a renderer feature (coarse depth
// culling, gang blocks) against the same scene drawn without it.
#pragma once

#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <bit>
#include <functional>
#include <vector>

#include "api/src/context_state.h"

namespace pf::test {

struct RenderedFrame {
  std::vector<unsigned char> color;
  std::vector<float> depth;
  FrameStats stats;
};

// A `size`-pixel square RGBA context with a depth buffer and `threads` rasterizer threads;
// `configure` sets its renderer's switches, `scene` draws (and clears: nothing is cleared
// before it); then glFinish, and the colour, depth and work counters are read back.
inline RenderedFrame renderFrame(int size, int threads, const std::function<void(Renderer&)>& configure,
                                 const std::function<void()>& scene) {
  std::vector<unsigned char> px(static_cast<size_t>(size) * size * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  EXPECT_TRUE(ctx && pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, size, size));
  RenderedFrame f;
  if (!ctx) return f;
  configure(ctx->renderer);
  scene();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  f.color = px;
  GLint w, h, bits;
  void* data = nullptr;
  EXPECT_TRUE(pfGetDepthBuffer(ctx, &w, &h, &bits, &data));
  const float* d = static_cast<const float*>(data);
  if (d) f.depth.assign(d, d + static_cast<size_t>(size) * size);
  f.stats = ctx->renderer.stats();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return f;
}

// The same image to the bit (colour bytes, depth bit patterns), from the same lanes committed.
inline void expectIdenticalFrames(const RenderedFrame& a, const RenderedFrame& b) {
  EXPECT_EQ(a.stats.lanes_committed, b.stats.lanes_committed);
  ASSERT_EQ(a.color.size(), b.color.size());
  ASSERT_EQ(a.depth.size(), b.depth.size());
  size_t colour_diff = 0, depth_diff = 0;
  for (size_t i = 0; i < a.color.size(); ++i) colour_diff += a.color[i] != b.color[i];
  for (size_t i = 0; i < a.depth.size(); ++i)
    depth_diff += std::bit_cast<uint32_t>(a.depth[i]) != std::bit_cast<uint32_t>(b.depth[i]);
  EXPECT_EQ(colour_diff, 0u);
  EXPECT_EQ(depth_diff, 0u);
}

}  // namespace pf::test
