// Shading parameters and their interpolators (paper sections 3.1 and 5.1): pfglMaterialInterpEXT
// chooses how a glBegin mode's instances interpolate a per-vertex parameter. Checked on a
// receding triangle against both interpolations computed here in double precision, and the
// generalised glMaterial setting a named parameter's current value.
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

// The triangle: object = eye coordinates; red is 1 at the far vertex, 0 at the near ones.
const double kTri[3][3] = {{-0.9, -0.9, -1.2}, {2.5, -2.0, -8.0}, {-0.5, 0.9, -1.5}};
const double kRed[3] = {0.0, 1.0, 0.0};

void draw() {
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) {
    pfglColor3f(static_cast<float>(kRed[i]), 0.0f, 1.0f);
    pfglVertex3d(kTri[i][0], kTri[i][1], kTri[i][2]);
  }
  pfglEnd();
  pfglFinish();
}

// Red at pixel (x, y) by GL's two interpolations, from window-space barycentrics.
void expected(int x, int y, double& linear, double& perspective, bool& inside) {
  double wx[3], wy[3], w[3];
  for (int i = 0; i < 3; ++i) {
    // glFrustum(-1, 1, -1, 1, 1, 10): x_clip = z_near * x / ... ; w_clip = -z.
    w[i] = -kTri[i][2];
    wx[i] = (kTri[i][0] / w[i] * 0.5 + 0.5) * kN;
    wy[i] = (kTri[i][1] / w[i] * 0.5 + 0.5) * kN;
  }
  double px = x + 0.5, py = y + 0.5;
  double area = (wx[1] - wx[0]) * (wy[2] - wy[0]) - (wx[2] - wx[0]) * (wy[1] - wy[0]);
  double l[3];
  l[0] = ((wx[1] - px) * (wy[2] - py) - (wx[2] - px) * (wy[1] - py)) / area;
  l[1] = ((wx[2] - px) * (wy[0] - py) - (wx[0] - px) * (wy[2] - py)) / area;
  l[2] = 1 - l[0] - l[1];
  inside = l[0] > 0.02 && l[1] > 0.02 && l[2] > 0.02;
  linear = l[0] * kRed[0] + l[1] * kRed[1] + l[2] * kRed[2];
  double s = 0, num = 0;
  for (int i = 0; i < 3; ++i) {
    s += l[i] / w[i];
    num += l[i] / w[i] * kRed[i];
  }
  perspective = num / s;
}

int red(const Ctx& c, int x, int y) { return c.px[(size_t(y) * kN + x) * 4]; }

}  // namespace

TEST(ShadingParameters, ColourIsPerspectiveLinearByDefaultAndLinearWhenBound) {
  Ctx c;
  GLuint color = pfglGetParamNameEXT("color");
  draw();
  int checked = 0, distinct = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      double lin, persp;
      bool inside;
      expected(x, y, lin, persp, inside);
      if (!inside) continue;
      EXPECT_NEAR(red(c, x, y), persp * 255, 1.01) << "perspective-correct at (" << x << ", " << y << ")";
      ++checked;
      distinct += std::abs(lin - persp) * 255 > 10;
    }
  EXPECT_GT(checked, 200);
  EXPECT_GT(distinct, 50) << "the two interpolations must differ here for the test to mean anything";
  pfglMaterialInterpEXT(color, GL_TRIANGLES, GL_LINEAR_INTERPOLATOR_EXT);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  draw();
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      double lin, persp;
      bool inside;
      expected(x, y, lin, persp, inside);
      if (inside) {
        EXPECT_NEAR(red(c, x, y), lin * 255, 1.01) << "screen-linear at (" << x << ", " << y << ")";
      }
    }
  // Binding the colour of another mode leaves GL_TRIANGLES as it is.
  pfglMaterialInterpEXT(color, GL_TRIANGLES, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT);
  pfglMaterialInterpEXT(color, GL_QUADS, GL_LINEAR_INTERPOLATOR_EXT);
  draw();
  double lin, persp;
  bool inside;
  expected(20, 20, lin, persp, inside);
  ASSERT_TRUE(inside);
  EXPECT_NEAR(red(c, 20, 20), persp * 255, 1.01);
}

TEST(ShadingParameters, ExtraParametersTakeChannelsWithoutChangingTheColour) {
  Ctx c;
  draw();
  std::vector<unsigned char> plain = c.px;
  GLuint gloss = pfglGetParamNameEXT("gloss");
  const GLfloat g[4] = {0.5f, 0.25f, 0.0f, 1.0f};
  pfglMaterialfv(GL_FRONT_AND_BACK, gloss, g);  // glMaterial with a name: its current value
  pfglMaterialInterpEXT(gloss, GL_TRIANGLES, GL_LINEAR_INTERPOLATOR_EXT);
  draw();
  EXPECT_EQ(c.px, plain);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(ShadingParameters, Errors) {
  Ctx c;
  GLuint color = pfglGetParamNameEXT("color");
  pfglMaterialInterpEXT(12345, GL_TRIANGLES, GL_LINEAR_INTERPOLATOR_EXT);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglMaterialInterpEXT(color, 0x31FFF, GL_LINEAR_INTERPOLATOR_EXT);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglMaterialInterpEXT(color, GL_TRIANGLES, GL_LINEAR);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglBegin(GL_TRIANGLES);
  pfglMaterialInterpEXT(color, GL_TRIANGLES, GL_LINEAR_INTERPOLATOR_EXT);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST(ShadingParameters, ColourIsOneValueUnderEveryName) {
  Ctx c;
  GLuint color = pfglGetParamNameEXT("color");
  pfglRastParam3fEXT(color, 0.25f, 0.5f, 0.75f);  // missing alpha: 1
  GLfloat v[4];
  pfglGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_EQ(v[0], 0.25f);
  EXPECT_EQ(v[3], 1.0f);
  const GLint raw[4] = {3, 4, 5, 6};  // glMaterialiv with a name: integers as they are
  GLuint count = pfglGetParamNameEXT("count");
  pfglMaterialiv(GL_FRONT_AND_BACK, count, raw);
  pfglMaterialiv(GL_FRONT_AND_BACK, color, raw);
  pfglGetFloatv(GL_CURRENT_COLOR, v);
  EXPECT_EQ(v[2], 5.0f);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A shared interpolator's point parameter is in eye coordinates, like P: an interpolator giving
// the distance from P to its `centre` matches the distance computed here in the eye-space plane.
TEST(ShadingParameters, InterpolatorPointsAreInEyeCoordinates) {
  Ctx c;
  ASSERT_NE(pfglCompilePrimitivesEXT("interpolator ring(point centre) {\n"
                                     "  float d = length(vector(P.x - centre.x, P.y - centre.y, P.z - centre.z));\n"
                                     "  interpolator_return(color(min(d, 1.0), 0.0, 0.0, 1.0));\n}\n"),
            0u);
  pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_TRIANGLES, pfglGetInterpolatorEXT("ring"));
  pfglTranslatef(0.0f, 0.0f, -2.0f);  // moves the triangle and the centre alike: both to z = -2
  pfglRastParam3fEXT(pfglGetParamNameEXT("centre"), 0.0f, 0.0f, 0.0f);
  pfglClear(GL_COLOR_BUFFER_BIT);
  pfglBegin(GL_TRIANGLES);
  pfglVertex3f(-3, -3, 0);
  pfglVertex3f(3, -3, 0);
  pfglVertex3f(0, 3, 0);
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int checked = 0;
  for (int y = 16; y < 48; y += 3)
    for (int x = 16; x < 48; x += 3) {
      // glFrustum(-1, 1, -1, 1, 1, 10): at z = -2 the pixel's centre is at eye (2 ndc_x, 2 ndc_y).
      const double ex = ((x + 0.5) / (kN / 2) - 1) * 2, ey = ((y + 0.5) / (kN / 2) - 1) * 2;
      const double d = std::min(std::sqrt(ex * ex + ey * ey), 1.0);
      EXPECT_NEAR(red(c, x, y), d * 255, 1.01) << "(" << x << ", " << y << ")";
      ++checked;
    }
  EXPECT_GT(checked, 50);
}
