// The torus primitive (primitives/torus.pfl) against a ray cast in double precision that shares
// nothing with it: sphere tracing on the tube's exact distance function (a step of the distance
// never crosses the surface), from the near plane, to 1e-12. Cases that break careless quartic
// solvers: a plain torus at an angle, a very thin one, one seen edge-on (grazing rays all along
// its rim), one cut by the near plane, and one whose plane holds a row of rays.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl_context.h"
#include "pixel_judging.h"

namespace {

constexpr int kN = 96;

struct TorusCase {
  const char* name;
  double ring, tube;    // radius, tube_radius
  double distance;      // of the centre from the eye
  double tilt;          // degrees about the (1, 0.2, 0) axis
  glm::dvec3 scale;     // non-uniform scale of the modelview
  int min_hits;
  glm::dvec3 axis{1, 0.2, 0};         // of the tilt
  glm::dvec3 offset{0.05, -0.02, 0};  // of the centre, across the view
};

void PrintTo(const TorusCase& c, std::ostream* os) { *os << c.name; }

glm::dmat4 projection() { return glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0); }
glm::dmat4 modelview(const TorusCase& c) {
  glm::dmat4 m = glm::translate(glm::dmat4(1), c.offset + glm::dvec3(0, 0, -c.distance));
  m = glm::rotate(m, glm::radians(c.tilt), glm::normalize(c.axis));
  return glm::scale(m, c.scale);
}

double tubeDistance(const glm::dvec3& p, double ring, double tube) {
  return std::hypot(std::hypot(p.x, p.y) - ring, p.z) - tube;
}

// Window depth of the first surface crossing of the ray through window point (x, y), or -1.
double castRay(const TorusCase& c, double x, double y) {
  const glm::dmat4 inv = glm::inverse(projection() * modelview(c));
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, far = glm::dvec3(b) / b.w;
  const double len = glm::length(far - o);
  const glm::dvec3 u = (far - o) / len;
  double s = 0;
  for (int i = 0; i < 100000 && s <= len; ++i) {
    const double g = std::abs(tubeDistance(o + u * s, c.ring, c.tube));
    if (g < 1e-12) {
      const glm::dvec4 clip = projection() * modelview(c) * glm::dvec4(o + u * s, 1);
      return clip.z / clip.w * 0.5 + 0.5;
    }
    s += g;
  }
  return -1;
}

class Torus : public testing::TestWithParam<TorusCase> {};

TEST_P(Torus, CoverageAndDepthMatchSphereTracingInDouble) {
  const TorusCase& tc = GetParam();
  pf::test::GlContext ctx(kN, kN);
  const GLenum torus = pfglGetPrimitiveEXT("torus");
  ASSERT_NE(torus, 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(tc.offset.x, tc.offset.y, tc.offset.z - tc.distance);
  pfglRotated(tc.tilt, tc.axis.x, tc.axis.y, tc.axis.z);
  pfglScaled(tc.scale.x, tc.scale.y, tc.scale.z);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglBegin(torus);
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 0, 0, 0);
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), static_cast<float>(tc.ring));
  pfglRastParamfEXT(pfglGetParamNameEXT("tube_radius"), static_cast<float>(tc.tube));
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const float* depth = ctx.depth();
  ASSERT_NE(depth, nullptr);

  int hits = 0, undecided = 0;
  double max_depth_error = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const double z = castRay(tc, x + 0.5, y + 0.5);
      // A silhouette within 0.02 pixel, or a jump of depth there (a rim, where the tube hides
      // itself): float and double may decide differently. Not judged.
      const auto jumps = [&](double px, double py) {
        const double z2 = castRay(tc, px, py);
        return (z2 < 0) != (z < 0) || std::abs(z2 - z) > 1e-3;
      };
      if (pf::test::changesNear(x, y, jumps)) {
        ++undecided;
        continue;
      }
      EXPECT_EQ(ctx.at(x, y)[3] != 0, z >= 0) << tc.name << " (" << x << ", " << y << ")";
      if (z < 0) continue;
      ++hits;
      max_depth_error = std::max(max_depth_error, std::abs(depth[size_t(y) * kN + x] - z));
      EXPECT_NEAR(depth[size_t(y) * kN + x], z, 4e-6) << tc.name << " (" << x << ", " << y << ")";
    }
  std::printf("  %s: %d pixels hit and judged, %d undecided; max depth error %.2g\n", tc.name, hits, undecided,
              max_depth_error);
  EXPECT_GT(hits, tc.min_hits) << tc.name;
  EXPECT_LT(undecided, hits / 4 + 40) << tc.name;
}

INSTANTIATE_TEST_SUITE_P(
    All, Torus,
    testing::Values(TorusCase{"tilted", 1.0, 0.3, 5.0, 55.0, glm::dvec3(1.1, 0.9, 1.0), 1000},
                    TorusCase{"thin", 1.2, 0.02, 4.0, 40.0, glm::dvec3(1, 1, 1), 150},
                    TorusCase{"edge_on", 1.0, 0.25, 5.0, 89.5, glm::dvec3(1, 1, 1), 400},
                    TorusCase{"cut_by_near_plane", 1.0, 0.45, 1.6, 20.0, glm::dvec3(1, 1, 1), 2000},
                    // Pixel row 48's rays lie in the torus' plane through its centre: each meets
                    // the tube's outermost point just where it enters the bounding sphere.
                    TorusCase{"rays_in_its_plane", 1.0, 0.3, 5.0, 90.0 + glm::degrees(std::atan(0.5 / 96)),
                              glm::dvec3(1, 1, 1), 150, glm::dvec3(1, 0, 0), glm::dvec3(0, 5 * 0.5 / 96, 0)}),
    [](const testing::TestParamInfo<TorusCase>& info) { return std::string(info.param.name); });

}  // namespace
