// The polygon stipple (GL 1.5 section 3.5.2) on its own, without OSMesa: which pixels a stippled
// quad keeps (bit 31 - x mod 32 of row y mod 32, the first byte's top bit at x = 0), that the
// fragments it drops leave the depth buffer alone, that lines are not stippled, and the API's
// errors and attribute groups. (Images, unpacking and packing are compared with OSMesa's in
// tests/conformance/cases_polygon_stipple.inc.)
#include <gtest/gtest.h>

#include <cstring>

#include <primflow/gl.h>

#include "gl_context.h"

namespace {

using pf::test::windowOrtho;

// A pattern whose row k keeps exactly pixel x = (3 * k) mod 32 of each 32.
void diagonal(GLubyte pattern[128]) {
  std::memset(pattern, 0, 128);
  for (int row = 0; row < 32; ++row) {
    const int x = (3 * row) % 32;
    pattern[row * 4 + x / 8] = static_cast<GLubyte>(0x80u >> (x % 8));
  }
}

void quad(float x0, float y0, float x1, float y1, float z) {
  pfglBegin(GL_QUADS);
  pfglVertex3f(x0, y0, z);
  pfglVertex3f(x1, y0, z);
  pfglVertex3f(x1, y1, z);
  pfglVertex3f(x0, y1, z);
  pfglEnd();
}

GLboolean enabled() {
  GLboolean b = 7;
  pfglGetBooleanv(GL_POLYGON_STIPPLE, &b);
  EXPECT_EQ(b, pfglIsEnabled(GL_POLYGON_STIPPLE));
  return b;
}

}  // namespace

TEST(PolygonStipple, KeepsThePatternsPixelsAndTheirDepthOnly) {
  const int w = 70, h = 40;
  pf::test::GlContext c(w, h);
  windowOrtho(w, h);
  pfglClearColor(0, 0, 0, 0);
  pfglClearDepth(1.0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  GLubyte pattern[128];
  diagonal(pattern);
  pfglPolygonStipple(pattern);
  pfglEnable(GL_POLYGON_STIPPLE);
  pfglColor3f(1, 0, 0);
  quad(0, 0, static_cast<float>(w), static_cast<float>(h), 0.0f);  // window depth 0.5
  pfglColor3f(0, 1, 0);
  pfglBegin(GL_LINES);  // a line of pixels at y = 20, in front: not stippled
  pfglVertex3f(0.0f, 20.5f, 0.5f);
  pfglVertex3f(static_cast<float>(w), 20.5f, 0.5f);
  pfglEnd();
  pfglFinish();
  const float* depth = c.depth();
  ASSERT_NE(depth, nullptr);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const unsigned char* p = c.at(x, y);
      const float d = depth[y * w + x];
      if (y == 20) {
        EXPECT_EQ(p[1], 255) << x << ", " << y;
        continue;
      }
      const bool kept = x % 32 == (3 * (y % 32)) % 32;
      EXPECT_EQ(p[0], kept ? 255 : 0) << x << ", " << y;
      EXPECT_EQ(d, kept ? 0.5f : 1.0f) << x << ", " << y;
    }
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(PolygonStipple, InitialStateErrorsAndNull) {
  pf::test::GlContext c(8, 8);
  GLubyte got[128];
  std::memset(got, 0, sizeof got);
  pfglGetPolygonStipple(got);
  for (GLubyte b : got) EXPECT_EQ(b, 0xff);  // all 1s
  EXPECT_EQ(enabled(), GL_FALSE);
  GLubyte pattern[128];
  diagonal(pattern);
  pfglPolygonStipple(pattern);
  pfglPolygonStipple(nullptr);  // ignored, no error (as Mesa)
  pfglGetPolygonStipple(nullptr);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglGetPolygonStipple(got);
  EXPECT_EQ(std::memcmp(got, pattern, 128), 0);
  // Inside glBegin: GL_INVALID_OPERATION, nothing set, nothing written.
  GLubyte ones[128];
  std::memset(ones, 0xff, sizeof ones);
  pfglBegin(GL_TRIANGLES);
  pfglPolygonStipple(ones);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLubyte inside[128];
  std::memset(inside, 0x11, sizeof inside);
  pfglBegin(GL_TRIANGLES);
  pfglGetPolygonStipple(inside);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  for (GLubyte b : inside) EXPECT_EQ(b, 0x11);
  pfglGetPolygonStipple(got);
  EXPECT_EQ(std::memcmp(got, pattern, 128), 0);
}

TEST(PolygonStipple, AttributeGroups) {
  pf::test::GlContext c(8, 8);
  GLubyte a[128], b[128], got[128];
  diagonal(a);
  std::memset(b, 0x5a, sizeof b);
  pfglPolygonStipple(a);
  pfglEnable(GL_POLYGON_STIPPLE);
  // GL_POLYGON_STIPPLE_BIT: the pattern, not the enable.
  pfglPushAttrib(GL_POLYGON_STIPPLE_BIT);
  pfglPolygonStipple(b);
  pfglDisable(GL_POLYGON_STIPPLE);
  pfglPopAttrib();
  pfglGetPolygonStipple(got);
  EXPECT_EQ(std::memcmp(got, a, 128), 0);
  EXPECT_EQ(enabled(), GL_FALSE);
  // GL_ENABLE_BIT and GL_POLYGON_BIT: the enable, not the pattern.
  for (GLbitfield group : {GLbitfield{GL_ENABLE_BIT}, GLbitfield{GL_POLYGON_BIT}}) {
    pfglPolygonStipple(a);
    pfglEnable(GL_POLYGON_STIPPLE);
    pfglPushAttrib(group);
    pfglPolygonStipple(b);
    pfglDisable(GL_POLYGON_STIPPLE);
    pfglPopAttrib();
    pfglGetPolygonStipple(got);
    EXPECT_EQ(std::memcmp(got, b, 128), 0);
    EXPECT_EQ(enabled(), GL_TRUE);
  }
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}
