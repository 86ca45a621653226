// The lighting commands' state and errors (GL 1.5 section 2.14 and its error rules), and the
// lighting equation against values computed here in double precision. (The images are compared
// with OSMesa in the differential tests.)
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <cmath>
#include <vector>

#include "raster/lighting.h"

namespace {

struct Ctx {
  PFcontext ctx;
  std::vector<unsigned char> px;
  Ctx() : ctx(pfCreateContext(GL_RGBA, 24)), px(4 * 4 * 4) { pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 4, 4); }
  ~Ctx() {
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
    pfDestroyContext(ctx);
  }
};

GLenum error() { return pfglGetError(); }

}  // namespace

TEST(Lighting, StateAndDefaults) {
  Ctx c;
  GLfloat v[4];
  pfglGetLightfv(GL_LIGHT0, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 1.0f);
  pfglGetLightfv(GL_LIGHT1, GL_DIFFUSE, v);
  EXPECT_EQ(v[0], 0.0f);
  pfglGetMaterialfv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_FLOAT_EQ(v[0], 0.2f);
  // A position is transformed by the modelview current when it is set.
  pfglTranslatef(1, 2, 3);
  const GLfloat pos[4] = {1, 0, 0, 1};
  pfglLightfv(GL_LIGHT2, GL_POSITION, pos);
  pfglGetLightfv(GL_LIGHT2, GL_POSITION, v);
  EXPECT_EQ(v[0], 2.0f);
  EXPECT_EQ(v[2], 3.0f);
  pfglEnable(GL_LIGHT2);
  EXPECT_EQ(pfglIsEnabled(GL_LIGHT2), GL_TRUE);
  GLint n;
  pfglGetIntegerv(GL_MAX_LIGHTS, &n);
  EXPECT_EQ(n, 8);
  // GL_COLOR_MATERIAL: glColor writes the tracked material properties.
  pfglColorMaterial(GL_BACK, GL_EMISSION);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglColor3f(0.5f, 0.25f, 0.125f);
  pfglGetMaterialfv(GL_BACK, GL_EMISSION, v);
  EXPECT_EQ(v[1], 0.25f);
  pfglGetMaterialfv(GL_FRONT, GL_EMISSION, v);
  EXPECT_EQ(v[1], 0.0f);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST(Lighting, Errors) {
  Ctx c;
  pfglLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglLightf(GL_LIGHT0, GL_AMBIENT, 1);  // a vector parameter through the scalar form
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 120);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglMaterialf(GL_FRONT, GL_SHININESS, 200);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_VALUE));
  pfglMaterialf(GL_FRONT, GL_DIFFUSE, 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglMaterialfv(GL_LEFT, GL_DIFFUSE, nullptr);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglLightModelf(GL_LIGHT_MODEL_AMBIENT, 1);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglColorMaterial(GL_FRONT, GL_SHININESS);
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_ENUM));
  pfglLightfv(GL_LIGHT0, GL_DIFFUSE, nullptr);  // NULL: ignored
  EXPECT_EQ(error(), static_cast<GLenum>(GL_NO_ERROR));
  pfglBegin(GL_TRIANGLES);
  const GLfloat red[4] = {1, 0, 0, 1};
  pfglMaterialfv(GL_FRONT, GL_DIFFUSE, red);  // allowed inside glBegin
  pfglLightfv(GL_LIGHT0, GL_DIFFUSE, red);    // not allowed
  pfglEnd();
  EXPECT_EQ(error(), static_cast<GLenum>(GL_INVALID_OPERATION));
  GLfloat v[4];
  pfglGetMaterialfv(GL_FRONT, GL_DIFFUSE, v);
  EXPECT_EQ(v[1], 0.0f);
}

// The equation, for one light of each kind, against GL 1.5's formula evaluated in double here.
TEST(Lighting, EquationMatchesTheSpecification) {
  pf::LightingState s;
  s.lights[0].enabled = true;
  s.lights[0].position = glm::vec4(1, 2, 2, 1);
  s.lights[0].spot_direction = glm::vec3(-1, -2, -2);
  s.lights[0].spot_cutoff = 30;
  s.lights[0].spot_exponent = 3;
  s.lights[0].linear_attenuation = 0.5f;
  s.material[0].specular = glm::vec4(0.5f, 0.5f, 0.5f, 1);
  s.material[0].shininess = 10;
  s.material[0].diffuse.a = 0.5f;  // the colour's alpha is the diffuse material's
  s.local_viewer = true;
  const glm::vec3 eye(0.1f, -0.2f, -1.0f), n(0, 0, 1);
  glm::vec4 got = pf::litColor(s, eye, n, 0);
  // Reference.
  double vp[3] = {1 - 0.1, 2 + 0.2, 2 + 1.0}, d = std::sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2]);
  for (double& x : vp) x /= d;
  double att = 1.0 / (1.0 + 0.5 * d);
  double sd = std::sqrt(9.0), spot_cos = (vp[0] * 1 + vp[1] * 2 + vp[2] * 2) / sd;
  double spot = spot_cos >= std::cos(30 * M_PI / 180) ? std::pow(spot_cos, 3) : 0;
  double ndotvp = std::max(vp[2], 0.0);
  double el = std::sqrt(0.01 + 0.04 + 1.0), h[3] = {vp[0] - 0.1 / el, vp[1] + 0.2 / el, vp[2] + 1.0 / el};
  double hl = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
  double spec = std::pow(std::max(h[2] / hl, 0.0), 10);
  double want = 0.2 * 0.2 + att * spot * (0.2 * 0.0 + ndotvp * 0.8 * 1.0 + spec * 0.5 * 1.0);
  EXPECT_GT(spot, 0.5) << "the vertex is inside the cone";
  EXPECT_NEAR(got.r, want, 1e-5);
  EXPECT_FLOAT_EQ(got.a, 0.5f);
  // The back face: the normal reversed, facing away from the light: ambient only.
  glm::vec4 back = pf::litColor(s, eye, n, 1);
  EXPECT_NEAR(back.r, 0.2 * 0.2, 1e-6);
}
