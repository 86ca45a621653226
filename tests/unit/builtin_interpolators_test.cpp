// The built-in shared interpolators (primitives/interpolators/*.pfl): coordinate systems and
// solid textures, each bound to the colour of a GL quad on a tilted plane under a rotating,
// unevenly scaling modelview, and checked per pixel against the same formula evaluated here in
// double precision at the object-space point the pixel's ray meets (noise from the double form
// of the same improved Perlin noise).
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>

#include "compiler/perlin_noise.h"
#include "gl_context.h"

namespace {

constexpr int kN = 96;
constexpr double kPi = 3.141592653589793;

// The object-space plane z = 0.3 x + 0.2 y + 0.1 over [-1, 1]^2, drawn as one quad.
double planeZ(double x, double y) { return 0.3 * x + 0.2 * y + 0.1; }

glm::dmat4 modelview() {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.2, -0.1, -3.0));
  m = glm::rotate(m, glm::radians(30.0), glm::normalize(glm::dvec3(1, 0.5, 0.2)));
  return glm::scale(m, glm::dvec3(1.3, 0.9, 1.1));
}

// The object-space point of the plane under pixel (x + ox, y + oy), or false outside the quad
// (with a margin, so edge pixels are not judged).
bool objectPoint(double x, double y, glm::dvec3& out) {
  const glm::dmat4 inv = glm::inverse(modelview());
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;  // glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 10)
  const glm::dvec3 o = glm::dvec3(inv * glm::dvec4(0, 0, 0, 1));
  const glm::dvec3 d = glm::dvec3(inv * glm::dvec4(nx * 0.6, ny * 0.6, -1, 0));
  // o + t d on z = 0.3 x + 0.2 y + 0.1.
  const double t = (0.3 * o.x + 0.2 * o.y + 0.1 - o.z) / (d.z - 0.3 * d.x - 0.2 * d.y);
  out = o + t * d;
  return t > 0 && std::abs(out.x) < 0.95 && std::abs(out.y) < 0.95;
}

double snoise(const glm::dvec3& p) { return pf::perlinNoiseOf<double>(p.x, p.y, p.z); }

// The standard library's fbm and turbulence (compiler/stdlib.pfl), in double.
double fbm(const glm::dvec3& p, int octaves) {
  double sum = 0, amplitude = 0.5, frequency = 1;
  for (int i = 0; i < octaves; ++i, frequency *= 2, amplitude *= 0.5) sum += amplitude * snoise(p * frequency);
  return sum * 2;
}
double turbulence(const glm::dvec3& p, int octaves) {
  double sum = 0, amplitude = 0.5, frequency = 1;
  for (int i = 0; i < octaves; ++i, frequency *= 2, amplitude *= 0.5)
    sum += amplitude * std::abs(snoise(p * frequency));
  return sum;
}

// solid_textures.pfl's cell hash, with the language's wrapping ints.
double cellRandom(int x, int y, int z, int k) {
  uint32_t h = uint32_t(x) * 73856093u + uint32_t(y) * 19349663u + uint32_t(z) * 83492791u + uint32_t(k) * 1013904223u;
  h = h * 1103515245u + 12345u;
  h = h * 1103515245u + 12345u;
  const int32_t s = static_cast<int32_t>(h);
  return double(((s / 65536) % 32768 + 32768) % 32768) / 32768.0;
}

double worleyF1(const glm::dvec3& q) {
  const glm::dvec3 f = glm::floor(q);
  double f1 = 1e30;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = int(f.x) + dx, y = int(f.y) + dy, z = int(f.z) + dz;
        const glm::dvec3 feature(f.x + dx + cellRandom(x, y, z, 0), f.y + dy + cellRandom(x, y, z, 1),
                                 f.z + dz + cellRandom(x, y, z, 2));
        f1 = std::min(f1, glm::length(q - feature));
      }
  return f1;
}

double turnFraction(const glm::dvec3& p) { return std::atan2(p.y, p.x) / (2 * kPi) + 0.5; }

struct Case {
  const char* name;
  bool solid;   // a solid texture (texture_color0/1) or a coordinate system (texture_origin)
  double scale;
  glm::dvec3 origin;
  // The expected colour channels 0-2 at object point p (before clamping to [0, 1]).
  std::function<glm::dvec3(const glm::dvec3& p)> expected;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

const glm::dvec3 kColour0(1, 0, 0.25), kColour1(0, 1, 0.75);
glm::dvec3 mixColours(double s) { return kColour0 + (kColour1 - kColour0) * s; }

std::vector<Case> cases() {
  std::vector<Case> c;
  const glm::dvec3 origin(-1, -1, -1);
  c.push_back({"planar", false, 0.4, origin, [origin](const glm::dvec3& p) { return (p - origin) * 0.4; }});
  c.push_back({"cylindrical", false, 0.5, glm::dvec3(0.1, 0.2, -1), [](const glm::dvec3& p) {
                 const glm::dvec3 q = p - glm::dvec3(0.1, 0.2, -1);
                 return glm::dvec3(turnFraction(q), q.z * 0.5, std::hypot(q.x, q.y) * 0.5);
               }});
  c.push_back({"spherical", false, 0.4, glm::dvec3(0.1, 0.2, -0.2), [](const glm::dvec3& p) {
                 const glm::dvec3 q = p - glm::dvec3(0.1, 0.2, -0.2);
                 const double r = glm::length(q);
                 return glm::dvec3(turnFraction(q), std::acos(std::clamp(q.z / r, -1.0, 1.0)) / kPi, r * 0.4);
               }});
  c.push_back({"toroidal", false, 0.5, glm::dvec3(0.1, -0.2, 0.3), [](const glm::dvec3& p) {
                 // About the circle of radius 0.9 (major_radius) around the origin's z axis.
                 const glm::dvec3 q = p - glm::dvec3(0.1, -0.2, 0.3);
                 const double rho = std::hypot(q.x, q.y) - 0.9;
                 return glm::dvec3(turnFraction(q), std::atan2(q.z, rho) / (2 * kPi) + 0.5, std::hypot(rho, q.z) * 0.5);
               }});
  const glm::dvec3 none(0);
  c.push_back({"solid_noise", true, 3, none, [](const glm::dvec3& p) { return mixColours(0.5 + 0.5 * snoise(p * 3.0)); }});
  c.push_back({"solid_fbm", true, 2, none,
               [](const glm::dvec3& p) { return mixColours(std::clamp(0.5 + 0.5 * fbm(p * 2.0, 6), 0.0, 1.0)); }});
  c.push_back({"solid_turbulence", true, 2, none,
               [](const glm::dvec3& p) { return mixColours(std::clamp(turbulence(p * 2.0, 6), 0.0, 1.0)); }});
  c.push_back({"marble", true, 0.7, none, [](const glm::dvec3& p) {
                 const glm::dvec3 q = p * 0.7;
                 return mixColours(0.5 + 0.5 * std::sin(kPi * (q.x + 4 * turbulence(q, 6))));
               }});
  c.push_back({"wood", true, 4, none, [](const glm::dvec3& p) {
                 const glm::dvec3 q = p * 4.0;
                 const double r = std::hypot(q.x, q.y) + 0.3 * snoise(q);
                 return mixColours(r - std::floor(r));
               }});
  c.push_back({"worley", true, 3, none,
               [](const glm::dvec3& p) { return mixColours(std::clamp(worleyF1(p * 3.0), 0.0, 1.0)); }});
  c.push_back({"checker", true, 2.5, none, [](const glm::dvec3& p) {
                 const glm::dvec3 f = glm::floor(p * 2.5);
                 const double s = std::fmod(f.x + f.y + f.z, 2.0);
                 return mixColours(s < 0 ? s + 2 : s);
               }});
  return c;
}

int toByte(double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); }

class BuiltinInterpolators : public testing::TestWithParam<Case> {};

TEST_P(BuiltinInterpolators, MatchTheirFormulaInDoubleAtTheObjectPoint) {
  const Case& tc = GetParam();
  pf::test::GlContext c(kN, kN);
  const GLenum interp = pfglGetInterpolatorEXT(tc.name);
  ASSERT_GE(interp, static_cast<GLenum>(GL_FIRST_INTERPOLATOR_EXT)) << tc.name;
  pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), GL_QUADS, interp);
  pfglRastParamfEXT(pfglGetParamNameEXT("texture_scale"), static_cast<float>(tc.scale));
  pfglRastParamfEXT(pfglGetParamNameEXT("major_radius"), 0.9f);  // toroidal's
  if (tc.solid) {
    pfglRastParam4fEXT(pfglGetParamNameEXT("texture_color0"), 1, 0, 0.25f, 1);
    pfglRastParam4fEXT(pfglGetParamNameEXT("texture_color1"), 0, 1, 0.75f, 1);
  } else {
    pfglRastParam3fEXT(pfglGetParamNameEXT("texture_origin"), static_cast<float>(tc.origin.x),
                       static_cast<float>(tc.origin.y), static_cast<float>(tc.origin.z));
  }
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.6, 0.6, -0.6, 0.6, 1, 10);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.2, -0.1, -3.0);
  pfglRotated(30.0, 1, 0.5, 0.2);
  pfglScaled(1.3, 0.9, 1.1);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglBegin(GL_QUADS);
  const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const auto& v : corners) pfglVertex3d(v[0], v[1], planeZ(v[0], v[1]));
  pfglEnd();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));

  int checked = 0, undecided = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      glm::dvec3 p;
      if (!objectPoint(x + 0.5, y + 0.5, p)) continue;
      const glm::dvec3 want = tc.expected(p);
      // Where the pattern jumps within a twentieth of a pixel (a checker edge, a ring of wood,
      // the seam of an angle) float and double may land on different sides: not judged.
      bool jump = false;
      for (int k = 0; k < 4 && !jump; ++k) {
        glm::dvec3 q;
        objectPoint(x + 0.5 + (k % 2 ? 0.05 : -0.05), y + 0.5 + (k / 2 ? 0.05 : -0.05), q);
        const glm::dvec3 near = tc.expected(q);
        for (int ch = 0; ch < 3; ++ch) jump |= std::abs(toByte(near[ch]) - toByte(want[ch])) > 12;
      }
      if (jump) {
        ++undecided;
        continue;
      }
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(c.at(x, y)[ch], toByte(want[ch]), 2) << tc.name << " (" << x << ", " << y << ") channel " << ch;
      ++checked;
    }
  EXPECT_GT(checked, 2000) << tc.name;
  EXPECT_LT(undecided, checked / 10) << tc.name;
}

INSTANTIATE_TEST_SUITE_P(All, BuiltinInterpolators, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
