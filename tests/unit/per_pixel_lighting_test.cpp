// Per-pixel lighting (the shading pass): a procedural primitive that sets its surface normal N
// and point P is lit per pixel with the context's GL lighting. A ball seen through an
// orthographic camera is compared with GL's lighting equation evaluated here in double precision
// at every pixel centre.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

constexpr int kN = 64;

const char* kBall =
    "// A ball of `radius` around `centre` under an orthographic camera: the pixel's eye-space ray\n"
    "// runs along -z, so the front surface is at z = c.z + sqrt(r^2 - d^2).\n"
    "primitive ball(point centre[1]; float radius[1]; interpolator_data d[1]; inout varying float Z) {\n"
    "  point c = eye(centre[0]);\n"
    "  float cx = c.x / c.w;\n"
    "  float cy = c.y / c.w;\n"
    "  float cz = c.z / c.w;\n"
    "  point e = eye(unscreen(point(X, Y, 0.0)));\n"
    "  float dx = e.x / e.w - cx;\n"
    "  float dy = e.y / e.w - cy;\n"
    "  float r = radius[0];\n"
    "  float h2 = r * r - dx * dx - dy * dy;\n"
    "  if (h2 <= 0) return;\n"
    "  float h = sqrt(h2);\n"
    "  Z = 0.5;\n"
    "  N = normal(dx / r, dy / r, h / r);\n"
    "  P = point(cx + dx, cy + dy, cz + h);\n"
    "  interpolation { perspective_linear: linear: interpolator_return(d[0]); default: interpolator_return; }\n"
    "}\n";

}  // namespace

TEST(PerPixelLighting, BallMatchesTheLightingEquation) {
  std::vector<unsigned char> px(kN * kN * 4);
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  ASSERT_TRUE(pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, kN, kN));
  ASSERT_NE(pfglCompilePrimitivesEXT(kBall), 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglOrtho(-1, 1, -1, 1, -10, 10);  // eye x, y = window x, y scaled to [-1, 1]
  pfglMatrixMode(GL_MODELVIEW);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // One directional light; the ball's colour is its ambient and diffuse material.
  const GLfloat dir[4] = {-0.4f, 0.5f, 0.77f, 0.0f};
  const GLfloat spec[4] = {0.5f, 0.5f, 0.5f, 1};
  pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
  pfglEnable(GL_LIGHT0);
  pfglMaterialfv(GL_FRONT, GL_SPECULAR, spec);
  pfglMaterialf(GL_FRONT, GL_SHININESS, 16.0f);
  pfglColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglEnable(GL_LIGHTING);
  const float colour[3] = {0.8f, 0.4f, 0.2f};
  pfglColor3fv(colour);
  pfglBegin(pfglGetPrimitiveEXT("ball"));
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), 0.8f);
  pfglRastParam3fEXT(pfglGetParamNameEXT("centre"), 0.1f, -0.05f, 0.0f);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // Reference: GL 1.5's equation for this light and material, in double.
  const double l_len = std::sqrt(0.4 * 0.4 + 0.5 * 0.5 + 0.77 * 0.77);
  const double L[3] = {-0.4 / l_len, 0.5 / l_len, 0.77 / l_len};
  double H[3] = {L[0], L[1], L[2] + 1.0};  // infinite viewer: h = VP + (0, 0, 1)
  const double h_len = std::sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
  for (double& v : H) v /= h_len;
  int lit = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const double ex = (x + 0.5) / kN * 2 - 1, ey = (y + 0.5) / kN * 2 - 1;
      const double dx = ex - 0.1, dy = ey + 0.05, h2 = 0.64 - dx * dx - dy * dy;
      const unsigned char* p = &px[(size_t(y) * kN + x) * 4];
      if (h2 <= 1e-4) {  // outside, or too close to the rim for float and double to agree
        if (h2 < -1e-4) {
          EXPECT_EQ(p[3], 0) << "(" << x << ", " << y << ") is outside the ball";
        }
        continue;
      }
      const double n[3] = {dx / 0.8, dy / 0.8, std::sqrt(h2) / 0.8};
      const double ndl = std::max(0.0, n[0] * L[0] + n[1] * L[1] + n[2] * L[2]);
      const double ndh = std::max(0.0, n[0] * H[0] + n[1] * H[1] + n[2] * H[2]);
      const double spec_term = ndl > 0 ? std::pow(ndh, 16.0) * 0.5 : 0.0;
      for (int k = 0; k < 3; ++k) {
        const double want = std::clamp(colour[k] * 0.2 + colour[k] * ndl + spec_term, 0.0, 1.0);
        EXPECT_NEAR(p[k], want * 255, 1.5) << "(" << x << ", " << y << ") channel " << k;
      }
      ++lit;
    }
  EXPECT_GT(lit, 1000);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}
