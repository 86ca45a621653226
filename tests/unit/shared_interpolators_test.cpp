// Shared interpolators (paper section 3.4): compiled at run time, bound to a shading parameter
// of any primitive with pfglMaterialInterpEXT, run per pixel from the surface point P that the
// primitive sets (eye coordinates) and their own per-primitive parameters. Checked against the
// surface point computed here in double precision, and across two different primitives.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include "gl_context.h"

#include <cmath>
#include <vector>

namespace {

constexpr int kN = 64;

struct Ctx : pf::test::GlContext {
  Ctx() : GlContext(kN, kN) {
    pfglMatrixMode(GL_PROJECTION);
    pfglFrustum(-1, 1, -1, 1, 1, 10);
    pfglMatrixMode(GL_MODELVIEW);
  }
};

// The colour is a smooth function of the eye-space point, scaled by a per-primitive parameter.
const char* kEyeRgb =
    "interpolator eye_rgb(float scale) {\n"
    "  interpolator_return(color(0.5 + P.x * scale, 0.5 + P.y * scale, -P.z * 0.1, 1.0));\n"
    "}\n";

const double kTri[3][3] = {{-0.9, -0.9, -1.2}, {2.5, -2.0, -8.0}, {-0.5, 0.9, -1.5}};

// The eye-space point of the triangle's plane seen through pixel (x, y)'s centre, and whether
// the pixel is well inside the triangle (window-space barycentrics > 0.02).
bool surfacePoint(int x, int y, double p[3]) {
  double xn = (x + 0.5) / kN * 2 - 1, yn = (y + 0.5) / kN * 2 - 1;  // glFrustum(-1, 1, -1, 1, 1, ..)
  double d[3] = {xn, yn, -1};  // the ray from the eye through the pixel, at z = -1
  double e1[3], e2[3], n[3];
  for (int k = 0; k < 3; ++k) e1[k] = kTri[1][k] - kTri[0][k], e2[k] = kTri[2][k] - kTri[0][k];
  n[0] = e1[1] * e2[2] - e1[2] * e2[1], n[1] = e1[2] * e2[0] - e1[0] * e2[2], n[2] = e1[0] * e2[1] - e1[1] * e2[0];
  double t = (n[0] * kTri[0][0] + n[1] * kTri[0][1] + n[2] * kTri[0][2]) / (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]);
  for (int k = 0; k < 3; ++k) p[k] = t * d[k];
  // Inside: barycentrics of p in the triangle (in 3D, on its plane).
  double v[3];
  for (int k = 0; k < 3; ++k) v[k] = p[k] - kTri[0][k];
  double d00 = e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2], d01 = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
  double d11 = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
  double d20 = v[0] * e1[0] + v[1] * e1[1] + v[2] * e1[2], d21 = v[0] * e2[0] + v[1] * e2[1] + v[2] * e2[2];
  double den = d00 * d11 - d01 * d01, b = (d11 * d20 - d01 * d21) / den, c = (d00 * d21 - d01 * d20) / den;
  return b > 0.02 && c > 0.02 && 1 - b - c > 0.02;
}

int expectedChannel(const double p[3], int k, double scale) {
  double v = k == 0 ? 0.5 + p[0] * scale : k == 1 ? 0.5 + p[1] * scale : -p[2] * 0.1;
  return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255));
}

void bindEyeRgb(GLenum mode) {
  ASSERT_NE(pfglCompilePrimitivesEXT(kEyeRgb), 0u);
  GLenum interp = pfglGetInterpolatorEXT("eye_rgb");
  EXPECT_GE(interp, static_cast<GLenum>(GL_FIRST_INTERPOLATOR_EXT));
  pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), mode, interp);
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace

TEST(SharedInterpolators, ColourFromTheSurfacePointOfATriangle) {
  Ctx c;
  bindEyeRgb(GL_TRIANGLES);
  GLuint scale = pfglGetParamNameEXT("scale");
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  pfglRastParamfEXT(scale, 0.2f);  // per primitive: the value at the first sequence point
  for (const auto& v : kTri) {
    pfglVertex3d(v[0], v[1], v[2]);
    pfglRastParamfEXT(scale, 5.0f);  // later changes do not reach this instance
  }
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int checked = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      double p[3];
      if (!surfacePoint(x, y, p)) continue;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(c.at(x, y)[k], expectedChannel(p, k, 0.2), 1) << "(" << x << ", " << y << ") channel " << k;
      ++checked;
    }
  EXPECT_GT(checked, 300);
}

// The same surface point gives the same value on two different primitives: a point drawn at
// the eye-space point under a pixel's centre, and the triangle through that pixel.
TEST(SharedInterpolators, SameValueAtTheSamePointOnTwoPrimitives) {
  Ctx c;
  bindEyeRgb(GL_TRIANGLES);
  pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_POINTS, pfglGetInterpolatorEXT("eye_rgb"));
  GLuint scale = pfglGetParamNameEXT("scale");
  pfglRastParamfEXT(scale, 0.3f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  for (const auto& v : kTri) pfglVertex3d(v[0], v[1], v[2]);
  pfglEnd();
  pfglFinish();
  std::vector<unsigned char> triangle = c.px;
  pfglClear(GL_COLOR_BUFFER_BIT);
  std::vector<std::pair<int, int>> pixels;
  pfglBegin(GL_POINTS);
  for (int y = 4; y < kN; y += 9)
    for (int x = 3; x < kN; x += 7) {
      double p[3];
      if (!surfacePoint(x, y, p)) continue;
      pfglVertex3d(p[0], p[1], p[2]);
      pixels.push_back({x, y});
    }
  pfglEnd();
  pfglFinish();
  ASSERT_GT(pixels.size(), 5u);
  for (auto [x, y] : pixels)
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(c.at(x, y)[k], triangle[(size_t(y) * kN + x) * 4 + k], 1) << "(" << x << ", " << y << ") channel " << k;
}

TEST(SharedInterpolators, CompileAndLookUp) {
  Ctx c;
  EXPECT_EQ(pfglGetInterpolatorEXT("nope"), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglGetInterpolatorEXT(nullptr), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  ASSERT_NE(pfglCompilePrimitivesEXT(kEyeRgb), 0u);
  GLenum first = pfglGetInterpolatorEXT("eye_rgb");
  ASSERT_NE(pfglCompilePrimitivesEXT(kEyeRgb), 0u);
  EXPECT_EQ(pfglGetInterpolatorEXT("eye_rgb"), first) << "recompiling keeps the id";
  // An interpolator reads P and its parameters, no arrays.
  EXPECT_EQ(pfglCompilePrimitivesEXT("interpolator bad(float w[3]) { interpolator_return(w[0]); }"), 0u);
  char log[512];
  pfglGetCompileLogEXT(0, sizeof log, nullptr, log);
  EXPECT_NE(std::string(log).find("depends only on per-primitive parameters and P"), std::string::npos) << log;
}
