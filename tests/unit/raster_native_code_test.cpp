// Native pixel programs (compiler/native/) as the rasterizer uses them: the comparison with the
// interpreter catches a planted miscompile; the process-wide cache compiles a program once for
// any number of contexts; a primitive recompiled under the same name draws its new code in new
// draws while draws recorded before still draw the old; blocks decided by native code's walk
// over a region's blocks draw what the interpreter draws.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <bit>
#include <cmath>
#include <functional>
#include <vector>

#include "api/src/context_state.h"
#include "compile_helpers.h"
#include "compiler/native/native_cache.h"
#include "compiler/native/pixel_codegen.h"

using namespace pf;
using namespace pf::test;

namespace {

// A disc whose pixels take one value or another by a varying if (a merge value), drawn
// perspective-correctly into 2 channels.
const char* kShadedDisc = R"(
primitive shaded_disc(float k[1][3]; interpolator_data d[1]; varying float X, Y; inout varying float Z) {
    float dx = X - k[0][0];
    float dy = Y - k[0][1];
    if (dx * dx + dy * dy > k[0][2]) return;
    float shade = 0.25;
    if (dx > 0) shade = 0.75;
    if (!ztest(shade)) return;
    Z = shade;
    interpolation {
    perspective_linear: interpolator_return(d[0] * shade);
    default: interpolator_return;
    }
}
)";

struct Drawn {
  std::vector<float> depth, channels;
  std::vector<uint32_t> ids;
  uint64_t native_blocks = 0;
};

// One 8x8 block of the disc at (2.5, 4.5), radius^2 9, through the interpreter or native code.
// (Its two shades meet between columns 2 and 3, inside a group of four lanes: with the split
// at a multiple of four, SSE2 code -- a branch per four lanes -- drew a dropped mask right.)
Drawn drawDisc(const CompiledPrimitive& prim, bool native) {
  const ChannelLayout layout = ChannelLayout::ofKind(2, InterpKind::PerspectiveLinear);
  RasterState st;
  st.vp_scale_x = st.vp_offset_x = st.vp_scale_y = st.vp_offset_y = 4;
  st.vp_x1 = st.vp_y1 = 8;
  st.depth_test = true;
  const std::vector<float> k = {2.5f, 4.5f, 9.0f};
  std::vector<uint32_t> params;
  for (float v : k) params.push_back(std::bit_cast<uint32_t>(v));
  const std::vector<float> channels = {2.0f, 4.0f};
  std::vector<uint32_t> record(SetupExecutor::recordWords(prim, 2) + 1);
  SetupExecutor setup;
  EXPECT_FALSE(setup.run(prim, SetupInput{params.data(), channels.data(), &layout, &st, 1}, record.data()).killed);
  Drawn d;
  d.depth.assign(64, 1.0f);
  d.ids.assign(64 * 64, 0u);
  d.channels.assign(2 * 4096, 0.0f);
  std::vector<float*> planes = {d.channels.data(), d.channels.data() + 4096};
  BlockTarget t;
  t.depth = d.depth.data();
  t.depth_stride = 8;
  t.shade_ids = d.ids.data();
  t.slots = planes.data();
  PixelExecutor ex;
  ex.use_native = native;
  ex.runBlock(prim, record.data(), layout, st, 1, 0, 0, ~0ull, t);
  d.native_blocks = ex.counters.blocks_native;
  return d;
}

// Depth entries, shading ids and channel values that differ.
size_t differences(const Drawn& a, const Drawn& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.depth.size(); ++i) n += std::bit_cast<uint32_t>(a.depth[i]) != std::bit_cast<uint32_t>(b.depth[i]);
  for (size_t i = 0; i < a.ids.size(); ++i) n += a.ids[i] != b.ids[i];
  for (size_t i = 0; i < a.channels.size(); ++i)
    n += std::bit_cast<uint32_t>(a.channels[i]) != std::bit_cast<uint32_t>(b.channels[i]);
  return n;
}

struct FaultPlanted {
  explicit FaultPlanted(NativeFault f) { setNativeFaultForTesting(f); }
  ~FaultPlanted() { setNativeFaultForTesting(NativeFault::None); }
};

}  // namespace

TEST(NativeCode, APlantedMiscompileIsCaught) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setThreshold(0);
  Compiled c = compile(kShadedDisc);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& prim = *c.find("shaded_disc");
  const Drawn interpreted = drawDisc(prim, false);
  const Drawn native = drawDisc(prim, true);
  EXPECT_EQ(native.native_blocks, 1u);
  EXPECT_EQ(differences(interpreted, native), 0u);
  for (NativeFault fault : {NativeFault::MergeWithoutMask, NativeFault::CommitWithoutMask}) {
    const FaultPlanted planted(fault);
    const Drawn wrong = drawDisc(prim, true);
    EXPECT_EQ(wrong.native_blocks, 1u);
    EXPECT_GT(differences(interpreted, wrong), 0u) << "fault " << static_cast<int>(fault) << " went unnoticed";
  }
  // The faulty functions were keyed apart: the correct one is still what runs.
  EXPECT_EQ(differences(interpreted, drawDisc(prim, true)), 0u);
}

namespace {

struct Context {
  std::vector<unsigned char> pixels = std::vector<unsigned char>(64 * 64 * 4);
  PFcontext ctx;
  explicit Context(int native) {
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, 1, PF_JIT, native, 0};
    ctx = pfCreateContextAttribs(attribs);
    EXPECT_TRUE(ctx && pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 64, 64));
    pfglMatrixMode(GL_PROJECTION);
    pfglOrtho(0, 64, 0, 64, -1, 1);
    pfglEnable(GL_DEPTH_TEST);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  ~Context() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

void drawTriangles() {
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 6; ++i) {
    pfglColor3f(0.1f * i, 0.5f, 1.0f - 0.1f * i);
    pfglVertex2f(2.0f + 9 * i, 3.0f);
    pfglVertex2f(60.0f - 5 * i, 10.0f + 7 * i);
    pfglVertex2f(5.0f + 3 * i, 61.0f - 2 * i);
  }
  pfglEnd();
}

}  // namespace

TEST(NativeCode, TwoContextsCompileOnce) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setThreshold(0);
  // A primitive of this test's own (its depth is nobody else's), so that the first context's
  // compiles are its own whatever other tests of this process drew before.
  const char* const source =
      "primitive left_of(point vertex[1]; inout varying float Z) {\n"
      "  if (X > screen(vertex[0]).x) return;\n"
      "  if (!ztest(0.171875)) return;\n"
      "  Z = 0.171875;\n"
      "}\n";
  uint64_t first_compiles = 0;
  std::vector<unsigned char> first_image;
  for (int round = 0; round < 2; ++round) {
    const uint64_t before = NativeProgramCache::instance().stats().compiled;
    Context c(1);
    ASSERT_NE(pfglCompilePrimitivesEXT(source), 0u);
    pfglBegin(pfglGetPrimitiveEXT("left_of"));
    pfglVertex2f(30.0f, 1.0f);
    pfglEnd();
    drawTriangles();
    pfglFinish();
    EXPECT_GT(c.ctx->renderer.stats().blocks_native, 0u);
    const uint64_t compiled = NativeProgramCache::instance().stats().compiled - before;
    if (round == 0) {
      first_compiles = compiled;
      first_image = c.pixels;
      EXPECT_GT(compiled, 0u) << "the first context compiled nothing";
    } else {
      EXPECT_EQ(compiled, 0u) << "the second context compiled again what the first had (" << first_compiles << ")";
      EXPECT_EQ(c.pixels, first_image);
    }
  }
}

TEST(NativeCode, ARecompiledPrimitiveDrawsItsNewCodeAfterPendingDrawsOfTheOld) {
  NativeProgramCache::instance().setThreshold(0);
  // Version 1 writes depth 0.25 left of its vertex, version 2 depth 0.75: both are drawn in one
  // frame, the first instance before the recompile, the second after.
  auto version = [](float z) {
    return "primitive strip(point vertex[1]; inout varying float Z) {\n"
           "  if (X > screen(vertex[0]).x) return;\n"
           "  if (!ztest(" + std::to_string(z) + ")) return;\n"
           "  Z = " + std::to_string(z) + ";\n"
           "}\n";
  };
  std::vector<std::vector<float>> depths;
  for (int native : {0, 1}) {
    Context c(native);
    pfglDepthFunc(GL_ALWAYS);
    ASSERT_NE(pfglCompilePrimitivesEXT(version(0.25f).c_str()), 0u);
    pfglBegin(pfglGetPrimitiveEXT("strip"));
    pfglVertex2f(40.0f, 1.0f);
    pfglEnd();
    ASSERT_NE(pfglCompilePrimitivesEXT(version(0.75f).c_str()), 0u);
    pfglBegin(pfglGetPrimitiveEXT("strip"));
    pfglVertex2f(20.0f, 1.0f);
    pfglEnd();
    GLint w, h, b;
    void* d;
    ASSERT_TRUE(pfGetDepthBuffer(c.ctx, &w, &h, &b, &d));
    const float* depth = static_cast<const float*>(d);
    depths.emplace_back(depth, depth + 64 * 64);
    if (native && nativeCodeAvailable()) {
      EXPECT_GT(c.ctx->renderer.stats().blocks_native, 0u);
    }
    EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  }
  for (const std::vector<float>& depth : depths)
    for (int x = 0; x < 64; ++x)  // the new version over the old where both draw
      EXPECT_EQ(depth[5 * 64 + x], x + 0.5f <= 20.0f ? 0.75f : x + 0.5f <= 40.0f ? 0.25f : 1.0f) << x;
  EXPECT_TRUE(depths[0] == depths[1]);
}

namespace {

// One frame drawn by `draw` through a context with native code or without, on `threads`
// threads, over a size x size framebuffer under an orthographic pixel projection with depths
// in [-depth, depth]: its colours, depths and work counters.
struct Frame {
  std::vector<unsigned char> pixels;
  std::vector<float> depth;
  FrameStats stats;
};

Frame drawFrame(int native, int threads, int size, float depth, const std::function<void()>& draw) {
  Frame out;
  out.pixels.resize(static_cast<size_t>(size) * size * 4);
  out.depth.resize(static_cast<size_t>(size) * size);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, PF_JIT, native, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  EXPECT_TRUE(ctx && pfMakeCurrent(ctx, out.pixels.data(), GL_UNSIGNED_BYTE, size, size));
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(0, size, 0, size, -depth, depth);
  pfglEnable(GL_DEPTH_TEST);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw();
  pfglFinish();
  pfglReadPixels(0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, out.depth.data());
  out.stats = ctx->renderer.stats();
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return out;
}

// `count` large triangles around `centre`, edges at every slope through the regions, crossing
// one another, at depths that cross: triangle i has radius r0 + dr i about a point `spread`
// from the centre, and its corner k depth dz (k - (i % 5) / 2).
void drawCrossingTriangles(int count, float centre, float spread, float r0, float dr, float dz) {
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < count; ++i) {
    const float a = 0.52f * static_cast<float>(i), cx = centre + spread * std::cos(3.0f * a),
                cy = centre + spread * std::sin(3.0f * a), r = r0 + dr * static_cast<float>(i);
    for (int k = 0; k < 3; ++k) {
      const float t = a + 2.0944f * static_cast<float>(k);
      pfglColor3f(0.08f * static_cast<float>(i % 12), 0.3f * static_cast<float>(k), 1.0f - 0.07f * static_cast<float>(i % 12));
      pfglVertex3f(cx + r * std::cos(t), cy + r * std::sin(t),
                   dz * (static_cast<float>(k) - 0.5f * static_cast<float>(i % 5)));
    }
  }
  pfglEnd();
}

// Large triangles over a 256x256 framebuffer, 2 threads.
Frame drawLargeTriangles(int native) {
  return drawFrame(native, 2, 256, 1.0f, [] { drawCrossingTriangles(12, 128.0f, 30.0f, 70.0f, 9.0f, 0.1f); });
}

// Spheres 120-180 pixels across over a 512x512 framebuffer, one thread: their silhouettes'
// regions are undecided, and a walk over such a region's blocks decides about one in four of
// them.
Frame drawSpheres(int native) {
  return drawFrame(native, 1, 512, 200.0f, [] {
    const GLenum sphere = pfglGetPrimitiveEXT("sphere");
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    pfglBegin(sphere);
    for (int i = 0; i < 24; ++i) {
      pfglColor3f(0.04f * static_cast<float>(i), 0.5f, 1.0f - 0.03f * static_cast<float>(i));
      pfglRastParamfEXT(radius, 60.0f + static_cast<float>(i % 5) * 7.5f);
      pfglRastParam3fEXT(centre, 40.0f + static_cast<float>((i * 97) % 432), 40.0f + static_cast<float>((i * 181) % 432),
                         static_cast<float>(i % 7) * 20.0f - 60.0f);
      pfglSequencePointEXT();
    }
    pfglEnd();
  });
}

// Triangles 300-460 pixels across over a 512x512 framebuffer, one thread: along their edges a
// walk over a region's blocks decides most of them.
Frame drawWideTriangles(int native) {
  return drawFrame(native, 1, 512, 200.0f, [] { drawCrossingTriangles(24, 256.0f, 60.0f, 150.0f, 3.5f, 5.0f); });
}

size_t depthDifferences(const Frame& a, const Frame& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.depth.size(); ++i)
    n += std::bit_cast<uint32_t>(a.depth[i]) != std::bit_cast<uint32_t>(b.depth[i]);
  return n;
}

}  // namespace

TEST(NativeCode, RegionsBlocksAreWalkedOnlyForProgramsWhoseWalksDecideMost) {
  // The spheres' first walks over their silhouette regions' blocks decide fewer than half of
  // them, so the frame stops walking them after its probe (PixelExecutor::BlockWalkTally): at
  // most kProbeWalks walks' worth of blocks decided by their own verdicts. The image and the
  // depths are the interpreter's all the same.
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setThreshold(0);
  NativeProgramCache::instance().setWalkThreshold(0);
  const Frame interpreted = drawSpheres(0);
  const Frame native = drawSpheres(1);
  EXPECT_EQ(native.pixels, interpreted.pixels);
  EXPECT_EQ(depthDifferences(native, interpreted), 0u);
  EXPECT_EQ(native.stats.region_walks, PixelExecutor::kProbeWalks) << "the probe's walks, and no more";
  EXPECT_GT(native.stats.blocks_walked, 0u);
  // Triangles' walks decide most of their blocks: they go on walking.
  const Frame triangles_interpreted = drawWideTriangles(0);
  const Frame triangles = drawWideTriangles(1);
  EXPECT_EQ(triangles.pixels, triangles_interpreted.pixels);
  EXPECT_EQ(depthDifferences(triangles, triangles_interpreted), 0u);
  EXPECT_GT(triangles.stats.region_walks, 2 * PixelExecutor::kProbeWalks);
}

TEST(NativeCode, BlocksDecidedByTheirOwnVerdictsDrawWhatTheInterpreterDraws) {
  // Where a 32x32 region's walk is undecided -- along a triangle's edges -- native code walks
  // its 16 blocks at once and runs the covered program or nothing on those it decides: the
  // image and depths must be the interpreter's, which decides by regions only.
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setThreshold(0);
  NativeProgramCache::instance().setWalkThreshold(0);
  const Frame interpreted = drawLargeTriangles(0);
  const Frame native = drawLargeTriangles(1);
  EXPECT_EQ(interpreted.stats.blocks_walked, 0u);
  EXPECT_GT(native.stats.blocks_walked, 50u);
  EXPECT_GT(native.stats.blocks_accepted, interpreted.stats.blocks_accepted);
  EXPECT_LT(native.stats.blocks_run, interpreted.stats.blocks_run);
  EXPECT_EQ(native.pixels, interpreted.pixels);
  EXPECT_EQ(depthDifferences(native, interpreted), 0u);
  // Something was drawn (the comparison is not of two empty frames).
  size_t drawn = 0;
  for (float z : native.depth) drawn += z < 1.0f;
  EXPECT_GT(drawn, 256u * 256u / 3);
}
