// Natural interpolation (paper section 3.2; docs/language.md, "A label that names a shared
// interpolator"): a shape bound to the shared `spherical`, `cylindrical` or `toroidal`
// interpolator fills it with its *own* coordinates -- about the sphere's centre, the torus's
// circle, the quadric's box -- instead of running the interpolator about its texture_origin.
// Each shape is drawn under a rotating, unevenly scaling modelview with the coordinates bound to
// the colour, and every judged pixel is checked against the coordinates computed here in double
// at the object-space point where the pixel's ray meets the shape. The interpolators'
// parameters are set to values that would give other colours if the shared programs ran.
// Also: a user's primitive naming a user's interpolator, in both execution modes, and the
// compile errors of the construct.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "compile_helpers.h"
#include "gl_context.h"
#include "pixel_judging.h"

namespace {

constexpr int kN = 96;
constexpr double kPi = 3.141592653589793;

glm::dmat4 projection() { return glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0); }
// Uneven scale, or (for sphere_impostors, made for similarity modelviews) an even one.
glm::dvec3 scaleOf(bool similarity) { return similarity ? glm::dvec3(1.1) : glm::dvec3(1.15, 0.9, 1.05); }
glm::dmat4 modelview(bool similarity) {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.1, -0.05, -4.0));
  m = glm::rotate(m, glm::radians(35.0), glm::normalize(glm::dvec3(1, 0.4, 0.1)));
  return glm::scale(m, scaleOf(similarity));
}

// The coordinate systems of compiler/stdlib.pfl, in double.
double turn(const glm::dvec3& q) { return std::atan2(q.y, q.x) / (2 * kPi) + 0.5; }
glm::dvec3 cylindrical(const glm::dvec3& q) { return {turn(q), q.z, std::hypot(q.x, q.y)}; }
glm::dvec3 spherical(const glm::dvec3& q) {
  const double r = glm::length(q);
  return {turn(q), r > 0 ? std::acos(std::clamp(q.z / r, -1.0, 1.0)) / kPi : 0.0, r};
}
glm::dvec3 toroidal(const glm::dvec3& q, double ring) {
  const double rho = std::hypot(q.x, q.y) - ring;
  return {turn(q), std::atan2(q.z, rho) / (2 * kPi) + 0.5, std::hypot(rho, q.z)};
}

struct Ray {
  glm::dvec3 o, d;  // object space, t = 0 at the near plane and 1 at the far
};

Ray pixelRay(double x, double y, bool similarity) {
  const glm::dmat4 inv = glm::inverse(projection() * modelview(similarity));
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w;
  return {o, glm::dvec3(b) / b.w - o};
}

// The first root of a u^2 + 2 b u + c in [0, 1] whose point passes `keep`.
std::optional<double> quadraticHit(double a, double b, double c, const Ray& r,
                                   const std::function<bool(const glm::dvec3&)>& keep) {
  const double disc = b * b - a * c;
  if (disc < 0 || a == 0) return std::nullopt;
  for (double t : {(-b - std::sqrt(disc)) / a, (-b + std::sqrt(disc)) / a})
    if (t >= 0 && t <= 1 && keep(r.o + r.d * t)) return t;
  return std::nullopt;
}

struct Case {
  const char* name;
  const char* interpolator;
  std::function<void()> draw;                              // the GL calls between clear and finish
  std::function<std::optional<double>(const Ray&)> hit;    // the first hit's t, in double
  std::function<glm::dvec3(const glm::dvec3&)> expected;   // colour channels 0-2 at the hit
  bool similarity = false;                                 // an evenly scaling modelview
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const glm::dvec3 kCentre(0.15, -0.1, 0.05);

void param3(const char* name, double x, double y, double z) {
  pfglRastParam3fEXT(pfglGetParamNameEXT(name), static_cast<float>(x), static_cast<float>(y), static_cast<float>(z));
}

// The quadric x^2 + y^2 = r^2 (a cylinder about the object z axis through kCentre) in the box
// kCentre +- (r + 0.05, r + 0.05, h / 2), or the sphere |p - kCentre| = r in a box around it:
// `quadric`'s coefficients for both.
void drawQuadric(bool cylinder, double r, double h) {
  const glm::dvec3 c = kCentre;
  // f = |p - c|^2 - r^2 (sphere) or with z left out (cylinder), as Q's ten entries.
  const double qzz = cylinder ? 0 : 1;
  const float coefficients[10] = {1, 1, static_cast<float>(qzz), 0, 0, 0, static_cast<float>(-c.x),
                                  static_cast<float>(-c.y), static_cast<float>(-qzz * c.z),
                                  static_cast<float>(c.x * c.x + c.y * c.y + qzz * c.z * c.z - r * r)};
  pfglBegin(pfglGetPrimitiveEXT("quadric"));
  pfglRastParamfvEXT(pfglGetParamNameEXT("coefficients"), 10, coefficients);
  const glm::dvec3 half = cylinder ? glm::dvec3(r + 0.05, r + 0.05, h / 2) : glm::dvec3(r + 0.05);
  param3("box_min", c.x - half.x, c.y - half.y, c.z - half.z);
  param3("box_max", c.x + half.x, c.y + half.y, c.z + half.z);
  pfglSequencePointEXT();
  pfglEnd();
}

// One sphere of radius r around kCentre, by `primitive` (sphere or sphere_impostors).
void drawSphere(const char* primitive, double r) {
  pfglBegin(pfglGetPrimitiveEXT(primitive));
  pfglRastParamfEXT(pfglGetParamNameEXT("radius"), static_cast<float>(r));
  param3("center", kCentre.x, kCentre.y, kCentre.z);
  pfglSequencePointEXT();
  pfglEnd();
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const double r = 0.8;
  // The sphere |p - kCentre| = r, however it is drawn, and its spherical coordinates.
  auto sphereHit = [=](const Ray& ray) {
    const glm::dvec3 oc = ray.o - kCentre;
    return quadraticHit(glm::dot(ray.d, ray.d), glm::dot(oc, ray.d), glm::dot(oc, oc) - r * r, ray,
                        [](const glm::dvec3&) { return true; });
  };
  auto aboutCentre = [](const glm::dvec3& p) { return spherical(p - kCentre); };
  out.push_back({"sphere", "spherical", [=] { drawSphere("sphere", r); }, sphereHit, aboutCentre});
  out.push_back({"sphere_impostors", "spherical", [=] { drawSphere("sphere_impostors", r); }, sphereHit, aboutCentre,
                 true});
  const double ring = 0.7, tube = 0.25;
  out.push_back({"torus", "toroidal",
                 [=] {
                   pfglBegin(pfglGetPrimitiveEXT("torus"));
                   param3("center", kCentre.x, kCentre.y, kCentre.z);
                   pfglRastParamfEXT(pfglGetParamNameEXT("radius"), static_cast<float>(ring));
                   pfglRastParamfEXT(pfglGetParamNameEXT("tube_radius"), static_cast<float>(tube));
                   pfglSequencePointEXT();
                   pfglEnd();
                 },
                 [=](const Ray& ray) -> std::optional<double> {
                   // Dense march for the first sign change of the tube distance, then bisection,
                   // over the part of the ray inside the torus's bounding sphere.
                   auto f = [&](double t) {
                     const glm::dvec3 q = ray.o + ray.d * t - kCentre;
                     return std::hypot(std::hypot(q.x, q.y) - ring, q.z) - tube;
                   };
                   const glm::dvec3 oc = ray.o - kCentre;
                   const double a = glm::dot(ray.d, ray.d), b = glm::dot(oc, ray.d);
                   const double disc = b * b - a * (glm::dot(oc, oc) - (ring + tube) * (ring + tube));
                   if (disc <= 0) return std::nullopt;
                   const double t0 = std::max(0.0, (-b - std::sqrt(disc)) / a), t1 = std::min(1.0, (-b + std::sqrt(disc)) / a);
                   if (t0 >= t1) return std::nullopt;
                   const int steps = 4000;
                   double prev = f(t0);
                   for (int i = 1; i <= steps; ++i) {
                     double lo = t0 + (t1 - t0) * (i - 1) / steps, hi = t0 + (t1 - t0) * i / steps;
                     const double cur = f(hi);
                     if ((prev > 0) != (cur > 0)) {
                       for (int k = 0; k < 60; ++k) {
                         const double mid = 0.5 * (lo + hi);
                         ((f(mid) > 0) == (f(lo) > 0) ? lo : hi) = mid;
                       }
                       return 0.5 * (lo + hi);
                     }
                     prev = cur;
                   }
                   return std::nullopt;
                 },
                 [=](const glm::dvec3& p) { return toroidal(p - kCentre, ring); }});
  const double cr = 0.6, height = 1.2;
  out.push_back({"quadric_cylinder", "cylindrical", [=] { drawQuadric(true, cr, height); },
                 [=](const Ray& ray) {
                   const glm::dvec3 oc = ray.o - kCentre;
                   const double a = ray.d.x * ray.d.x + ray.d.y * ray.d.y, b = oc.x * ray.d.x + oc.y * ray.d.y;
                   return quadraticHit(a, b, oc.x * oc.x + oc.y * oc.y - cr * cr, ray, [=](const glm::dvec3& p) {
                     return std::abs(p.z - kCentre.z) <= height / 2;
                   });
                 },
                 // About the box's axis, from its bottom: v is the height above it (<= 1.2).
                 [=](const glm::dvec3& p) { return cylindrical(p - kCentre + glm::dvec3(0, 0, height / 2)); }});
  out.push_back({"quadric_sphere", "spherical", [=] { drawQuadric(false, r, 0); }, sphereHit, aboutCentre});
  out.push_back({"disk", "cylindrical",
                 [=] {
                   pfglBegin(pfglGetPrimitiveEXT("disk"));
                   param3("center", kCentre.x, kCentre.y, kCentre.z);
                   pfglRastParamfEXT(pfglGetParamNameEXT("radius"), static_cast<float>(r));
                   pfglSequencePointEXT();
                   pfglEnd();
                 },
                 [=](const Ray& ray) -> std::optional<double> {
                   const double t = (kCentre.z - ray.o.z) / ray.d.z;
                   const glm::dvec3 p = ray.o + ray.d * t;
                   if (t < 0 || t > 1 || std::hypot(p.x - kCentre.x, p.y - kCentre.y) > r) return std::nullopt;
                   return t;
                 },
                 [](const glm::dvec3& p) { return cylindrical(p - kCentre); }});
  return out;
}

int toByte(double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); }

class NaturalInterpolators : public testing::TestWithParam<Case> {};

TEST_P(NaturalInterpolators, ShapeGivesItsOwnCoordinatesInDouble) {
  const Case& tc = GetParam();
  pf::test::GlContext c(kN, kN);
  const GLenum interp = pfglGetInterpolatorEXT(tc.interpolator);
  ASSERT_GE(interp, static_cast<GLenum>(GL_FIRST_INTERPOLATOR_EXT)) << tc.interpolator;
  // Bound for every mode the shapes are drawn in (the quadric's own, and the disk's).
  for (const char* prim : {"sphere", "sphere_impostors", "torus", "quadric", "disk"})
    pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), pfglGetPrimitiveEXT(prim), interp);
  // What the shared programs would use: far from the shapes' own origins and radii.
  param3("texture_origin", 3.0, -2.0, 1.0);
  pfglRastParamfEXT(pfglGetParamNameEXT("texture_scale"), 0.25f);
  pfglRastParamfEXT(pfglGetParamNameEXT("major_radius"), 2.0f);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.1, -0.05, -4.0);
  pfglRotated(35.0, 1, 0.4, 0.1);
  const glm::dvec3 scale = scaleOf(tc.similarity);
  pfglScaled(scale.x, scale.y, scale.z);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  tc.draw();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));

  int checked = 0, undecided = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      auto colourAt = [&](double px, double py) -> std::optional<glm::dvec3> {
        const Ray ray = pixelRay(px, py, tc.similarity);
        const std::optional<double> t = tc.hit(ray);
        if (!t) return std::nullopt;
        return tc.expected(ray.o + ray.d * *t);
      };
      const std::optional<glm::dvec3> want = colourAt(x + 0.5, y + 0.5);
      // Silhouettes, and seams of an angle (a jump within a twentieth of a pixel), not judged.
      const bool unsure = pf::test::changesNear(
          x, y,
          [&](double px, double py) {
            const std::optional<glm::dvec3> near = colourAt(px, py);
            if (near.has_value() != want.has_value()) return true;
            if (!near) return false;
            for (int ch = 0; ch < 3; ++ch)
              if (std::abs(toByte((*near)[ch]) - toByte((*want)[ch])) > 12) return true;
            return false;
          },
          0.05);
      if (unsure) {
        ++undecided;
        continue;
      }
      if (!want) {
        EXPECT_EQ(c.at(x, y)[3], 0) << tc.name << ": drawn at (" << x << ", " << y << ") where the shape is not";
        continue;
      }
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(c.at(x, y)[ch], toByte((*want)[ch]), 2) << tc.name << " (" << x << ", " << y << ") channel " << ch;
      ++checked;
    }
  EXPECT_GT(checked, 800) << tc.name;
  EXPECT_LT(undecided, checked / 5) << tc.name;
}

INSTANTIATE_TEST_SUITE_P(Shapes, NaturalInterpolators, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

// A user's interpolator and a user's primitive that computes it itself: the primitive's branch
// fills the channels bound to it (here on one 8x8 block, in both execution modes); a layout
// without that interpolator skips the branch.
const char* kUserSource =
    "interpolator stripes(float k) { interpolator_return(color(sin(P.x * k), 0.0, 0.0, 1.0)); }\n"
    "primitive square(interpolator_data interp_data[1]; varying float X, Y; inout varying float Z) {\n"
    "  if (X > 6.0) return;\n"
    "  Z = 0.5;\n"
    "  interpolation {\n"
    "  perspective_linear:\n"
    "  linear:\n"
    "    interpolator_return(interp_data[0]);\n"
    "  stripes:\n"
    "    if (Y < 4.0) interpolator_return(color(X * 0.125, Y * 0.125, 0.25, 1.0));\n"
    "  default:\n"
    "    interpolator_return;\n"
    "  }\n"
    "}\n";

TEST(NaturalInterpolatorsLanguage, BranchFillsTheNamedInterpolatorsChannels) {
  pf::test::Compiled c = pf::test::compile(kUserSource);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const pf::CompiledPrimitive* square = c.find("square");
  ASSERT_NE(square, nullptr);
  ASSERT_EQ(square->named_interpolators, std::vector<std::string>{"stripes"});
  ASSERT_EQ(c.module.interpolators.size(), 1u);
  // Channels 0-3: bound to `stripes` (the Shared kind).
  pf::ChannelLayout layout;
  layout.count = 4;
  layout.kind_begin[static_cast<int>(pf::InterpKind::Shared)] = 0;
  layout.kind_end[static_cast<int>(pf::InterpKind::Shared)] = 4;
  layout.gbuffer_slot = {0, 1, 2, 3};
  layout.shared.push_back({c.module.interpolators[0].get(), 0, 0});
  const pf::test::BlockRun r = pf::test::runBlockIn(*square, {}, std::vector<float>(4, 0.0f), layout);
  int judged = 0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      ASSERT_EQ(r.drawn(x, y), x + 0.5 <= 6.0) << x << ", " << y;
      if (!r.drawn(x, y)) continue;
      // Rows below 4: the branch's value; the others leave the branch without one: zeros.
      const bool set = y + 0.5 < 4.0;
      EXPECT_EQ(r.channel(0, x, y), set ? (x + 0.5f) * 0.125f : 0.0f);
      EXPECT_EQ(r.channel(1, x, y), set ? (y + 0.5f) * 0.125f : 0.0f);
      EXPECT_EQ(r.channel(2, x, y), set ? 0.25f : 0.0f);
      EXPECT_EQ(r.channel(3, x, y), set ? 1.0f : 0.0f);
      ++judged;
    }
  EXPECT_EQ(judged, 48);
}

void expectError(const std::string& source, const std::string& message) {
  pf::test::Compiled c = pf::test::compile(source);
  EXPECT_FALSE(c.ok) << source;
  EXPECT_NE(c.diagnostics.find(message), std::string::npos) << c.diagnostics;
}

std::string primitiveWith(const std::string& interpolation) {
  return "interpolator stripes(float k) { interpolator_return(P.x * k); }\n"
         "primitive p(interpolator_data interp_data[1]; varying float X, Y; inout varying float Z) {\n"
         "  Z = 0.5;\n  interpolation {\n" +
         interpolation + "  }\n}\n";
}

TEST(NaturalInterpolatorsLanguage, Errors) {
  expectError(primitiveWith("  stripez:\n    interpolator_return(1.0);\n"),
              "test.pfl:5:3: error: 'stripez' is not a shared interpolator");
  expectError(primitiveWith("  stripes:\n  linear:\n    interpolator_return(interp_data[0]);\n"),
              "cannot share its body with 'linear'");
  expectError(primitiveWith("  stripes:\n    interpolator_return;\n"),
              "in the 'stripes:' branch, interpolator_return takes the interpolator's value");
  expectError(primitiveWith("  stripes:\n    interpolator_return(interp_data[0]);\n"),
              "returns the value of interpolator 'stripes'");
  expectError(primitiveWith("  stripes:\n    interpolator_return(1.0);\n  stripes:\n    interpolator_return(2.0);\n"),
              "interpolation label 'stripes' appears twice");
  // Defined after the primitive: not known yet where the label is.
  expectError("primitive p(interpolator_data interp_data[1]; varying float X, Y; inout varying float Z) {\n"
              "  Z = 0.5;\n  interpolation {\n  later:\n    interpolator_return(1.0);\n  }\n}\n"
              "interpolator later(float k) { interpolator_return(k); }\n",
              "'later' is not a shared interpolator");
}

}  // namespace
