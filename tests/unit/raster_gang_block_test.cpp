// Gang blocks (raster/gang_block.h): the pixels of several small instances in one block, each
// lane reading its own instance's uniforms. The image must be the same to the bit as with each
// instance packed alone (Renderer::setGangBlocks(false)) -- where instances overlap (a block's
// lanes test the depth buffer at once, so two instances of one pixel must not share a block),
// and where a program branches on a uniform that instances disagree on (they must not share a
// block either: a block takes one branch).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <bit>
#include <functional>
#include <random>
#include <vector>

#include "api/src/context_state.h"

namespace {

constexpr int kSize = 128;

struct Frame {
  std::vector<unsigned char> color;
  std::vector<float> depth;
  pf::FrameStats stats;
};

// Draws `scene` into a fresh context (2 threads) with gang blocks on or off.
Frame draw(bool gangs, const std::function<void()>& scene) {
  std::vector<unsigned char> px(static_cast<size_t>(kSize) * kSize * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 2, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  EXPECT_TRUE(ctx && pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  ctx->renderer.setGangBlocks(gangs);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  scene();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  Frame f;
  f.color = px;
  GLint w, h, bits;
  void* data = nullptr;
  EXPECT_TRUE(pfGetDepthBuffer(ctx, &w, &h, &bits, &data));
  const float* d = static_cast<const float*>(data);
  f.depth.assign(d, d + kSize * kSize);
  f.stats = ctx->renderer.stats();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return f;
}

void expectSame(const Frame& ganged, const Frame& alone) {
  EXPECT_EQ(alone.stats.blocks_ganged, 0u);
  EXPECT_GT(ganged.stats.blocks_ganged, 0u);
  EXPECT_LT(ganged.stats.blocks_run, alone.stats.blocks_run);
  EXPECT_EQ(ganged.stats.lanes_committed, alone.stats.lanes_committed);
  size_t colour_diff = 0, depth_diff = 0;
  for (size_t i = 0; i < alone.color.size(); ++i) colour_diff += ganged.color[i] != alone.color[i];
  for (size_t i = 0; i < alone.depth.size(); ++i)
    depth_diff += std::bit_cast<uint32_t>(ganged.depth[i]) != std::bit_cast<uint32_t>(alone.depth[i]);
  EXPECT_EQ(colour_diff, 0u);
  EXPECT_EQ(depth_diff, 0u);
}

void perspective() {
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.0, 0.0, -4.0);
  pfglEnable(GL_DEPTH_TEST);
}

}  // namespace

TEST(GangBlocks, AnInstanceNeverSharesABlockWithOneItOverlaps) {
  // Pairs of small impostors at one place, the first of each pair nearer: the first must win.
  // Sharing a block, both would pass the depth test against the depth before them and the
  // later lane's commit would win.
  auto scene = [] {
    perspective();
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f), u(0.0f, 1.0f);
    pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
    for (int i = 0; i < 1500; ++i) {
      const float x = pos(rng), y = pos(rng), z = pos(rng), r = 0.01f + 0.02f * u(rng);
      pfglColor3f(1.0f, u(rng), 0.0f);
      pfglRastParamfEXT(radius, r);
      pfglRastParam3fEXT(centre, x, y, z);
      pfglSequencePointEXT();
      pfglColor3f(0.0f, u(rng), 1.0f);
      pfglRastParamfEXT(radius, r * 1.2f);
      pfglRastParam3fEXT(centre, x, y, z - 0.05f);
      pfglSequencePointEXT();
    }
    pfglEnd();
  };
  const Frame ganged = draw(true, scene), alone = draw(false, scene);
  expectSame(ganged, alone);
  // The nearer (red) spheres show: more red pixels than blue ones (the blue rims show too).
  size_t red = 0, blue = 0;
  for (size_t i = 0; i < ganged.color.size(); i += 4) {
    red += ganged.color[i] == 255;
    blue += ganged.color[i + 2] == 255;
  }
  EXPECT_GT(red, blue);
}

TEST(GangBlocks, InstancesThatDisagreeOnABranchNeverShareABlock) {
  // A disc whose depth bulges towards or away from the viewer as a uniform parameter says: the
  // pixel program jumps on it (PixelProgram::branch_slots), so discs of the two kinds must run
  // in blocks of their own kind. They alternate, overlapping often, under GL_LESS.
  const char* kDisc =
      "primitive tinted_disc(point center[1]; float radius[1]; float mode[1]; interpolator_data interp_data[1];\n"
      "                      varying float X, Y; inout varying float Z)\n"
      "{\n"
      "    point w = screen(center[0]);\n"
      "    float cx = w.x / w.w;\n"
      "    float cy = w.y / w.w;\n"
      "    float cz = w.z / w.w;\n"
      "    float r = radius[0];\n"
      "    bound(cx - r, cy - r, cx + r, cy + r);\n"
      "    float dx = X - cx;\n"
      "    float dy = Y - cy;\n"
      "    float d2 = dx * dx + dy * dy;\n"
      "    if (d2 > r * r) return;\n"
      "    float z = cz;\n"
      "    if (mode[0] > 0.5) {\n"
      "        z = cz - 0.05 * d2 / (r * r);\n"
      "    } else {\n"
      "        z = cz + 0.05 * d2 / (r * r);\n"
      "    }\n"
      "    if (!ztest(z)) return;\n"
      "    Z = z;\n"
      "    interpolation {\n"
      "    perspective_linear:\n"
      "    linear:\n"
      "        interpolator_return(interp_data[0]);\n"
      "    default:\n"
      "        interpolator_return;\n"
      "    }\n"
      "}\n";
  auto scene = [kDisc] {
    ASSERT_NE(pfglCompilePrimitivesEXT(kDisc), 0u);
    const GLenum disc = pfglGetPrimitiveEXT("tinted_disc");
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius"),
                 mode = pfglGetParamNameEXT("mode");
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> pos(-0.9f, 0.9f), u(0.0f, 1.0f);
    pfglEnable(GL_DEPTH_TEST);
    pfglBegin(disc);
    for (int i = 0; i < 3000; ++i) {
      pfglColor3f(u(rng), u(rng), u(rng));
      pfglRastParamfEXT(radius, 1.5f + 4.0f * u(rng));
      pfglRastParamfEXT(mode, static_cast<float>(i % 2));
      pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
      pfglSequencePointEXT();
    }
    pfglEnd();
  };
  expectSame(draw(true, scene), draw(false, scene));
}
