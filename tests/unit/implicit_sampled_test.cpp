// Sampled fields through the API (pfglSampledFieldEXT; seed 000 section 3's voxel arrays): a
// ball's signed distance sampled at 8 to 64 samples per axis, drawn by the implicit primitive
// and compared per pixel with the analytic ball -- the depth error shrinks with the resolution,
// trilinear and tricubic (B-spline) alike, and every root-finding method finds the surface --;
// the same bytes for any thread count and on the interpreter; and the API's errors.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "compiler/native/native_cache.h"
#include "frame_capture.h"

namespace {

constexpr int kN = 96;
constexpr double kRadius = 0.7;

// R - |p| (positive inside) at n^3 points spanning [-1, 1]^3.
std::vector<float> ballSamples(int n) {
  std::vector<float> v;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = -1 + 2.0 * i / (n - 1), y = -1 + 2.0 * j / (n - 1), z = -1 + 2.0 * k / (n - 1);
        v.push_back(static_cast<float>(kRadius - std::sqrt(x * x + y * y + z * z)));
      }
  return v;
}

const GLdouble kBox[6] = {-1, -1, -1, 1, 1, 1};

using Image = pf::test::CapturedFrame;

// The ball sampled at n^3, drawn by `method` over [-1, 1]^3 under an orthographic view down -z
// (pixel centres at -1 + (i + 0.5) 2/kN; z = 1 - 2 depth).
Image drawBall(int n, GLenum interpolation, float method, float steps, int threads = 2, int native = 1) {
  pf::test::FrameCapture capture(kN, kN, threads, native);
  const std::vector<float> samples = ballSamples(n);
  const GLuint field = pfglSampledFieldEXT("ball", n, n, n, kBox, interpolation, samples.data());
  EXPECT_NE(field, 0u);
  pf::test::viewUnitBoxFromAbove();
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor3f(1, 1, 1);
  pfglBegin(pfglGetPrimitiveEXT("implicit"));
  pfglRastParamfEXT(pfglGetParamNameEXT("field"), static_cast<float>(field));
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_min"), -1, -1, -1);
  pfglRastParam3fEXT(pfglGetParamNameEXT("box_max"), 1, 1, 1);
  pfglRastParamfEXT(pfglGetParamNameEXT("method"), method);
  pfglRastParamfEXT(pfglGetParamNameEXT("steps"), steps);
  pfglSequencePointEXT();
  pfglEnd();
  return capture.finish();
}

// The largest |z - z_ball| over pixels whose ray meets the ball away from its rim (within 0.85 of
// its radius: an 8^3 grid moves the surface by a few hundredths); coverage must agree there, and
// be empty well outside it.
double maxDepthError(const Image& img) {
  double worst = 0.0;
  int hits = 0;
  for (int py = 0; py < kN; ++py)
    for (int px = 0; px < kN; ++px) {
      const double x = -1 + (px + 0.5) * 2 / kN, y = -1 + (py + 0.5) * 2 / kN, r2 = x * x + y * y;
      const float d = img.depth[static_cast<size_t>(py) * kN + px];
      if (r2 > 0.85 * 0.85 * kRadius * kRadius) {
        if (r2 > 1.15 * 1.15 * kRadius * kRadius) {
          EXPECT_EQ(d, 1.0f) << "pixel " << px << ", " << py << " outside the ball";
        }
        continue;
      }
      EXPECT_LT(d, 1.0f) << "pixel " << px << ", " << py << " on the ball";
      if (!(d < 1.0f)) continue;
      worst = std::max(worst, std::fabs((1.0 - 2.0 * d) - std::sqrt(kRadius * kRadius - r2)));
      ++hits;
    }
  EXPECT_GT(hits, 2000);
  return worst;
}

TEST(ImplicitSampled, DepthErrorShrinksWithResolutionTrilinearAndTricubic) {
  for (GLenum interpolation : {GL_FIELD_TRILINEAR_EXT, GL_FIELD_TRICUBIC_EXT}) {
    double previous = 1.0;
    for (int n : {8, 16, 32, 64}) {
      const double err = maxDepthError(drawBall(n, interpolation, GL_FIELD_METHOD_INTERVAL_EXT, 0));
      std::printf("sampled ball, %s, %d^3 samples: max depth error %.3g\n",
                  interpolation == GL_FIELD_TRILINEAR_EXT ? "trilinear" : "tricubic", n, err);
      EXPECT_LT(err, 0.6 * previous) << n << " samples per axis";
      previous = err;
    }
    EXPECT_LT(previous, 2e-3);
  }
}

TEST(ImplicitSampled, EveryMethodFindsTheSurface) {
  for (GLenum interpolation : {GL_FIELD_TRILINEAR_EXT, GL_FIELD_TRICUBIC_EXT})
    for (float method : {0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f}) {
      SCOPED_TRACE(method);
      const double err = maxDepthError(drawBall(32, interpolation, method, method >= 5.0f || method == 3.0f ? 128.0f : 0.0f));
      EXPECT_LT(err, 5e-3);
    }
}

TEST(ImplicitSampled, ByteIdenticalForAnyThreadCountAndOnTheInterpreter) {
  const uint64_t saved = pf::NativeProgramCache::instance().threshold();
  pf::NativeProgramCache::instance().setThreshold(0);
  for (float method : {GL_FIELD_METHOD_INTERVAL_EXT, GL_FIELD_METHOD_SPHERE_EXT}) {
    const Image base = drawBall(16, GL_FIELD_TRICUBIC_EXT, method, 0, 1, 0);
    for (int threads : {1, 3})
      for (int native : {0, 1}) {
        const Image other = drawBall(16, GL_FIELD_TRICUBIC_EXT, method, 0, threads, native);
        EXPECT_TRUE(base.rgba == other.rgba) << threads << " threads, native " << native;
        EXPECT_TRUE(base.depth == other.depth) << threads << " threads, native " << native;
      }
  }
  pf::NativeProgramCache::instance().setThreshold(saved);
}

std::string fieldLog() {
  char log[1024];
  pfglGetFieldLogEXT(0, sizeof log, nullptr, log);
  return log;
}

TEST(ImplicitSampled, BadArgumentsAreGlErrors) {
  pf::test::FrameCapture capture(8, 8, 1, 1);
  std::vector<float> v = ballSamples(4);
  EXPECT_EQ(pfglSampledFieldEXT("g", 0, 4, 4, kBox, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_NE(fieldLog().find("g: error: a sampled field needs at least 2 samples along each axis (found 0 x 4 x 4)"),
            std::string::npos)
      << fieldLog();
  v[37] = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, kBox, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_NE(fieldLog().find("sample 37 (x 1, y 1, z 2) is not a finite number"), std::string::npos) << fieldLog();
  v[37] = 0.0f;
  EXPECT_EQ(pfglSampledFieldEXT("g", 1024, 1024, 1024, kBox, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_OUT_OF_MEMORY));
  EXPECT_NE(fieldLog().find("larger than the 16777216 allowed"), std::string::npos) << fieldLog();
  const GLdouble flat[6] = {-1, -1, -1, 1, -1, 1};
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, flat, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, nullptr, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, kBox, GL_FIELD_TRILINEAR_EXT, nullptr), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, kBox, GL_FIELD_HYPERFUN_EXT, v.data()), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglBegin(GL_TRIANGLES);
  EXPECT_EQ(pfglSampledFieldEXT("g", 4, 4, 4, kBox, GL_FIELD_TRILINEAR_EXT, v.data()), 0u);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  // A good one gets the next id, and its name finds it.
  const GLuint id = pfglSampledFieldEXT("good", 4, 4, 4, kBox, GL_FIELD_TRICUBIC_EXT, v.data());
  EXPECT_EQ(id, 1u);
  EXPECT_EQ(pfglGetFieldEXT("good"), id);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
