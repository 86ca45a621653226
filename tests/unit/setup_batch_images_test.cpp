// Images drawn with and without batched setup (raster/setup_batch.h) -- through the renderer's
// switch and through the API under PF_SETUP_BATCH=0 -- are identical, as are the renderer's
// counters, for 1 and 2 threads: batching changes neither a record nor the binning order.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "compiler/native/native_cache.h"
#include "raster/renderer.h"
#include "setup_batch_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {

struct Frame {
  std::vector<uint8_t> color;
  std::vector<float> depth;
  FrameStats stats;
  SetupBatchCounters batch;
};

// A frame of many instances of several primitives through Renderer::submitInstances (`scale`
// times as many of each).
Frame drawThroughRenderer(bool batching, int threads, int scale = 1) {
  Frame f;
  f.color.assign(static_cast<size_t>(kSize) * kSize * 4, 0);
  f.depth.assign(static_cast<size_t>(kSize) * kSize, 1.0f);
  Renderer r(threads);
  r.setNativeCode(false);  // pixel_instructions counts the interpreter's instructions
  r.setSetupBatching(batching);
  r.setTarget(f.color.data(), f.depth.data(), kSize, kSize);
  const float black[4] = {0, 0, 0, 1};
  r.clear(true, true, black, 1.0f);
  const RasterState state = testState();
  const ChannelLayout layout = ChannelLayout::ofKind(4, InterpKind::PerspectiveLinear);
  ShadeState shade;
  shade.color_slot = 0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0, 1);
  for (const char* name : {"sphere_impostors", "triangles", "sphere", "torus", "ellipsoid", "cylinder", "points"}) {
    const CompiledPrimitive& prim = builtin(name);
    const int n = (std::string(name) == "sphere_impostors" ? 301 : 45) * scale;
    const int count = prim.sequence_points;
    std::vector<uint32_t> params;
    std::vector<float> channels;
    size_t pwords = static_cast<size_t>(prim.paramFloats(count)), vfloats = static_cast<size_t>(count) * 4;
    for (int i = 0; i < n; ++i) {
      std::vector<uint32_t> p = instanceParams(prim, count, rng, unit(rng) < 0.15);
      if (std::string(name) == "sphere_impostors") {
        const size_t radius = static_cast<size_t>(prim.findParam("radius")->offset);
        p[radius] = u(std::bit_cast<float>(p[radius]) * 0.5f);
      }
      params.insert(params.end(), p.begin(), p.end());
      for (size_t c = 0; c < vfloats; ++c) channels.push_back(unit(rng));
    }
    r.submitInstances(prim, n, params.data(), pwords, channels.data(), vfloats, layout, state, shade, count);
  }
  r.flush();
  f.stats = r.stats();
  f.batch = r.setupBatchCounters();
  return f;
}

// The frame set up one by one (`off`) and batched (`on`): the same colours and depths to the
// bit, the same instances killed and binned, the same pixel work.
void expectSameFrame(const Frame& off, const Frame& on, int threads) {
  EXPECT_EQ(off.color, on.color) << threads << " thread(s)";
  EXPECT_TRUE(std::equal(off.depth.begin(), off.depth.end(), on.depth.begin(),
                         [](float a, float b) { return u(a) == u(b); }))
      << threads << " thread(s)";
  EXPECT_EQ(off.stats.instances_killed, on.stats.instances_killed);
  EXPECT_EQ(off.stats.bin_entries, on.stats.bin_entries);
  EXPECT_EQ(off.stats.pixel_instructions, on.stats.pixel_instructions);
}

}  // namespace

TEST(SetupBatch, RendererImagesAndCountersIdenticalWithAndWithoutBatching) {
  for (int threads : {1, 2}) {
    const Frame off = drawThroughRenderer(false, threads), on = drawThroughRenderer(true, threads);
    EXPECT_EQ(off.batch.batches, 0u);
    EXPECT_GT(on.batch.lanes_batched, 300u) << "batching did not happen";
    EXPECT_GT(on.stats.instances_killed, 10u);  // degenerate instances were among them
    EXPECT_GT(on.stats.bin_entries, 100u);
    expectSameFrame(off, on, threads);
    EXPECT_EQ(off.stats.instances_submitted, on.stats.instances_submitted);
    EXPECT_EQ(off.stats.setup_instructions, on.stats.setup_instructions);
    EXPECT_EQ(off.stats.lanes_committed, on.stats.lanes_committed);
  }
}

// Batched setup writes the records straight into the scene's, the killed instances' gaps closed
// as they are binned, in jobs across the threads: thousands of instances, a sixth of them
// degenerate, give the same image and counters with 1, 2 and 3 threads as instances set up one
// by one.
TEST(SetupBatch, ManyInstancesAcrossThreadsAreBinnedAsOneByOne) {
  const Frame off = drawThroughRenderer(false, 1, 24);
  EXPECT_GT(off.stats.instances_killed, 500u);
  for (int threads : {1, 2, 3}) {
    const Frame on = drawThroughRenderer(true, threads, 24);
    EXPECT_GT(on.batch.lanes_batched, 9000u);
    expectSameFrame(off, on, threads);
  }
}

namespace {

// Spheres (some with radius <= 0, some behind the eye) and triangles through the API, in a
// context created under PF_SETUP_BATCH=`batch_env` (null: unset).
std::vector<unsigned char> drawThroughApi(const char* batch_env, int threads) {
  if (batch_env) {
    setenv("PF_SETUP_BATCH", batch_env, 1);
  } else {
    unsetenv("PF_SETUP_BATCH");
  }
  std::vector<unsigned char> px(static_cast<size_t>(kSize) * kSize * 4);
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_THREADS, threads, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  unsetenv("PF_SETUP_BATCH");
  EXPECT_TRUE(ctx && pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, kSize, kSize));
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.1, -0.2, -6);
  pfglRotated(40.0, 0.3, 1, 0.2);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglEnable(GL_LIGHTING);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_COLOR_MATERIAL);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0, 1), sym(-1, 1);
  const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
  for (int i = 0; i < 700; ++i) {
    pfglColor3f(unit(rng), unit(rng), unit(rng));
    const int kind = static_cast<int>(rng() % 20);
    float r = 0.03f + 0.1f * unit(rng);
    if (kind == 0) r = -r;
    if (kind == 1) r = 0;
    if (kind == 2) r = std::numeric_limits<float>::quiet_NaN();
    pfglRastParamfEXT(radius, r);
    const float z = kind == 3 ? 7.0f : sym(rng) * 2;  // kind 3: behind the eye
    pfglRastParam3fEXT(centre, sym(rng) * 2, sym(rng) * 2, z);
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglDisable(GL_LIGHTING);
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 3 * 150; ++i) {
    pfglColor3f(unit(rng), unit(rng), unit(rng));
    pfglVertex3f(sym(rng) * 2, sym(rng) * 2, i % 97 == 0 ? 9.0f : sym(rng) * 2);
  }
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return px;
}

}  // namespace

TEST(SetupBatch, ApiImagesIdenticalWithAndWithoutBatching) {
  for (int threads : {1, 2}) {
    const std::vector<unsigned char> off = drawThroughApi("0", threads), on = drawThroughApi(nullptr, threads);
    int drawn = 0;
    for (size_t i = 0; i < on.size(); i += 4) drawn += on[i] || on[i + 1] || on[i + 2];
    EXPECT_GT(drawn, kSize * kSize / 4);
    EXPECT_TRUE(off == on) << threads << " thread(s): images differ";
  }
}

// The same scene with the batches' setup in native code from the first batch: the image of the
// scalar setup, bit for bit.
TEST(SetupBatch, ApiImagesIdenticalWithSetupInNativeCode) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache& cache = NativeProgramCache::instance();
  const uint64_t compiled = cache.stats().compiled, saved = cache.setupThreshold();
  cache.setSetupThreshold(0);
  const std::vector<unsigned char> native = drawThroughApi(nullptr, 2);
  cache.setSetupThreshold(saved);
  EXPECT_GT(cache.stats().compiled, compiled) << "no setup program was compiled";
  EXPECT_TRUE(drawThroughApi("0", 2) == native) << "images differ";
}

