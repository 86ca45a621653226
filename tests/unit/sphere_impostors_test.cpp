// The sphere_impostors primitive (primitives/sphere_impostors.pfl): 60 overlapping spheres, each
// with its own colour, under a rotating, uniformly scaling modelview, in one glBegin. Per pixel:
// which sphere is nearest (its colour), coverage and window depth, against ray casts computed
// here in double precision through the same matrices.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "gl_context.h"
#include "pixel_judging.h"

namespace {

constexpr int kN = 128;

struct Ball {
  glm::dvec3 centre;
  double radius;
  int id;  // its red channel: 40 + 3 id
};

glm::dmat4 projection() { return glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0); }
glm::dmat4 modelview() {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.1, -0.2, -6));
  m = glm::rotate(m, glm::radians(40.0), glm::normalize(glm::dvec3(0.3, 1, 0.2)));
  return glm::scale(m, glm::dvec3(1.3));
}

// The nearest sphere the ray through window point (x, y) meets: (window depth, index), or -1.
std::pair<double, int> castRay(const std::vector<Ball>& balls, double x, double y) {
  const glm::dmat4 inv = glm::inverse(projection() * modelview());
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::dvec3(b) / b.w - o;
  double best = 2;
  int which = -1;
  for (size_t i = 0; i < balls.size(); ++i) {
    const glm::dvec3 oc = o - balls[i].centre;
    const double qa = glm::dot(d, d), qb = glm::dot(oc, d), qc = glm::dot(oc, oc) - balls[i].radius * balls[i].radius;
    const double disc = qb * qb - qa * qc;
    if (disc < 0) continue;
    double t = (-qb - std::sqrt(disc)) / qa;
    if (t < 0) t = (-qb + std::sqrt(disc)) / qa;
    if (t >= 0 && t <= 1 && t < best) best = t, which = static_cast<int>(i);
  }
  if (which < 0) return {-1, -1};
  const glm::dvec4 c = projection() * modelview() * glm::dvec4(o + d * best, 1);
  return {c.z / c.w * 0.5 + 0.5, which};
}

// Draws `balls` (object coordinates) in one glBegin under the test's matrices and judges every
// pixel against castRay: the nearest sphere's colour and its window depth. Returns the pixels
// judged and covered. `tolerance`: window depth.
std::pair<int, int> drawAndJudge(const std::vector<Ball>& balls, double tolerance) {
  pf::test::GlContext c(kN, kN);
  const GLenum mode = pfglGetPrimitiveEXT("sphere_impostors");
  EXPECT_NE(mode, 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.1, -0.2, -6);
  pfglRotated(40.0, 0.3, 1, 0.2);
  pfglScaled(1.3, 1.3, 1.3);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  const GLuint centre = pfglGetParamNameEXT("center"), radius = pfglGetParamNameEXT("radius");
  pfglBegin(mode);
  for (const Ball& b : balls) {
    pfglColor4ub(static_cast<GLubyte>(40 + 3 * b.id), 0, 0, 255);
    pfglRastParamfEXT(radius, static_cast<float>(b.radius));
    pfglRastParam3fEXT(centre, static_cast<float>(b.centre.x), static_cast<float>(b.centre.y),
                       static_cast<float>(b.centre.z));
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglFinish();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const float* depth = c.depth();
  EXPECT_NE(depth, nullptr);
  if (!depth) return {0, 0};

  int judged = 0, undecided = 0, covered = 0;
  double max_error = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const auto [z, which] = castRay(balls, x + 0.5, y + 0.5);
      // A rim or a crossing of two spheres within 0.02 pixel: either answer.
      const auto center_which = which;  // clang 14 cannot capture a structured binding
      if (pf::test::changesNear(x, y,
                                [&](double px, double py) { return castRay(balls, px, py).second != center_which; })) {
        ++undecided;
        continue;
      }
      ++judged;
      const unsigned char* p = c.at(x, y);
      EXPECT_EQ(p[0], which < 0 ? 0 : 40 + 3 * balls[static_cast<size_t>(which)].id) << "(" << x << ", " << y << ")";
      if (which < 0) continue;
      ++covered;
      const double err = std::abs(depth[size_t(y) * kN + x] - z);
      max_error = std::max(max_error, err);
      EXPECT_LT(err, tolerance) << "(" << x << ", " << y << ") sphere " << which;
    }
  std::printf("  %d pixels judged (%d covered), %d undecided; max depth error %.2g\n", judged, covered, undecided,
              max_error);
  EXPECT_LT(undecided, judged / 20);
  return {judged, covered};
}

}  // namespace

TEST(SphereImpostors, NearestSphereCoverageAndDepthMatchRayCastsInDouble) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ball> balls;
  for (int i = 0; i < 60; ++i) balls.push_back({glm::dvec3(u(rng) * 1.4, u(rng) * 1.4, u(rng)), 0.12 + 0.1 * (u(rng) + 1), i});
  EXPECT_GT(drawAndJudge(balls, 1e-6).second, 3000);
}

// Spheres the near plane cuts (the inside of their far half shows), and spheres around the eye
// -- one centred on it, whose centre has no window image, and one whose centre is behind it --
// against the same double-precision ray casts. Window depth at the near plane (eye z = -1)
// changes 36 times faster per eye-space unit than at the first test's spheres (z = -6): its
// tolerance there, 4e-6, is 9 times tighter in eye space.
TEST(SphereImpostors, NearPlaneCutsAndSpheresAroundTheEye) {
  const glm::dmat4 to_object = glm::inverse(modelview());
  auto ball = [&](glm::dvec3 eye_centre, double eye_radius, int id) {
    return Ball{glm::dvec3(to_object * glm::dvec4(eye_centre, 1.0)), eye_radius / 1.3, id};
  };
  // Cut by the near plane (z = -1), in front of the spheres around the eye.
  EXPECT_GT(drawAndJudge({ball({0.1, 0.0, -1.1}, 0.3, 0), ball({-0.3, 0.2, -0.95}, 0.25, 1),
                          ball({0.0, 0.0, 0.0}, 8.0, 2)},
                         4e-6)
                .second,
            kN * kN / 2);
  EXPECT_GT(drawAndJudge({ball({0.2, -0.2, -1.05}, 0.2, 3), ball({0.2, 0.1, 0.5}, 1.8, 4)}, 4e-6).second,
            kN * kN / 2);
}

// Spheres behind the eye, one whose front point is the eye itself: nothing of them is in front,
// and such a front point has no image to recentre at -- they draw nothing, even with the depth
// test off (where a NaN depth would pass). Under the test's matrices and under the identity.
TEST(SphereImpostors, SpheresBehindTheEyeDrawNothing) {
  const glm::dmat4 to_object = glm::inverse(modelview());
  for (int identity = 0; identity < 2; ++identity)
    for (const glm::dvec3 eye_centre : {glm::dvec3(0.0, 0.0, 0.5), glm::dvec3(0.1, -0.2, 2.0)}) {
      pf::test::GlContext c(kN, kN);
      pfglMatrixMode(GL_PROJECTION);
      pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
      pfglMatrixMode(GL_MODELVIEW);
      double scale = 1.0;
      glm::dvec3 o = eye_centre;
      if (!identity) {
        pfglTranslated(0.1, -0.2, -6);
        pfglRotated(40.0, 0.3, 1, 0.2);
        pfglScaled(1.3, 1.3, 1.3);
        scale = 1.3;
        o = glm::dvec3(to_object * glm::dvec4(eye_centre, 1.0));
      }
      pfglClearColor(0, 0, 0, 0);
      pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      pfglColor4ub(200, 100, 50, 255);
      pfglBegin(pfglGetPrimitiveEXT("sphere_impostors"));
      pfglRastParamfEXT(pfglGetParamNameEXT("radius"), static_cast<float>(0.5 / scale));
      pfglRastParam3fEXT(pfglGetParamNameEXT("center"), static_cast<float>(o.x), static_cast<float>(o.y),
                         static_cast<float>(o.z));
      pfglSequencePointEXT();
      pfglEnd();
      pfglFinish();
      ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
      int drawn = 0;
      for (int y = 0; y < kN; ++y)
        for (int x = 0; x < kN; ++x) drawn += c.at(x, y)[0] != 0;
      EXPECT_EQ(drawn, 0) << "identity " << identity << ", eye z " << eye_centre.z;
    }
}
