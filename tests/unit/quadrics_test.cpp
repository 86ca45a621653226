// The quadric primitives (primitives/quadrics.pfl): each shape drawn under a rotating, unevenly
// scaling modelview, its coverage and depth checked per pixel against a ray cast computed here
// in double precision. The reference knows nothing of quadric.pfl's coefficients: each shape is
// its pieces -- an implicit function written from the shape's definition and the region of
// space where that surface is part of the shape -- and along a ray each piece's function is a
// polynomial of degree <= 2, recovered exactly (in double) from three samples.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "gl_context.h"
#include "pixel_judging.h"

namespace {

constexpr int kN = 96;

struct Piece {
  std::function<double(const glm::dvec3&)> f;
  std::function<bool(const glm::dvec3&)> in_region;
};

struct Shape {
  const char* name;
  std::function<void()> draw;  // glBegin(...) ... glEnd() in object coordinates
  std::vector<Piece> pieces;
};

glm::dmat4 projection() { return glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0); }
glm::dmat4 modelview() {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.1, -0.05, -5));
  m = glm::rotate(m, glm::radians(50.0), glm::normalize(glm::dvec3(1, 0.3, 0.2)));
  return glm::scale(m, glm::dvec3(1.2, 0.8, 1.0));
}

// The nearest hit of the ray through window point (x, y) on the shape: window depth and the
// piece hit, or depth -1 for a miss.
std::pair<double, int> castRay(const Shape& s, double x, double y) {
  const glm::dmat4 inv = glm::inverse(projection() * modelview());
  const double nx = x / kN * 2 - 1, ny = y / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  const glm::dvec3 o = glm::dvec3(a) / a.w, d = glm::dvec3(b) / b.w - o;
  double best = 2;
  int piece = -1;
  for (size_t i = 0; i < s.pieces.size(); ++i) {
    const Piece& p = s.pieces[i];
    const double f0 = p.f(o), fh = p.f(o + 0.5 * d), f1 = p.f(o + d);
    const double qa = 2 * f1 - 4 * fh + 2 * f0, qb = f1 - f0 - qa, qc = f0;
    std::vector<double> roots;
    if (std::abs(qa) < 1e-12 * (std::abs(qb) + std::abs(qc))) {
      if (qb != 0) roots.push_back(-qc / qb);
    } else {
      const double disc = qb * qb - 4 * qa * qc;
      if (disc >= 0) {
        roots.push_back((-qb - std::sqrt(disc)) / (2 * qa));
        roots.push_back((-qb + std::sqrt(disc)) / (2 * qa));
      }
    }
    for (double t : roots)
      if (t >= 0 && t <= 1 && t < best && p.in_region(o + t * d)) best = t, piece = static_cast<int>(i);
  }
  if (piece < 0) return {-1, -1};
  const glm::dvec4 c = projection() * modelview() * glm::dvec4(o + best * d, 1);
  return {c.z / c.w * 0.5 + 0.5, piece};
}

GLuint param(const char* name) { return pfglGetParamNameEXT(name); }

void drawOne(const char* primitive, const std::function<void()>& set_params) {
  pfglBegin(pfglGetPrimitiveEXT(primitive));
  set_params();
  pfglSequencePointEXT();
  pfglEnd();
}

double sq(double v) { return v * v; }

std::vector<Shape> shapes() {
  std::vector<Shape> out;
  auto always = [](const glm::dvec3&) { return true; };
  {  // A saddle z = x^2 - y^2 in the unit box: the general quadric.
    const float k[10] = {1, -1, 0, 0, 0, 0, 0, 0, -0.5f, 0};
    auto box = [](const glm::dvec3& p) { return std::abs(p.x) <= 0.9 && std::abs(p.y) <= 0.8 && std::abs(p.z) <= 1; };
    out.push_back({"quadric",
                   [k] {
                     drawOne("quadric", [&] {
                       pfglRastParamfvEXT(param("coefficients"), 10, k);
                       pfglRastParam3fEXT(param("box_min"), -0.9f, -0.8f, -1);
                       pfglRastParam3fEXT(param("box_max"), 0.9f, 0.8f, 1);
                     });
                   },
                   {{[](const glm::dvec3& p) { return p.x * p.x - p.y * p.y - p.z; }, box}}});
  }
  {
    const glm::dvec3 c(0.1, 0.2, 0), r(1.0, 0.6, 0.8);
    out.push_back({"ellipsoid",
                   [=] {
                     drawOne("ellipsoid", [&] {
                       pfglRastParam3fEXT(param("center"), 0.1f, 0.2f, 0);
                       pfglRastParam3fEXT(param("radii"), 1.0f, 0.6f, 0.8f);
                     });
                   },
                   {{[=](const glm::dvec3& p) { return sq((p.x - c.x) / r.x) + sq((p.y - c.y) / r.y) + sq((p.z - c.z) / r.z) - 1; },
                     always}}});
  }
  const glm::dvec3 c(0.1, -0.1, -0.5);
  auto setCRH = [](double r, double h) {
    pfglRastParam3fEXT(param("center"), 0.1f, -0.1f, -0.5f);
    pfglRastParamfEXT(param("radius"), static_cast<float>(r));
    pfglRastParamfEXT(param("height"), static_cast<float>(h));
  };
  auto radial = [c](const glm::dvec3& p) { return sq(p.x - c.x) + sq(p.y - c.y); };
  auto capAt = [=](double z, double r) {
    return Piece{[z](const glm::dvec3& p) { return p.z - z; }, [=](const glm::dvec3& p) { return radial(p) <= r * r; }};
  };
  auto between = [c](double za, double zb) {
    return [=](const glm::dvec3& p) { return p.z - c.z >= za && p.z - c.z <= zb; };
  };
  {
    const double r = 0.7, h = 1.2;
    out.push_back({"cylinder", [=] { drawOne("cylinder", [&] { setCRH(r, h); }); },
                   {{[=](const glm::dvec3& p) { return radial(p) - r * r; }, between(0, h)}, capAt(c.z, r), capAt(c.z + h, r)}});
  }
  {
    const double r = 0.8, h = 1.1;
    out.push_back({"cone", [=] { drawOne("cone", [&] { setCRH(r, h); }); },
                   {{[=](const glm::dvec3& p) { return radial(p) - sq(r / h * (c.z + h - p.z)); }, between(0, h)},
                    capAt(c.z, r)}});
  }
  {
    const double r = 0.9, h = 1.3;
    out.push_back({"paraboloid", [=] { drawOne("paraboloid", [&] { setCRH(r, h); }); },
                   {{[=](const glm::dvec3& p) { return radial(p) - r * r / h * (p.z - c.z); }, between(0, h)}}});
  }
  {
    const double r = 0.4, h = 1.4, rt = 0.9;
    out.push_back({"hyperboloid",
                   [=] {
                     drawOne("hyperboloid", [&] {
                       setCRH(r, h);
                       pfglRastParamfEXT(param("top_radius"), static_cast<float>(rt));
                     });
                   },
                   // The radius grows from r at the waist to rt at z' = +-h/2, as sqrt(r^2 + k z'^2).
                   {{[=](const glm::dvec3& p) { return radial(p) - r * r - (rt * rt - r * r) * sq((p.z - c.z) / (h / 2)); },
                     between(-h / 2, h / 2)}}});
  }
  {  // A flared vase: x'^2 + y'^2 = 0.4 z'^2 + 0.16 for z' in [0, 1.2] (its widest radius, at
     // the top, is for the primitive to find).
    out.push_back({"revolution",
                   [] {
                     drawOne("revolution", [&] {
                       pfglRastParam3fEXT(param("center"), 0.1f, -0.1f, -0.5f);
                       const float profile[5] = {-0.4f, 0, -0.16f, 0, 1.2f};
                       pfglRastParamfvEXT(param("profile"), 5, profile);
                     });
                   },
                   {{[=](const glm::dvec3& p) { return radial(p) - 0.4 * sq(p.z - c.z) - 0.16; }, between(0, 1.2)}}});
  }
  {
    const double r = 0.9;
    out.push_back({"disk", [=] { drawOne("disk", [&] { setCRH(r, 0); }); }, {capAt(c.z, r)}});
  }
  return out;
}

void PrintTo(const Shape& s, std::ostream* os) { *os << s.name; }

class Quadrics : public testing::TestWithParam<Shape> {};

TEST_P(Quadrics, CoverageAndDepthMatchRayCastsInDouble) {
  const Shape& shape = GetParam();
  pf::test::GlContext c(kN, kN);
  ASSERT_NE(pfglGetPrimitiveEXT(shape.name), 0u);
  pfglMatrixMode(GL_PROJECTION);
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglTranslated(0.1, -0.05, -5);
  pfglRotated(50.0, 1, 0.3, 0.2);
  pfglScaled(1.2, 0.8, 1.0);
  pfglClearColor(0, 0, 0, 0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor3f(1, 1, 1);
  shape.draw();
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const float* depth = c.depth();
  ASSERT_NE(depth, nullptr);

  int hits = 0, misses = 0, undecided = 0;
  double max_depth_error = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const auto [z, piece] = castRay(shape, x + 0.5, y + 0.5);
      // Near a silhouette, a region's border or where two pieces meet, float and double may
      // decide differently: such pixels (another answer within 0.02 pixel) are not judged.
      const auto center_piece = piece;  // clang 14 cannot capture a structured binding
      if (pf::test::changesNear(x, y,
                                [&](double px, double py) { return castRay(shape, px, py).second != center_piece; })) {
        ++undecided;
        continue;
      }
      const bool drawn = c.at(x, y)[3] != 0;
      EXPECT_EQ(drawn, piece >= 0) << shape.name << " (" << x << ", " << y << ")";
      if (piece < 0) {
        ++misses;
        continue;
      }
      ++hits;
      const double err = std::abs(depth[size_t(y) * kN + x] - z);
      max_depth_error = std::max(max_depth_error, err);
      EXPECT_LT(err, 4e-6) << shape.name << " (" << x << ", " << y << ")";
    }
  EXPECT_GT(hits, 400) << shape.name;
  EXPECT_GT(misses, 600) << shape.name;
  EXPECT_LT(undecided, hits / 8) << shape.name;
  std::printf("  %s: %d pixels hit and judged, %d missed and judged, %d undecided; max depth error %.2g\n",
              shape.name, hits, misses, undecided, max_depth_error);
}

INSTANTIATE_TEST_SUITE_P(All, Quadrics, testing::ValuesIn(shapes()),
                         [](const testing::TestParamInfo<Shape>& info) { return std::string(info.param.name); });

}  // namespace
