// The built-in implicit primitive (primitives/implicit.pfl) through the API: a field compiled
// from Fidget text, drawn by every method under a perspective projection and a rotating,
// unevenly scaling modelview -- coverage and window depth against ray casts in double through
// the same matrices -- meeting a GL quad correctly in the Z-buffer; and the API's errors.
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

#include "gl_context.h"

namespace {

constexpr int kN = 64;
constexpr double kRadius = 0.9;

// Fidget text (negative inside): x^2 + y^2 + z^2 - 0.81.
constexpr const char* kSphereVm =
    "x var-x\ny var-y\nz var-z\nx2 square x\ny2 square y\nz2 square z\ns add x2 y2\nr2 add s z2\n"
    "c const 0.81\nout sub r2 c\n";

glm::dmat4 modelview() {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0.2, -0.1, -4.5));
  m = glm::rotate(m, glm::radians(30.0), glm::normalize(glm::dvec3(1, 2, 0)));
  return glm::scale(m, glm::dvec3(1.2, 0.7, 1.0));
}
const glm::dmat4 kProjection = glm::frustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);

void loadMatrices() {
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
  pfglMatrixMode(GL_MODELVIEW);
  pfglLoadIdentity();
  pfglTranslated(0.2, -0.1, -4.5);
  pfglRotated(30.0, 1, 2, 0);
  pfglScaled(1.2, 0.7, 1.0);
}

// The object-space ray of pixel (x, y): origin on the near plane, direction to the far plane.
void pixelRay(int x, int y, glm::dvec3& o, glm::dvec3& d) {
  const glm::dmat4 inv = glm::inverse(kProjection * modelview());
  const double nx = (x + 0.5) / kN * 2 - 1, ny = (y + 0.5) / kN * 2 - 1;
  const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1, 1), b = inv * glm::dvec4(nx, ny, 1, 1);
  o = glm::dvec3(a) / a.w;
  d = glm::dvec3(b) / b.w - o;
}

double windowDepth(const glm::dvec3& p) {
  const glm::dvec4 clip = kProjection * modelview() * glm::dvec4(p, 1);
  return clip.z / clip.w * 0.5 + 0.5;
}

// Window depth of the sphere on pixel (x, y); -1 for a miss; -2 near the rim (no sure verdict).
double sphereDepth(int x, int y) {
  glm::dvec3 o, d;
  pixelRay(x, y, o, d);
  const double qa = glm::dot(d, d), qb = glm::dot(o, d), qc = glm::dot(o, o) - kRadius * kRadius;
  const double disc = qb * qb - qa * qc;
  if (std::fabs(disc) < 1e-4 * qa) return -2;
  if (disc < 0) return -1;
  return windowDepth(o + d * ((-qb - std::sqrt(disc)) / qa));
}

GLuint compileSphere() {
  const GLuint id = pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "sphere.vm", kSphereVm, 2.0f * 1.75f);
  EXPECT_NE(id, 0u);
  return id;
}

void drawImplicit(GLuint field, float method, float steps) {
  const GLuint f = pfglGetParamNameEXT("field"), lo = pfglGetParamNameEXT("box_min"),
               hi = pfglGetParamNameEXT("box_max"), m = pfglGetParamNameEXT("method"), s = pfglGetParamNameEXT("steps");
  pfglBegin(pfglGetPrimitiveEXT("implicit"));
  pfglRastParamfEXT(f, static_cast<float>(field));
  pfglRastParam3fEXT(lo, -1, -1, -1);
  pfglRastParam3fEXT(hi, 1, 1, 1);
  pfglRastParamfEXT(m, method);
  pfglRastParamfEXT(s, steps);
  pfglSequencePointEXT();
  pfglEnd();
}

// Draws `field` with `method` and checks coverage and window depth against the double sphere.
void expectSphereImage(const pf::test::GlContext& gl, GLuint field, float method) {
  loadMatrices();
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor3f(0.2f, 0.8f, 0.4f);
  drawImplicit(field, method, method == 3.0f ? 128.0f : 0.0f);
  pfglFinish();
  ASSERT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  const float* depth = gl.depth();
  int judged = 0, hits = 0;
  double max_err = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const double want = sphereDepth(x, y);
      if (want == -2) continue;
      ++judged;
      const bool drawn = gl.at(x, y)[1] != 0;
      ASSERT_EQ(drawn, want >= 0) << "pixel " << x << ", " << y;
      if (!drawn) continue;
      ++hits;
      max_err = std::max(max_err, std::fabs(depth[y * kN + x] - want));
    }
  std::printf("implicit method %g: %d judged, %d hits, max window-depth error %.3g\n", method, judged, hits, max_err);
  EXPECT_GT(hits, 400);
  EXPECT_LT(max_err, 2e-6);
}

TEST(Implicit, EveryMethodMatchesRayCastsInDouble) {
  for (float method : {0.0f, 1.0f, 2.0f, 3.0f, 4.0f}) {
    SCOPED_TRACE(method);
    pf::test::GlContext gl(kN, kN);
    expectSphereImage(gl, compileSphere(), method);
  }
}

// The same sphere as a field unit of the language whose radius is its parameter (HyperFun's
// library: hfSphere), drawn by the polynomial (auto) and the interval method.
TEST(Implicit, LanguageFieldsTakeTheirParameters) {
  const char* source =
      "field float other(point p) { return p.x; }\n"
      "field float ball(point p, float r) { return hfSphere(p, point(0.0, 0.0, 0.0), r); }\n";
  for (float method : {0.0f, 2.0f}) {
    SCOPED_TRACE(method);
    pf::test::GlContext gl(kN, kN);
    const GLdouble radius = kRadius;
    const GLuint field = pfglCompileFieldParamsEXT(GL_FIELD_LANGUAGE_EXT, "ball", source, 0.0f, 0.0, 1, &radius);
    ASSERT_NE(field, 0u);
    expectSphereImage(gl, field, method);
  }
  pf::test::GlContext gl(8, 8);
  char log[1024];
  EXPECT_EQ(pfglCompileFieldParamsEXT(GL_FIELD_LANGUAGE_EXT, "ball", source, 0.0f, 0.0, 0, nullptr), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));
  pfglGetFieldLogEXT(0, sizeof log, nullptr, log);
  EXPECT_NE(std::string(log).find("ball:2:1: error: field 'ball' takes 1 parameter value after its point; 0 given"),
            std::string::npos) << log;
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_LANGUAGE_EXT, "f", "field float f(point p) {\n  return floor(p.x);\n}\n", 0.0f), 0u);
  pfglGetFieldLogEXT(0, sizeof log, nullptr, log);
  EXPECT_NE(std::string(log).find("f:2:10: error: 'floor (and fract, mod)' of a value that depends on the field's point"),
            std::string::npos) << log;
  const GLdouble one = 1.0;  // a language field has no time
  EXPECT_EQ(pfglCompileFieldParamsEXT(GL_FIELD_LANGUAGE_EXT, "ball", source, 0.0f, 0.5, 1, &one), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
}

// The plane x = 0 of object space as a GL quad, red, through the sphere (green): each pixel
// shows whichever is nearer, as the double ray casts say.
TEST(Implicit, MeetsGlGeometryInOneZBuffer) {
  pf::test::GlContext gl(kN, kN);
  const GLuint field = compileSphere();
  loadMatrices();
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  pfglColor3f(0.0f, 1.0f, 0.0f);
  drawImplicit(field, 2.0f, 0.0f);
  pfglColor3f(1.0f, 0.0f, 0.0f);
  pfglBegin(GL_QUADS);
  pfglVertex3f(0.0f, -1.5f, -1.5f);
  pfglVertex3f(0.0f, 1.5f, -1.5f);
  pfglVertex3f(0.0f, 1.5f, 1.5f);
  pfglVertex3f(0.0f, -1.5f, 1.5f);
  pfglEnd();
  pfglFinish();
  int sphere_wins = 0, plane_wins = 0;
  for (int y = 0; y < kN; ++y)
    for (int x = 0; x < kN; ++x) {
      const double s = sphereDepth(x, y);
      glm::dvec3 o, d;
      pixelRay(x, y, o, d);
      const double t = -o.x / d.x;
      const glm::dvec3 q = o + d * t;
      if (s < 0 || std::fabs(q.y) > 1.45 || std::fabs(q.z) > 1.45) continue;  // need both, away from edges
      const double p = windowDepth(q);
      if (std::fabs(p - s) < 1e-5) continue;  // where they cross
      const unsigned char* c = gl.at(x, y);
      if (s < p) {
        EXPECT_TRUE(c[1] > 0 && c[0] == 0) << "pixel " << x << ", " << y << ": the sphere is nearer";
        ++sphere_wins;
      } else {
        EXPECT_TRUE(c[0] > 0 && c[1] == 0) << "pixel " << x << ", " << y << ": the plane is nearer";
        ++plane_wins;
      }
    }
  EXPECT_GT(sphere_wins, 100);
  EXPECT_GT(plane_wins, 100);
}

TEST(Implicit, CompileErrorsAndBadArguments) {
  pf::test::GlContext gl(8, 8);
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "bad.vm", "x var-x\ny frobnicate x\n", 0.0f), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_NO_ERROR));  // a compile failure is not a GL error
  char log[512];
  GLsizei length = 0;
  pfglGetFieldLogEXT(0, sizeof log, &length, log);
  EXPECT_NE(std::string(log).find("bad.vm:2:3: error: unsupported operation 'frobnicate'"), std::string::npos) << log;
  EXPECT_EQ(pfglCompileFieldEXT(0x1234, "x.vm", kSphereVm, 0.0f), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "x.vm", nullptr, 0.0f), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "x.vm", kSphereVm, -1.0f), 0u);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "x.vm", kSphereVm, 0.0f), 1u);
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "y.vm", kSphereVm, 0.0f), 2u);
  pfglGetFieldLogEXT(3, sizeof log, &length, log);
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglBegin(GL_TRIANGLES);
  EXPECT_EQ(pfglCompileFieldEXT(GL_FIELD_FIDGET_EXT, "x.vm", kSphereVm, 0.0f), 0u);
  pfglEnd();
  EXPECT_EQ(pfglGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

}  // namespace
