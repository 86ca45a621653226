// Gang blocks (raster/gang_block.h): the pixels of several small instances in one block, each
// lane reading its own instance's uniforms. The image must be the same to the bit as with each
// instance packed alone (Renderer::setGangBlocks(false)) -- where instances overlap (a block's
// lanes test the depth buffer at once, so two instances of one pixel must not share a block),
// and where a program branches on a uniform that instances disagree on (they must not share a
// block either: a block takes one branch).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <functional>
#include <random>
#include <vector>

#include "rendered_frame.h"

namespace {

constexpr int kSize = 128;

using Frame = pf::test::RenderedFrame;

// Draws `scene` (which clears) into a fresh context (2 threads, `size` pixels square) with
// gang blocks and coarse depth culling on or off.
Frame draw(bool gangs, const std::function<void()>& scene, bool cull = true, int size = kSize) {
  return pf::test::renderFrame(size, 2,
                               [&](pf::Renderer& r) {
                                 r.setGangBlocks(gangs);
                                 r.setDepthCulling(cull);
                               },
                               scene);
}

void expectSame(const Frame& ganged, const Frame& alone) {
  EXPECT_EQ(alone.stats.blocks_ganged, 0u);
  EXPECT_GT(ganged.stats.blocks_ganged, 0u);
  EXPECT_LT(ganged.stats.blocks_run, alone.stats.blocks_run);
  pf::test::expectIdenticalFrames(ganged, alone);
}

void perspective(double distance = 4.0) {
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.0, 0.0, -distance);
  pfglEnable(GL_DEPTH_TEST);
}

}  // namespace

TEST(GangBlocks, AnInstanceNeverSharesABlockWithOneItOverlaps) {
  // Pairs of small impostors at one place, the first of each pair nearer: the first must win.
  // Sharing a block, both would pass the depth test against the depth before them and the
  // later lane's commit would win.
  auto scene = [] {
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
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

// Instances whose every pixel the depth filter leaves out join a gang block without a lane;
// each must take the place of the one before it, not pile up past the block's 64 members
// (they wrote past the member arrays and crashed). Many disjoint small spheres in one tile
// behind a depth cleared to 0 under GL_LESS (nothing passes), and a lattice drawn front to
// back (the back layer hidden), against the same scenes unculled.
TEST(GangBlocks, MembersWithEveryPixelCulledDoNotPileUp) {
  auto behind_clear = [] {
    pfglClearDepth(0.0);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    perspective();
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) {
        pfglColor3f(1, 0, 0);
        pfglRastParamfEXT(radius, 0.06f);
        pfglRastParam3fEXT(centre, -1.8f + 0.3f * i, -1.8f + 0.3f * j, 0.0f);
        pfglSequencePointEXT();
      }
    pfglEnd();
  };
  const Frame none = draw(true, behind_clear, true, 64);
  EXPECT_GT(none.stats.pixels_depth_culled, 500u);
  pf::test::expectIdenticalFrames(none, draw(true, behind_clear, false, 64));
  auto lattice = [] {
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    perspective();
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
    for (int layer = 0; layer < 2; ++layer)
      for (int j = 0; j < 9; ++j)
        for (int i = 0; i < 9; ++i) {
          pfglColor3f(static_cast<float>(layer), static_cast<float>(1 - layer), 0.0f);
          pfglRastParamfEXT(radius, layer == 0 ? 0.16f : 0.04f);
          pfglRastParam3fEXT(centre, -1.68f + 0.42f * i, -1.68f + 0.42f * j, layer == 0 ? 0.3f : 0.0f);
          pfglSequencePointEXT();
        }
    pfglEnd();
  };
  const Frame front = draw(true, lattice, true, 64);
  EXPECT_GT(front.stats.pixels_depth_culled, 0u);
  pf::test::expectIdenticalFrames(front, draw(true, lattice, false, 64));
}
