// The built-in sphere primitive (primitives/sphere.pfl), fed as in the paper's figure 3: coverage
// and depth of two spheres -- one under a rotating, non-uniformly scaling modelview, so an
// ellipsoid -- against ray casts computed here in double precision through the same matrices.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

constexpr int kN = 96;

struct Sphere {
  glm::dmat4 modelview;
  glm::dvec3 centre;
  double radius;
};

// Window depth of the ray through pixel (x, y) hitting sphere s, or -1 (a miss, or too close to
// the rim for float and double to agree).
double castRay(const glm::dmat4& projection, const Sphere& s, int x, int y) {
  const glm::dmat4 inv = glm::inverse(projection * s.modelview);  // window (ndc) -> object
  const double nx = (x + 0.5) / kN * 2 - 1, ny = (y + 0.5) / kN * 2 - 1;
  glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::dvec3(b) / b.w - o, oc = o - s.centre;
  const double qa = glm::dot(d, d), qb = glm::dot(oc, d), qc = glm::dot(oc, oc) - s.radius * s.radius;
  const double disc = qb * qb - qa * qc;
  if (disc < 1e-6 * qa * s.radius * s.radius) return -1;  // outside, or at the rim
  const double t = (-qb - std::sqrt(disc)) / qa;
  if (t < 0 || t > 1) return -1;
  const glm::dvec4 clip = projection * s.modelview * glm::dvec4(o + d * t, 1);
  return clip.z / clip.w * 0.5 + 0.5;
}

}  // namespace

TEST(Sphere, CoverageAndDepthMatchRayCastsInDouble) {
  std::vector<unsigned char> px(kN * kN * 4);
  PFcontext ctx = pfCreateContext(GL_RGBA, 24);
  ASSERT_TRUE(pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, kN, kN));
  const GLenum sphere = pfglGetPrimitiveEXT("sphere");
  ASSERT_NE(sphere, 0u);
  const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  const glm::dmat4 projection = glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);

  Sphere spheres[2];
  // A plain sphere, and an ellipsoid: rotated, scaled unevenly.
  spheres[0].modelview = glm::translate(glm::dmat4(1), glm::dvec3(-0.8, 0.3, -6));
  spheres[0].centre = glm::dvec3(0, 0, 0);
  spheres[0].radius = 1.0;
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.9, -0.4, -7));
  m = glm::rotate(m, glm::radians(35.0), glm::normalize(glm::dvec3(1, 1, 0)));
  m = glm::scale(m, glm::dvec3(1.0, 0.5, 1.6));
  spheres[1].modelview = m;
  spheres[1].centre = glm::dvec3(0.2, 0.0, 0.1);
  spheres[1].radius = 0.9;

  for (int k = 0; k < 2; ++k) {
    pfglLoadIdentity();
    if (k == 0) {
      pfglTranslated(-0.8, 0.3, -6);
    } else {
      pfglTranslated(0.9, -0.4, -7);
      pfglRotated(35.0, 1, 1, 0);
      pfglScaled(1.0, 0.5, 1.6);
    }
    pfglColor3f(k == 0 ? 1.0f : 0.0f, 0.5f, 1.0f);
    pfglBegin(sphere);
    pfglRastParamfEXT(radius, static_cast<float>(spheres[k].radius));
    pfglRastParam3fEXT(centre, static_cast<float>(spheres[k].centre.x), static_cast<float>(spheres[k].centre.y),
                       static_cast<float>(spheres[k].centre.z));
    pfglSequencePointEXT();
    pfglEnd();
  }
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  GLint w, h, b;
  void* d = nullptr;
  ASSERT_TRUE(pfGetDepthBuffer(ctx, &w, &h, &b, &d));
  const float* depth = static_cast<const float*>(d);

  int hits[2] = {0, 0};
  double max_depth_error = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const double z0 = castRay(projection, spheres[0], x, y), z1 = castRay(projection, spheres[1], x, y);
      const unsigned char* p = &px[(size_t(y) * kN + x) * 4];
      const size_t i = size_t(y) * kN + x;
      if (z0 < 0 && z1 < 0) continue;  // a miss (or a rim pixel, left undecided)
      const int near = z1 < 0 || (z0 >= 0 && z0 < z1) ? 0 : 1;
      const double z = near == 0 ? z0 : z1;
      if (std::abs(z0 - z1) < 1e-4 && z0 >= 0 && z1 >= 0) continue;  // where they cross: either
      EXPECT_EQ(p[0], near == 0 ? 255 : 0) << "(" << x << ", " << y << "): the nearer sphere is " << near;
      EXPECT_NEAR(depth[i], z, 1e-6) << "(" << x << ", " << y << ")";
      max_depth_error = std::max(max_depth_error, std::abs(depth[i] - z));
      ++hits[near];
    }
  std::printf("  %d + %d pixels hit and judged; max depth error %.2g\n", hits[0], hits[1], max_depth_error);
  EXPECT_GT(hits[0], 300);
  EXPECT_GT(hits[1], 150);
  // Outside every sphere (with a margin for the rim) nothing is drawn.
  int drawn_outside = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      bool near_any = false;
      for (int dy = -1; dy <= 1 && !near_any; ++dy)
        for (int dx = -1; dx <= 1 && !near_any; ++dx) {
          const int xx = std::clamp(x + dx, 0, kN - 1), yy = std::clamp(y + dy, 0, kN - 1);
          near_any = castRay(projection, spheres[0], xx, yy) >= 0 || castRay(projection, spheres[1], xx, yy) >= 0;
        }
      if (!near_any) drawn_outside += px[(size_t(y) * kN + x) * 4 + 3] != 0;
    }
  EXPECT_EQ(drawn_outside, 0);
  pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  pfDestroyContext(ctx);
}
