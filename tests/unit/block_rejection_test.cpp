// Hierarchical block rejection and acceptance (raster/block_rejection.h): sound -- a region it
// rejects is one where the program draws no pixel, one it accepts one where it draws every
// pixel, checked against running the program on every pixel, for edge tests, discriminants,
// divisions, NaN and infinite parameters -- and invisible: images and depth buffers with and
// without it are bit-identical for triangles, spheres, quadrics and tori (the covered programs
// run there); and it does reject what lies outside a primitive.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <vector>

#include "compile_helpers.h"
#include "gl_context.h"
#include "rejection_probe.h"
#include "setup_batch_helpers.h"
#include "raster/block_rejection.h"

using namespace pf;
using namespace pf::test;

namespace {

const char* const kProbe = kRejectionProbe;

float pick(std::mt19937& rng) {
  std::uniform_int_distribution<int> special(0, 19);
  std::uniform_real_distribution<float> u(-12.0f, 12.0f);
  switch (special(rng)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -std::numeric_limits<float>::infinity();
    case 3: return 0.0f;
    case 4: return std::round(u(rng)) + 0.5f;  // through pixel centres
    default: return u(rng);
  }
}

}  // namespace

TEST(BlockRejection, RejectsOnlyBlocksWhereNothingIsDrawn) {
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("probe");
  ASSERT_GE(p.pixel.last_early_retire, 0);
  std::mt19937 rng(11);
  BlockRejection rejection;
  int rejected = 0, empty = 0, accepted = 0, full = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<float> k(8);
    for (float& v : k) v = pick(rng);
    // The instance's uniform record, as the renderer makes it.
    std::vector<uint32_t> params(8), record(SetupExecutor::recordWords(p, 0) + 1);
    for (int i = 0; i < 8; ++i) params[i] = f2u(k[i]);
    ChannelLayout layout = ChannelLayout::ofKind(0, InterpKind::PerspectiveLinear);
    RasterState st;
    SetupExecutor setup;
    const SetupOutput out = setup.run(p, SetupInput{params.data(), nullptr, &layout, &st, 1}, record.data());
    if (out.killed) continue;
    const BlockRun r = runBlock(p, k, {}, 0, true, 1.0f);  // pixels (0..7, 0..7), both modes
    bool any = false;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) any = any || r.drawn(x, y);
    const RegionVerdict verdict = rejection.verdict(p.pixel, record.data(), st, 0, 0, 8, 8);
    if (verdict == RegionVerdict::Rejected) {
      ++rejected;
      EXPECT_FALSE(any) << "trial " << trial << ": rejected a block the program draws in";
    }
    bool all = true;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) all = all && r.drawn(x, y);
    if (verdict == RegionVerdict::Accepted) {  // the probe's only returns are coverage tests
      ++accepted;
      EXPECT_TRUE(all) << "trial " << trial << ": accepted a block where the program retires a pixel";
    }
    empty += !any;
    bool finite = true;
    for (float v : k) finite = finite && std::isfinite(v);
    full += all && finite;
  }
  // Most empty blocks are recognised (the conditions are the evaluator's strong suit), and most
  // full ones among those with finite parameters (an infinite or NaN one makes the ranges
  // unknown: never accepted, always safe).
  EXPECT_GT(rejected, empty / 2) << rejected << " of " << empty << " empty blocks rejected";
  EXPECT_GT(accepted, full / 2) << accepted << " of " << full << " full blocks with finite parameters accepted";
}

// The covered program (compiler/covered_program.h) of the triangle: its coverage tests are gone
// (no Retire before its depth test), nothing else is, and its jumps land inside it.
TEST(BlockRejection, TheTrianglesCoveredProgramHasNoCoverageTests) {
  const CompiledPrimitive& tri = builtin("triangles");
  ASSERT_TRUE(tri.pixel.covered);
  const PixelProgram& full = tri.pixel;
  const PixelProgram& covered = *tri.pixel.covered;
  EXPECT_LT(covered.code.size() + 30, full.code.size());
  int retires_before_ztest = 0, ztests = 0, retires = 0;
  for (const Instr& in : covered.code) {
    if (in.op == Op::ZTest) ++ztests;
    if (in.op == Op::Retire) (ztests == 0 ? retires_before_ztest : retires) += 1;
    if (in.op == Op::Jmp || in.op == Op::JmpIfNot || in.op == Op::JmpIfNone || in.op == Op::LoopBack) {
      EXPECT_LE(in.a, covered.code.size());
    }
  }
  EXPECT_EQ(retires_before_ztest, 0);
  EXPECT_EQ(ztests, 1);
  EXPECT_EQ(retires, 1);  // the depth test's
  size_t full_retires = 0;
  for (const Instr& in : full.code) full_retires += in.op == Op::Retire;
  EXPECT_GE(full_retires, 8u);  // three edges for each vertex order, the near/far clip, the depth test
}

// Single pixels on an edge through (or within rounding of) their centre: float rounding decides
// whether the pixel is drawn, so the intervals must be wider than rounding can move a value.
TEST(BlockRejection, EdgesWithinRoundingOfAPixelCentre) {
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("probe");
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  std::uniform_int_distribution<int> pixel(0, 7);
  BlockRejection rejection;
  int decided_by_rounding = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const float a = u(rng), b = u(rng);
    const int px = pixel(rng), py = pixel(rng);
    // c cancels a X + b Y at the pixel's centre as closely as a float can.
    const float cc = static_cast<float>(-(static_cast<double>(a) * (px + 0.5) + static_cast<double>(b) * (py + 0.5)));
    const std::vector<float> k = {a, b, cc, 4.0f, 4.0f, 100.0f, 1000.0f, trial % 2 ? 1.0f : 0.0f};
    std::vector<uint32_t> params(8), record(SetupExecutor::recordWords(p, 0) + 1);
    for (int i = 0; i < 8; ++i) params[i] = f2u(k[i]);
    ChannelLayout layout = ChannelLayout::ofKind(0, InterpKind::PerspectiveLinear);
    RasterState st;
    SetupExecutor setup;
    setup.run(p, SetupInput{params.data(), nullptr, &layout, &st, 1}, record.data());
    const BlockRun r = runBlock(p, k, {}, 0, true, 1.0f);
    const double exact = static_cast<double>(a) * (px + 0.5) + static_cast<double>(b) * (py + 0.5) + cc;
    decided_by_rounding += (exact < 0) == r.drawn(px, py);  // float said otherwise than the reals
    if (rejection.rejects(p.pixel, record.data(), st, px, py, px + 1, py + 1)) {
      EXPECT_FALSE(r.drawn(px, py)) << "trial " << trial << ": pixel (" << px << ", " << py << ") rejected but drawn";
    }
  }
  EXPECT_GT(decided_by_rounding, 10);  // the test does reach the cases it is about
}

namespace {

// Draws a few large triangles and shapes; returns colour and depth.
struct Frame {
  std::vector<unsigned char> color;
  std::vector<float> depth;
};

Frame drawScene() {
  GlContext c(160, 120);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.0, 0.0, -5.0);
  pfglRotated(20, 0.3, 1, 0.1);
  pfglEnable(GL_DEPTH_TEST);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f), col(0.0f, 1.0f);
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 60; ++i) {
    pfglColor3f(col(rng), col(rng), col(rng));
    pfglVertex3f(u(rng), u(rng), u(rng) * 0.5f);
  }
  pfglEnd();
  pfglColor3f(0.9f, 0.5f, 0.2f);
  pfglBegin(pfglGetPrimitiveEXT("sphere"));
  for (int i = 0; i < 6; ++i) {
    pfglRastParamfEXT(pfglGetParamNameEXT("radius"), 0.3f + 0.1f * i);
    pfglRastParam3fEXT(pfglGetParamNameEXT("center"), u(rng), u(rng), u(rng) * 0.3f);
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglBegin(pfglGetPrimitiveEXT("torus"));
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 0.5f, -0.5f, 0.0f);
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), 1.2f);
  pfglRastParamfEXT(pfglGetParamNameEXT("tube_radius"), 0.3f);
  pfglSequencePointEXT();
  pfglEnd();
  pfglBegin(pfglGetPrimitiveEXT("cylinder"));
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), -1.0f, 0.5f, -0.5f);
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), 0.6f);
  pfglRastParamfEXT(pfglGetParamNameEXT("height"), 1.5f);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  Frame f;
  f.color = c.px;
  f.depth.assign(c.depth(), c.depth() + 160 * 120);
  return f;
}

}  // namespace

TEST(BlockRejection, ImagesAreTheSameWithAndWithout) {
  ::setenv("PF_NO_BLOCK_REJECTION", "1", 1);
  const Frame without = drawScene();
  ::unsetenv("PF_NO_BLOCK_REJECTION");
  const Frame with = drawScene();
  ASSERT_EQ(with.color.size(), without.color.size());
  EXPECT_TRUE(with.color == without.color) << "colour differs";
  bool depth_same = true;
  for (size_t i = 0; i < with.depth.size(); ++i)
    depth_same = depth_same && std::bit_cast<uint32_t>(with.depth[i]) == std::bit_cast<uint32_t>(without.depth[i]);
  EXPECT_TRUE(depth_same) << "depth differs";
  size_t drawn = 0;
  for (size_t i = 0; i < with.depth.size(); ++i) drawn += with.depth[i] < 1.0f;
  EXPECT_GT(drawn, with.depth.size() / 4);  // the scene is not empty
}

// A half-screen triangle: every 32x32 region wholly on the other side of its long edge is
// rejected; the regions it covers are not.
TEST(BlockRejection, RejectsRegionsOutsideATriangle) {
  Compiled c = compile(
      "primitive half(varying float X, Y; inout varying float Z) {\n"
      "  if (X + Y > 128.0) return;\n  Z = 0.5;\n}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("half");
  std::vector<uint32_t> record(SetupExecutor::recordWords(p, 0) + 1);
  ChannelLayout layout = ChannelLayout::ofKind(0, InterpKind::PerspectiveLinear);
  RasterState st;
  SetupExecutor setup;
  setup.run(p, SetupInput{nullptr, nullptr, &layout, &st, 1}, record.data());
  BlockRejection rejection;
  for (int y = 0; y < 256; y += 32)
    for (int x = 0; x < 256; x += 32) {
      const bool outside = x + 0.5 + y + 0.5 > 128.0;  // the region's nearest pixel centre is out
      EXPECT_EQ(rejection.rejects(p.pixel, record.data(), st, x, y, x + 32, y + 32), outside) << x << ", " << y;
    }
}
