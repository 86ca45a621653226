// The superquadric primitive (primitives/superquadric.pfl) against a ray cast in double
// precision that shares nothing with it: the implicit function F itself (not the primitive's
// gauge F^(e1/2), no bounds, no convexity), sampled along the ray from the near plane every 4e-3
// (in unit coordinates (p - center) / radii) and where the ray crosses a coordinate plane or
// passes nearest an axis (where the fins and spikes of e > 2 shapes are thinner than any step),
// the first sign change refined by bisection to 1e-13; for e1 = e2 = 1, the analytic
// ray-ellipsoid intersection instead. Compared per pixel, away from silhouettes: coverage
// exactly, window depth within the primitive's documented bound (2^-21 of the ray's span in the
// box) converted to depth plus 1e-6 of float rounding (at most 4e-6 in all), and the normal
// through GL's lighting (one white directional light, diffuse only: red = max(0, N . L)).
// Cases: an ellipsoid with unequal radii, a rounded box (e = 0.3), a pinched shape (e1 = 2.5,
// e2 = 0.5), an octahedron (e = 2: edges where the gradient jumps), a star (e > 2 both ways), a
// star prism (e1 < 2 < e2), one under a rotating, non-uniformly scaling modelview, and three cut
// by the near plane (seen mostly from inside: a convex one, a pinched one, a star prism). Every
// branch of the primitive's searches and bounds is used.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_context.h"

namespace {

constexpr int kN = 96;

struct SuperquadricCase {
  const char* name;
  glm::dvec3 center, radii;
  double e1, e2;
  double distance;   // of the modelview's origin from the eye
  double tilt;       // degrees about (1, 0.2, 0)
  double spin;       // degrees about (0.3, 1, 0.5), after the tilt
  glm::dvec3 scale;  // non-uniform scale of the modelview
  int min_hits;
  int min_inside = 0;  // judged pixels whose ray starts inside the solid
};

void PrintTo(const SuperquadricCase& c, std::ostream* os) { *os << c.name; }

glm::dmat4 projection() { return glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0); }
glm::dmat4 modelview(const SuperquadricCase& c) {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.05, -0.02, -c.distance));
  m = glm::rotate(m, glm::radians(c.tilt), glm::normalize(glm::dvec3(1, 0.2, 0)));
  m = glm::rotate(m, glm::radians(c.spin), glm::normalize(glm::dvec3(0.3, 1, 0.5)));
  return glm::scale(m, c.scale);
}

// The light, a direction in eye coordinates.
const glm::dvec3 kLight = glm::normalize(glm::dvec3(-0.4, 0.5, 0.77));

// F - 1 in unit coordinates q: < 0 inside, written as the definition reads.
double implicit(const SuperquadricCase& c, const glm::dvec3& q) {
  const double xy = std::pow(std::abs(q.x), 2 / c.e2) + std::pow(std::abs(q.y), 2 / c.e2);
  return std::pow(xy, c.e2 / c.e1) + std::pow(std::abs(q.z), 2 / c.e1) - 1;
}

// The gradient of F at unit coordinates q, in object coordinates (through the radii).
glm::dvec3 gradient(const SuperquadricCase& c, const glm::dvec3& q) {
  const double ax = std::max(std::abs(q.x), 1e-300), ay = std::max(std::abs(q.y), 1e-300),
               az = std::max(std::abs(q.z), 1e-300);
  const double sxy = std::pow(ax, 2 / c.e2) + std::pow(ay, 2 / c.e2);
  // dF/d|x| = (e2/e1) sxy^(e2/e1 - 1) (2/e2) |x|^(2/e2 - 1) = k |x|^(2/e2 - 1)
  const double k = (2 / c.e1) * std::pow(sxy, c.e2 / c.e1 - 1);
  const glm::dvec3 g(k * std::pow(ax, 2 / c.e2 - 1) * (q.x < 0 ? -1 : 1),
                     k * std::pow(ay, 2 / c.e2 - 1) * (q.y < 0 ? -1 : 1),
                     (2 / c.e1) * std::pow(az, 2 / c.e1 - 1) * (q.z < 0 ? -1 : 1));
  return g / c.radii;
}

struct Hit {
  double depth = -1;  // window depth, -1: no hit
  double lit = 0;     // max(0, N . L) with the eye-space normal there
  double slack = 0;      // the primitive's documented bound (2^-21 of the ray's span in the box), in depth
  bool inside = false;   // the ray starts inside the solid (the near plane cuts it)
};

// The first crossing of the surface by the ray through window point (x, y), from the near plane.
Hit castRay(const SuperquadricCase& c, double x, double y) {
  const glm::dmat4 mv = modelview(c);
  const glm::dmat4 inv = glm::inverse(projection() * mv);
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, far = glm::dvec3(b) / b.w;
  const double len = glm::length(far - o);
  const glm::dvec3 u = (far - o) / len;
  // The ray in unit coordinates: q0 + qu s, s from 0 (near plane) to len (far plane).
  const glm::dvec3 q0 = (o - c.center) / c.radii, qu = u / c.radii;
  // Where it is in the box |q| <= 1.01 (which holds the solid).
  double s0 = 0, s1 = len;
  for (int k = 0; k < 3; ++k) {
    if (qu[k] == 0) {
      if (std::abs(q0[k]) > 1.01) return {};
      continue;
    }
    const double ta = (-1.01 - q0[k]) / qu[k], tb = (1.01 - q0[k]) / qu[k];
    s0 = std::max(s0, std::min(ta, tb));
    s1 = std::min(s1, std::max(ta, tb));
  }
  if (!(s0 < s1)) return {};
  double s = -1;
  if (c.e1 == 1 && c.e2 == 1) {
    // The ellipsoid: |q0 + qu s|^2 = 1, the roots without cancellation.
    const double A = glm::dot(qu, qu), B = glm::dot(q0, qu), C = glm::dot(q0, q0) - 1;
    const double disc = B * B - A * C;
    if (disc < 0) return {};
    const double q = B >= 0 ? -(B + std::sqrt(disc)) : -(B - std::sqrt(disc));
    const double r0 = std::min(q / A, C / q), r1 = std::max(q / A, C / q);
    s = r0 >= 0 ? r0 : r1;
    if (s < 0 || s > len) return {};
  } else {
    // Samples at most 4e-3 apart in unit coordinates, from the start of the box, and also where
    // the ray crosses a coordinate plane through the centre or passes nearest an axis: for
    // e > 2 the solid has fins along those planes and spikes along the axes, thinner than any
    // step near their edges and tips, whose inside is there.
    const double h = 4e-3 / glm::length(qu);
    std::vector<double> samples;
    for (double t = s0; t < s1; t += h) samples.push_back(t);
    samples.push_back(s1);
    for (int k = 0; k < 3; ++k) {
      if (qu[k] != 0) samples.push_back(-q0[k] / qu[k]);
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double uu = qu[i] * qu[i] + qu[j] * qu[j];
      if (uu > 0) samples.push_back(-(q0[i] * qu[i] + q0[j] * qu[j]) / uu);
    }
    std::sort(samples.begin(), samples.end());
    const bool inside = implicit(c, q0 + qu * s0) < 0;
    double prev = s0;
    for (const double t : samples) {
      if (t <= s0 || t > s1) continue;
      if ((implicit(c, q0 + qu * t) < 0) != inside) {
        double lo = prev, hi = t;
        while (hi - lo > 1e-13 * len) {
          const double m = 0.5 * (lo + hi);
          ((implicit(c, q0 + qu * m) < 0) == inside ? lo : hi) = m;
        }
        s = 0.5 * (lo + hi);
        break;
      }
      prev = t;
    }
    if (s < 0) return {};
  }
  const glm::dmat4 pm = projection() * mv;
  auto depth = [&](double t) {
    const glm::dvec4 clip = pm * glm::dvec4(o + u * t, 1);
    return clip.z / clip.w * 0.5 + 0.5;
  };
  Hit hit;
  hit.depth = depth(s);
  hit.inside = implicit(c, q0) < 0;
  const double bound = (s1 - s0) / 2097152.0;
  hit.slack = std::max(std::abs(depth(s + bound) - hit.depth), std::abs(depth(s - bound) - hit.depth));
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(mv)));
  const glm::dvec3 n = glm::normalize(normal_matrix * gradient(c, q0 + qu * s));
  hit.lit = std::max(0.0, glm::dot(n, kLight));
  return hit;
}

class Superquadric : public testing::TestWithParam<SuperquadricCase> {};

TEST_P(Superquadric, CoverageDepthAndNormalMatchARayCastInDouble) {
  const SuperquadricCase& sc = GetParam();
  pf::test::GlContext ctx(kN, kN);
  const GLenum superquadric = pfglGetPrimitiveEXT("superquadric");
  ASSERT_NE(superquadric, 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  // Lit by one white directional light, diffuse only: red = max(0, N . L).
  const GLfloat light[4] = {float(kLight.x), float(kLight.y), float(kLight.z), 0};
  const GLfloat black[4] = {0, 0, 0, 1};
  pfglLightfv(GL_LIGHT0, GL_POSITION, light);  // with the identity modelview: eye coordinates
  pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  pfglEnable(GL_LIGHT0);
  pfglColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglEnable(GL_LIGHTING);
  pfglTranslated(0.05, -0.02, -sc.distance);
  pfglRotated(sc.tilt, 1, 0.2, 0);
  pfglRotated(sc.spin, 0.3, 1, 0.5);
  pfglScaled(sc.scale.x, sc.scale.y, sc.scale.z);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor4f(1, 1, 1, 1);
  pfglBegin(superquadric);
  const glm::vec3 center(sc.center), radii(sc.radii);
  pfglRastParam3fEXT(pfglGetParamNameEXT("center"), center.x, center.y, center.z);
  pfglRastParam3fEXT(pfglGetParamNameEXT("radii"), radii.x, radii.y, radii.z);
  const GLfloat exponents[2] = {float(sc.e1), float(sc.e2)};
  pfglRastParamfvEXT(pfglGetParamNameEXT("exponents"), 2, exponents);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const float* depth = ctx.depth();
  ASSERT_NE(depth, nullptr);

  int hits = 0, undecided = 0, shaded = 0, inside = 0;
  double max_depth_error = 0, max_slack = 0, max_lit_error = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const Hit ref = castRay(sc, x + 0.5, y + 0.5);
      // A silhouette within 0.02 pixel, or a jump of depth there (where the shape hides itself):
      // float and double may decide differently. Not judged. Where the normal turns fast (an
      // edge, a cusp) the lighting is not judged either.
      bool edge = false, turning = false;
      for (int k = 0; k < 4 && !edge; ++k) {
        const Hit h2 = castRay(sc, x + 0.5 + (k % 2 ? 0.02 : -0.02), y + 0.5 + (k / 2 ? 0.02 : -0.02));
        edge = (h2.depth < 0) != (ref.depth < 0) || std::abs(h2.depth - ref.depth) > 1e-3;
        turning = turning || std::abs(h2.lit - ref.lit) > 0.01;
      }
      if (edge) {
        ++undecided;
        continue;
      }
      const unsigned char* px = ctx.at(x, y);
      EXPECT_EQ(px[3] != 0, ref.depth >= 0) << sc.name << " (" << x << ", " << y << ")";
      if (ref.depth < 0 || px[3] == 0) continue;
      ++hits;
      inside += ref.inside;
      // The documented bound in depth, plus float rounding of the pipeline (unprojecting the
      // pixel, the hit point, projecting it back): 1e-6.
      const double tolerance = std::min(ref.slack + 1e-6, 4e-6);
      const double error = std::abs(depth[size_t(y) * kN + x] - ref.depth);
      EXPECT_LE(error, tolerance) << sc.name << " (" << x << ", " << y << ")";
      max_depth_error = std::max(max_depth_error, error);
      max_slack = std::max(max_slack, ref.slack);
      if (!turning) {
        ++shaded;
        const double lit_error = std::abs(px[0] / 255.0 - ref.lit);
        EXPECT_LE(lit_error, 3.0 / 255) << sc.name << " (" << x << ", " << y << ")";
        max_lit_error = std::max(max_lit_error, lit_error);
      }
    }
  std::printf("  %s: %d pixels hit and judged (%d from inside, %d for lighting), %d undecided; max depth "
              "error %.3g (documented bound in depth up to %.3g), max lighting error %.3g\n",
              sc.name, hits, inside, shaded, undecided, max_depth_error, max_slack, max_lit_error);
  EXPECT_GT(hits, sc.min_hits) << sc.name;
  EXPECT_GE(inside, sc.min_inside) << sc.name;
  EXPECT_GT(shaded, hits / 2) << sc.name;
  EXPECT_LT(undecided, hits / 4 + 40) << sc.name;
}

INSTANTIATE_TEST_SUITE_P(
    All, Superquadric,
    testing::Values(
        SuperquadricCase{"ellipsoid", {0.1, -0.05, 0.2}, {1.2, 0.7, 0.9}, 1.0, 1.0, 5.0, 35.0, 20.0, {1, 1, 1}, 1000},
        SuperquadricCase{"rounded_box", {0, 0.1, 0}, {1.0, 0.8, 0.6}, 0.3, 0.3, 5.0, 40.0, 30.0, {1, 1, 1}, 1100},
        SuperquadricCase{"pinched", {0, 0, 0.1}, {1.1, 1.0, 1.2}, 2.5, 0.5, 5.0, 25.0, 15.0, {1, 1, 1}, 1000},
        SuperquadricCase{"octahedron", {0, 0, 0}, {1.2, 1.0, 1.1}, 2.0, 2.0, 5.0, 30.0, 40.0, {1, 1, 1}, 600},
        SuperquadricCase{"star", {0, 0, 0}, {1.3, 1.2, 1.2}, 3.0, 3.0, 5.0, 20.0, 50.0, {1, 1, 1}, 450},
        SuperquadricCase{"star_prism", {0, 0.05, 0}, {1.3, 1.2, 0.9}, 0.6, 3.0, 5.0, 50.0, 25.0, {1, 1, 1}, 500},
        SuperquadricCase{"scaled_rotated", {0.1, 0, -0.1}, {0.9, 0.6, 0.8}, 0.7, 1.6, 5.0, 60.0, 35.0,
                         {1.4, 0.7, 1.1}, 1100},
        SuperquadricCase{"cut_by_near_plane", {0.45, 0.3, 0}, {0.6, 0.5, 0.45}, 0.5, 1.0, 1.3, 20.0, 10.0,
                         {1, 1, 1}, 2500, 1000},
        SuperquadricCase{"pinched_cut_by_near_plane", {-0.3, -0.25, 0}, {0.6, 0.55, 0.6}, 2.5, 0.5, 1.1, 30.0, 20.0,
                         {1, 1, 1}, 3000, 2000},
        SuperquadricCase{"star_prism_cut_by_near_plane", {0.3, -0.3, 0}, {0.6, 0.55, 0.5}, 0.6, 3.0, 1.1, 40.0,
                         15.0, {1, 1, 1}, 3000, 800}),
    [](const testing::TestParamInfo<SuperquadricCase>& info) { return std::string(info.param.name); });

// Exponents outside [0.1, 4] and radii that are not all > 0 draw nothing.
TEST(Superquadric, OutOfRangeParametersDrawNothing) {
  pf::test::GlContext ctx(32, 32);
  const GLenum superquadric = pfglGetPrimitiveEXT("superquadric");
  ASSERT_NE(superquadric, 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0, 0, -4);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  const float cases[][5] = {{0.05f, 1, 1, 1, 1}, {1, 4.5f, 1, 1, 1}, {1, 1, 0, 1, 1}, {1, 1, 1, -1, 1}};
  for (const auto& c : cases) {
    pfglBegin(superquadric);
    pfglRastParam3fEXT(pfglGetParamNameEXT("center"), 0, 0, 0);
    pfglRastParam3fEXT(pfglGetParamNameEXT("radii"), c[2], c[3], c[4]);
    pfglRastParamfvEXT(pfglGetParamNameEXT("exponents"), 2, c);
    pfglSequencePointEXT();
    pfglEnd();
  }
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  int covered = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) covered += ctx.at(x, y)[3] != 0;
  EXPECT_EQ(covered, 0);
  // The same call with valid values draws.
  pfglBegin(superquadric);
  pfglRastParam3fEXT(pfglGetParamNameEXT("radii"), 1, 1, 1);
  const GLfloat e[2] = {1, 1};
  pfglRastParamfvEXT(pfglGetParamNameEXT("exponents"), 2, e);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) covered += ctx.at(x, y)[3] != 0;
  EXPECT_GT(covered, 150);
}

}  // namespace
