// Ordered fragments (docs/architecture.md): draws with blending, the alpha test or the stencil
// test are shaded in submission order among the deferred ones. On primitives OSMesa does not
// have -- sphere impostors lit per pixel, spheres coloured by a shared interpolator -- beside
// triangles: blending with (GL_ONE, GL_ZERO), an alpha test that passes everything and a
// stencil test that does must draw exactly what deferred shading draws (the ordered path
// shades the same colours, in an order that gives the same visibility); and a translucent scene
// must be byte-identical for any thread count, with native code and with the interpreter.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <random>
#include <vector>

#include "compiler/native/native_cache.h"

namespace {

// Pixel programs compiled on their first block (the default waits for a thousand), so that
// native code draws this small scene; put back afterwards.
struct NativeOnFirstBlock {
  uint64_t saved = pf::NativeProgramCache::instance().threshold();
  NativeOnFirstBlock() { pf::NativeProgramCache::instance().setThreshold(0); }
  ~NativeOnFirstBlock() { pf::NativeProgramCache::instance().setThreshold(saved); }
};

constexpr int kW = 180, kH = 140;

const char* kEyeRgb =
    "interpolator eye_rgb(float scale) {\n"
    "  interpolator_return(color(0.5 + P.x * scale, 0.5 + P.y * scale, -P.z * 0.1, 0.6));\n"
    "}\n";

struct Frame {
  std::vector<unsigned char> color;
  std::vector<float> depth;
};

enum class Mode { Deferred, BlendOneZero, AlphaAlways, StencilAlways, Translucent };

// The scene under `mode`'s fragment operations, with `threads` rasterizer threads and pixel
// programs as native code (`native` 1) or on the interpreter (0).
Frame draw(Mode mode, int threads = 1, int native = -1) {
  const int attribs[] = {PF_FORMAT,  GL_RGBA, PF_DEPTH_BITS, 24, PF_STENCIL_BITS, 8, PF_THREADS, threads,
                         native >= 0 ? PF_JIT : 0, native, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  EXPECT_NE(ctx, nullptr);
  Frame f;
  f.color.assign(size_t(kW) * kH * 4, 0);
  pfMakeCurrent(ctx, f.color.data(), GL_UNSIGNED_BYTE, kW, kH);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.8, 0.8, -0.6, 0.6, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.0, 0.0, -6.0);
  pfglEnable(GL_DEPTH_TEST);
  const GLfloat dir[4] = {-0.4f, 0.5f, 0.77f, 0.0f};
  pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
  pfglEnable(GL_LIGHT0);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglClearColor(0.1f, 0.2f, 0.3f, 1.0f);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  switch (mode) {
    case Mode::Deferred: break;
    case Mode::BlendOneZero: pfglEnable(GL_BLEND); pfglBlendFunc(GL_ONE, GL_ZERO); break;
    case Mode::AlphaAlways: pfglEnable(GL_ALPHA_TEST); pfglAlphaFunc(GL_ALWAYS, 0.5f); break;
    case Mode::StencilAlways:
      pfglEnable(GL_STENCIL_TEST);
      pfglStencilFunc(GL_ALWAYS, 1, 0xff);
      pfglStencilOp(GL_INCR, GL_INCR, GL_INCR);
      break;
    case Mode::Translucent: pfglEnable(GL_BLEND); pfglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); break;
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> pos(-3.0f, 3.0f), small(-0.3f, 0.3f), col(0.0f, 1.0f);
  // Triangles lit per vertex, opaque whatever the mode (the mode's draws interleave with them).
  for (int round = 0; round < 3; ++round) {
    const bool mode_draws = round != 1;
    if (!mode_draws) {
      pfglDisable(GL_BLEND);
      pfglDisable(GL_ALPHA_TEST);
      pfglDisable(GL_STENCIL_TEST);
    }
    pfglEnable(GL_LIGHTING);
    pfglBegin(GL_TRIANGLES);
    for (int i = 0; i < 60; ++i) {
      const float x = pos(rng), y = pos(rng), z = pos(rng);
      for (int k = 0; k < 3; ++k) {
        pfglColor4f(col(rng), col(rng), col(rng), 0.3f + 0.6f * col(rng));
        pfglNormal3f(small(rng), small(rng), 1.0f);
        pfglVertex3f(x + 2 * small(rng), y + 2 * small(rng), z + small(rng));
      }
    }
    pfglEnd();
    // Sphere impostors lit per pixel.
    const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
    pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
    for (int i = 0; i < 80; ++i) {
      pfglColor4f(col(rng), col(rng), col(rng), 0.3f + 0.6f * col(rng));
      pfglRastParamfEXT(radius, 0.05f + 0.3f * col(rng));
      pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
      pfglSequencePointEXT();
    }
    pfglEnd();
    pfglDisable(GL_LIGHTING);
    // Spheres coloured by a shared interpolator of their surface point.
    EXPECT_NE(pfglCompilePrimitivesEXT(kEyeRgb), 0u);
    const GLenum sphere = pfglGetPrimitiveEXT("sphere");
    const GLuint rgb = pfglGetInterpolatorEXT("eye_rgb"), scale = pfglGetParamNameEXT("scale");
    pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), sphere, rgb);
    pfglRastParamfEXT(scale, 0.2f);
    pfglBegin(sphere);
    for (int i = 0; i < 6; ++i) {
      pfglRastParamfEXT(radius, 0.4f + 0.3f * col(rng));
      pfglRastParam3fEXT(centre, pos(rng), pos(rng), pos(rng));
      pfglSequencePointEXT();
    }
    pfglEnd();
    if (!mode_draws) {
      if (mode == Mode::BlendOneZero || mode == Mode::Translucent) pfglEnable(GL_BLEND);
      if (mode == Mode::AlphaAlways) pfglEnable(GL_ALPHA_TEST);
      if (mode == Mode::StencilAlways) pfglEnable(GL_STENCIL_TEST);
    }
  }
  EXPECT_EQ(pfglGetError(), GLenum(GL_NO_ERROR));
  pfglFinish();
  GLint w = 0, h = 0, bytes = 0;
  void* data = nullptr;
  EXPECT_TRUE(pfGetDepthBuffer(ctx, &w, &h, &bytes, &data));
  const float* depth = static_cast<const float*>(data);
  f.depth.assign(depth, depth + size_t(kW) * kH);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
  return f;
}

size_t differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  size_t n = 0;
  for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
  return n;
}

TEST(OrderedFragments, PassThroughOperationsDrawWhatDeferredShadingDraws) {
  const Frame deferred = draw(Mode::Deferred);
  size_t drawn = 0;
  for (size_t i = 0; i < deferred.depth.size(); ++i) drawn += deferred.depth[i] < 1.0f;
  ASSERT_GT(drawn, size_t(kW) * kH / 4);  // the scene covers a good part of the frame
  for (Mode mode : {Mode::BlendOneZero, Mode::AlphaAlways, Mode::StencilAlways}) {
    const Frame ordered = draw(mode);
    EXPECT_EQ(differing(deferred.color, ordered.color), 0u) << "mode " << int(mode);
    EXPECT_TRUE(deferred.depth == ordered.depth) << "mode " << int(mode);
  }
}

TEST(OrderedFragments, TranslucentSceneIsTheSameForAnyThreadCountAndExecutor) {
  const NativeOnFirstBlock native_on_first_block;
  const Frame deferred = draw(Mode::Deferred);
  const Frame one = draw(Mode::Translucent, 1, 0);
  EXPECT_GT(differing(deferred.color, one.color), 1000u);  // blending shows
  for (int threads : {2, 3, 8})
    for (int native : {0, 1}) {
      const Frame many = draw(Mode::Translucent, threads, native);
      EXPECT_EQ(differing(one.color, many.color), 0u) << threads << " threads, native " << native;
      EXPECT_TRUE(one.depth == many.depth) << threads << " threads, native " << native;
    }
}

}  // namespace
