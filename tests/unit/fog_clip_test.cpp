// Fog and user clip planes through the API: the fog factor against GL's equations in double
// precision, fog on a sphere (per pixel, from its surface point, against the analytic hit), clip planes on the exact
// sphere primitive against an analytic ray cast (a plane across it and a plane through its
// depth), the errors and queries, the attribute groups and display lists, and NULL pointers.
// (The images against OSMesa: tests/conformance/cases_fog_clip.inc.)
#include <gtest/gtest.h>

#include <primflow/context.h>
#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "raster/fog.h"
#include "gl_context.h"

namespace {

GLenum error() { return pfglGetError(); }

// GL's fog factor (GL 1.5 equations 3.24-3.26) in double, clamped.
double glFogFactor(GLenum mode, double z, double density, double start, double end) {
  double f = mode == GL_LINEAR ? (end - z) / (end - start)
             : mode == GL_EXP  ? std::exp(-density * z)
                               : std::exp(-(density * z) * (density * z));
  return std::clamp(f, 0.0, 1.0);
}

TEST(Fog, FactorMatchesGlEquations) {
  pf::FogParams linear{true, pf::FogMode::Linear, -1.0f / 28.0f, 30.0f / 28.0f, {0, 0, 0}};
  pf::FogParams exp{true, pf::FogMode::Exp, static_cast<float>(0.08 / std::log(2.0)), 0, {0, 0, 0}};
  pf::FogParams exp2{true, pf::FogMode::Exp2, static_cast<float>(0.06 / std::sqrt(std::log(2.0))), 0, {0, 0, 0}};
  for (double z = 0.0; z < 80.0; z += 0.37) {
    EXPECT_NEAR(pf::fogFactor(linear, static_cast<float>(z)), glFogFactor(GL_LINEAR, z, 0, 2, 30), 2e-6) << z;
    EXPECT_NEAR(pf::fogFactor(exp, static_cast<float>(z)), glFogFactor(GL_EXP, z, 0.08, 0, 0), 2e-6) << z;
    EXPECT_NEAR(pf::fogFactor(exp2, static_cast<float>(z)), glFogFactor(GL_EXP2, z, 0.06, 0, 0), 2e-6) << z;
  }
  EXPECT_EQ(pf::fogFactor(exp, std::nanf("")), 0.0f);  // NaN: all fog, not NaN
}

// Draws a sphere of radius r at (0, 0, cz) in eye space, orthographic over [-1, 1]^2, depth [-10, 10].
void drawSphere(float cz, float r) {
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglOrtho(-1, 1, -1, 1, -10, 10);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglColor3f(1.0f, 0.5f, 0.0f);
  pfglBegin(pfglGetPrimitiveEXT("sphere"));
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), r);
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 0.0f, 0.0f, cz);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
}

// A sphere is fogged by each pixel's own surface point (|P.z|), against the analytic front hit:
// GL's linear fog from 0 to 8 in double precision, within one step of 8 bits. Lit or not (the
// surface point reaches the shading pass either way).
TEST(Fog, SphereIsFoggedByEachPixelsSurfacePoint) {
  constexpr int kN = 32;
  pf::test::GlContext c(kN, kN);
  for (bool lit : {false, true}) {
    pfglClearColor(0, 0, 0, 1);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglEnable(GL_FOG);
    pfglFogi(GL_FOG_MODE, GL_LINEAR);
    pfglFogf(GL_FOG_START, 0.0f);
    pfglFogf(GL_FOG_END, 8.0f);
    const GLfloat blue[4] = {0, 0, 1, 1};
    pfglFogfv(GL_FOG_COLOR, blue);
    // Lit: ambient only, a white ambient light on an ambient material of the unlit colour --
    // the lit colour is the unlit one, so one reference serves both.
    const GLfloat none[4] = {0, 0, 0, 1}, white[4] = {1, 1, 1, 1}, colour[4] = {1.0f, 0.5f, 0.0f, 1.0f};
    pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, white);
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, colour);
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, none);
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
    (lit ? pfglEnable : pfglDisable)(GL_LIGHTING);
    const float cz = -2.0f, r = 0.8f;
    drawSphere(cz, r);
    pfglDisable(GL_LIGHTING);
    int checked = 0;
    double fog_min = 1.0, fog_max = 0.0;
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const double px = (x + 0.5) / kN * 2 - 1, py = (y + 0.5) / kN * 2 - 1;
        const double rr = double(r) * r - px * px - py * py;
        if (rr < 0.02) continue;  // outside, or the rim (float and double may disagree)
        const double z = std::fabs(cz + std::sqrt(rr));  // the front hit's eye distance
        const double f = glFogFactor(GL_LINEAR, z, 0, 0, 8);
        const unsigned char* p = c.at(x, y);
        EXPECT_NEAR(p[0], f * 255, 1.0) << x << "," << y << (lit ? " lit" : "");
        EXPECT_NEAR(p[1], f * 0.5 * 255, 1.0) << x << "," << y << (lit ? " lit" : "");
        EXPECT_NEAR(p[2], (1 - f) * 255, 1.0) << x << "," << y << (lit ? " lit" : "");
        fog_min = std::min(fog_min, f);
        fog_max = std::max(fog_max, f);
        ++checked;
      }
    EXPECT_GT(checked, 300);
    EXPECT_GT(fog_max - fog_min, 0.08);  // the fog varies across the sphere: not its centre's
  }
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

// The fogged sphere, lit per pixel, in perspective, drawn by native code and by the interpreter:
// the same bytes (the surface point both commit is the fog's input).
TEST(Fog, SphereFogIsTheSameWithNativeCodeAndTheInterpreter) {
  constexpr int kN = 48;
  std::vector<unsigned char> images[2];
  for (int native = 0; native < 2; ++native) {
    images[native].assign(kN * kN * 4, 0);
    const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_JIT, native, 0};
    PFcontext ctx = pfCreateContextAttribs(attribs);
    ASSERT_NE(ctx, nullptr);
    ASSERT_TRUE(pfMakeCurrent(ctx, images[native].data(), GL_UNSIGNED_BYTE, kN, kN));
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglEnable(GL_DEPTH_TEST);
    pfglEnable(GL_LIGHTING);
    pfglEnable(GL_LIGHT0);
    pfglEnable(GL_FOG);
    pfglFogi(GL_FOG_MODE, GL_EXP2);
    pfglFogf(GL_FOG_DENSITY, 0.3f);
    pfglMatrixMode(GL_PROJECTION);
    pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    pfglMatrixMode(GL_MODELVIEW);
    pfglBegin(pfglGetPrimitiveEXT("sphere"));
    for (int k = 0; k < 3; ++k) {
      pfglRastParamfEXT(pfglGetParamNameEXT("radius"), 0.6f + 0.2f * k);
      pfglRastParam3fEXT(pfglGetParamNameEXT("center"), -0.8f + 0.8f * k, 0.1f * k, -3.0f - 1.5f * k);
      pfglSequencePointEXT();
    }
    pfglEnd();
    pfglFinish();
    EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
  EXPECT_TRUE(images[0] == images[1]);
  int covered = 0;
  for (size_t i = 3; i < images[1].size(); i += 4) covered += images[1][i] != 0;
  EXPECT_GT(covered, 300);
}

TEST(ClipPlanes, ExactSphereAgainstAnalyticRayCast) {
  constexpr int kN = 64;
  pf::test::GlContext c(kN, kN);
  pfglEnable(GL_DEPTH_TEST);
  // x >= 0.3 (eye space), and z >= 0.5 (the front hit must lie nearer the eye than z = 0.5).
  const GLdouble across[4] = {1.0, 0.0, 0.0, -0.3};
  const GLdouble through_depth[4] = {0.0, 0.0, 1.0, -0.5};
  for (int which = 0; which < 2; ++which) {
    pfglClearColor(0, 0, 0, 0);
    pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    pfglMatrixMode(GL_MODELVIEW);
    pfglLoadIdentity();
    pfglClipPlane(GL_CLIP_PLANE4, which == 0 ? across : through_depth);
    pfglEnable(GL_CLIP_PLANE4);
    drawSphere(0.0f, 1.0f);
    pfglDisable(GL_CLIP_PLANE4);
    int drawn = 0;
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const double px = (x + 0.5) / kN * 2 - 1, py = (y + 0.5) / kN * 2 - 1;
        const double rr = 1.0 - px * px - py * py;
        if (std::fabs(rr) < 0.05) continue;  // the rim: float and double may disagree
        const double z = rr > 0 ? std::sqrt(rr) : -1.0;  // the front hit's eye z
        const double d = which == 0 ? px - 0.3 : z - 0.5;
        if (rr > 0 && std::fabs(d) < 0.02) continue;  // within a hair of the plane
        const bool expected = rr > 0 && d > 0;
        EXPECT_EQ(c.at(x, y)[3] != 0, expected) << "plane " << which << " pixel " << x << ", " << y;
        drawn += expected;
      }
    EXPECT_GT(drawn, 200);
  }
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ClipPlanes, QueriesErrorsAttributesAndLists) {
  pf::test::GlContext c(8, 8);
  GLint max = 0;
  pfglGetIntegerv(GL_MAX_CLIP_PLANES, &max);
  EXPECT_EQ(max, 8);
  const GLdouble eq[4] = {1, 2, 3, 4};
  pfglTranslatef(0, 0, -2);  // the plane times the inverse modelview: (1, 2, 3, 4) . (x, y, z + 2, 1)
  pfglClipPlane(GL_CLIP_PLANE0 + 7, eq);
  GLdouble back[4];
  pfglGetClipPlane(GL_CLIP_PLANE0 + 7, back);
  EXPECT_DOUBLE_EQ(back[0], 1);
  EXPECT_DOUBLE_EQ(back[2], 3);
  EXPECT_DOUBLE_EQ(back[3], 10);
  pfglClipPlane(GL_CLIP_PLANE0 + 8, eq);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglGetClipPlane(GL_CLIP_PLANE0 + 8, back);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglClipPlane(GL_CLIP_PLANE0, nullptr);  // ignored, no crash
  pfglGetClipPlane(GL_CLIP_PLANE0, nullptr);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglBegin(GL_POINTS);
  pfglClipPlane(GL_CLIP_PLANE0, eq);
  pfglEnd();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  pfglEnable(GL_CLIP_PLANE0 + 7);
  pfglPushAttrib(GL_TRANSFORM_BIT);
  pfglDisable(GL_CLIP_PLANE0 + 7);
  pfglClipPlane(GL_CLIP_PLANE0 + 7, eq);
  pfglPopAttrib();
  EXPECT_TRUE(pfglIsEnabled(GL_CLIP_PLANE0 + 7));
  pfglGetClipPlane(GL_CLIP_PLANE0 + 7, back);
  EXPECT_DOUBLE_EQ(back[3], 10);
  pfglLoadIdentity();
  pfglNewList(1, GL_COMPILE);
  pfglClipPlane(GL_CLIP_PLANE1, eq);
  pfglEndList();
  pfglGetClipPlane(GL_CLIP_PLANE1, back);
  EXPECT_DOUBLE_EQ(back[0], 0);  // not yet
  pfglCallList(1);
  pfglGetClipPlane(GL_CLIP_PLANE1, back);
  EXPECT_DOUBLE_EQ(back[3], 4);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Fog, QueriesErrorsAttributesAndLists) {
  pf::test::GlContext c(8, 8);
  GLfloat f[4];
  pfglGetFloatv(GL_FOG_DENSITY, f);
  EXPECT_EQ(f[0], 1.0f);
  GLint mode = 0;
  pfglGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP);
  pfglFogf(GL_FOG_DENSITY, -0.5f);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglFogi(GL_FOG_MODE, GL_LINEAR + 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglFogf(0x1234, 0.0f);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglFogf(GL_FOG_COORD_SRC, static_cast<GLfloat>(GL_FOG_COORD));  // no fog coordinates in primflow
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglFogfv(GL_FOG_COLOR, nullptr);  // ignored, no crash
  pfglFogiv(GL_FOG_MODE, nullptr);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglFogf(GL_FOG_START, 2.5f);
  GLint start = 0;
  pfglGetIntegerv(GL_FOG_START, &start);
  EXPECT_EQ(start, 3);  // a half away from zero, as Mesa
  pfglEnable(GL_FOG);
  pfglPushAttrib(GL_FOG_BIT);
  pfglDisable(GL_FOG);
  pfglFogf(GL_FOG_START, 7.0f);
  pfglPopAttrib();
  EXPECT_TRUE(pfglIsEnabled(GL_FOG));
  pfglGetFloatv(GL_FOG_START, f);
  EXPECT_EQ(f[0], 2.5f);
  pfglNewList(2, GL_COMPILE);
  pfglFogi(GL_FOG_MODE, GL_EXP2);
  pfglEndList();
  pfglGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP);
  pfglCallList(2);
  pfglGetIntegerv(GL_FOG_MODE, &mode);
  EXPECT_EQ(mode, GL_EXP2);
  pfglBegin(GL_POINTS);
  pfglFogf(GL_FOG_DENSITY, 0.5f);
  pfglEnd();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

}  // namespace
