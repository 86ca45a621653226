// GL_PER_PIXEL_LIGHTING_EXT: vertex primitives lit per pixel from their interpolated eye-space
// position and normal. A triangle with diverging vertex normals under a close point light, local
// viewer and a sharp highlight -- where per-vertex (Gouraud) lighting visibly differs -- is checked
// per pixel against GL's lighting equation evaluated in double at the exact surface point, with
// the normal interpolated perspective-correct and normalised.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

#include "gl_context.h"

namespace {

constexpr int kN = 96;
const glm::dvec3 kV[3] = {{-1.6, -1.2, -3.0}, {1.7, -1.0, -3.6}, {-0.2, 1.6, -3.2}};
const glm::dvec3 kNormal[3] = {{-0.5, -0.3, 1.0}, {0.6, -0.2, 1.0}, {0.0, 0.7, 1.0}};
const glm::dvec3 kLight(0.3, 0.4, -1.6);
const glm::dvec3 kColour(0.8, 0.5, 0.3);
constexpr double kShininess = 40, kLinear = 0.2;

// Draws the triangle, lit per pixel or per vertex.
void draw(bool per_pixel) {
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1, 10);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const GLfloat pos[4] = {static_cast<GLfloat>(kLight.x), static_cast<GLfloat>(kLight.y), static_cast<GLfloat>(kLight.z), 1};
  const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1};
  pfglLightfv(GL_LIGHT0, GL_POSITION, pos);
  pfglLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, static_cast<GLfloat>(kLinear));
  pfglEnable(GL_LIGHT0);
  pfglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  pfglMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  pfglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, static_cast<GLfloat>(kShininess));
  pfglColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglEnable(GL_NORMALIZE);
  pfglEnable(GL_LIGHTING);
  if (per_pixel) pfglEnable(GL_PER_PIXEL_LIGHTING_EXT);
  else pfglDisable(GL_PER_PIXEL_LIGHTING_EXT);
  pfglColor3f(static_cast<GLfloat>(kColour.r), static_cast<GLfloat>(kColour.g), static_cast<GLfloat>(kColour.b));
  pfglBegin(GL_TRIANGLES);
  for (int i = 0; i < 3; ++i) {
    pfglNormal3f(static_cast<GLfloat>(kNormal[i].x), static_cast<GLfloat>(kNormal[i].y), static_cast<GLfloat>(kNormal[i].z));
    pfglVertex3d(kV[i].x, kV[i].y, kV[i].z);
  }
  pfglEnd();
  pfglFinish();
}

// GL's lit colour at pixel (x, y) in double, or false outside the triangle (with a margin).
bool expected(int x, int y, glm::dvec3& out) {
  const glm::dvec3 dir((x + 0.5) / kN - 0.5, (y + 0.5) / kN - 0.5, -1.0);  // glFrustum(+-0.5, near 1)
  const glm::dvec3 e1 = kV[1] - kV[0], e2 = kV[2] - kV[0], plane = glm::cross(e1, e2);
  const glm::dvec3 p = dir * (glm::dot(plane, kV[0]) / glm::dot(plane, dir));
  const glm::dvec3 v = p - kV[0];
  const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const double d20 = glm::dot(v, e1), d21 = glm::dot(v, e2), den = d00 * d11 - d01 * d01;
  const double b1 = (d11 * d20 - d01 * d21) / den, b2 = (d00 * d21 - d01 * d20) / den, b0 = 1 - b1 - b2;
  if (b0 < 0.02 || b1 < 0.02 || b2 < 0.02) return false;
  glm::dvec3 n(0);
  for (int i = 0; i < 3; ++i) n += (i == 0 ? b0 : i == 1 ? b1 : b2) * glm::normalize(kNormal[i]);
  n = glm::normalize(n);
  const glm::dvec3 to_light = kLight - p;
  const double dist = glm::length(to_light);
  const glm::dvec3 L = to_light / dist, V = glm::normalize(-p), H = glm::normalize(L + V);
  const double attenuation = 1 / (1 + kLinear * dist);
  const double ndl = std::max(0.0, glm::dot(n, L));
  const double spec = ndl > 0 ? std::pow(std::max(0.0, glm::dot(n, H)), kShininess) : 0.0;
  out = 0.2 * kColour + attenuation * (ndl * kColour + spec * glm::dvec3(0.6));
  return true;
}

}  // namespace

TEST(PerPixelVertexLighting, TrianglesMatchTheLightingEquationAtEveryPixel) {
  pf::test::GlContext c(kN, kN);
  GLboolean on = GL_TRUE;
  pfglGetBooleanv(GL_PER_PIXEL_LIGHTING_EXT, &on);
  EXPECT_EQ(on, GL_FALSE);  // off initially
  draw(true);
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(pfglIsEnabled(GL_PER_PIXEL_LIGHTING_EXT));
  const std::vector<unsigned char> per_pixel = c.px;
  int judged = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      glm::dvec3 want;
      if (!expected(x, y, want)) continue;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(per_pixel[(size_t(y) * kN + x) * 4 + k], std::clamp(want[k], 0.0, 1.0) * 255, 1.5)
            << "(" << x << ", " << y << ") channel " << k;
      ++judged;
    }
  EXPECT_GT(judged, 1500);

  // Per vertex, the highlight is smeared: many pixels differ from the per-pixel image.
  draw(false);
  int differ = 0;
  for (size_t i = 0; i < c.px.size(); ++i) differ += std::abs(int(c.px[i]) - int(per_pixel[i])) > 6;
  EXPECT_GT(differ, 200);
}
