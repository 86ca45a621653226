// The lighting commands' state and errors (GL 1.5 section 2.14 and its error rules), and the
// lighting equation against values computed here in double precision, and the shading pass's
// prepared form of it against the equation written out. (The images are compared with OSMesa in
// the differential tests.)
#include <gtest/gtest.h>

#include <primflow/gl.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>
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

namespace {

// GL 1.5's equation (section 2.14.1) written out directly, term by term, in float: what the
// shading pass's LightingEquation must reproduce to the bit while working out per state what
// does not depend on the point.
glm::vec4 directEquation(const pf::LightingState& s, const pf::Material& m, const glm::vec3& eye, const glm::vec3& n) {
  glm::vec3 c = glm::vec3(m.emission) + glm::vec3(m.ambient) * glm::vec3(s.model_ambient);
  for (const pf::Light& l : s.lights) {
    if (!l.enabled) continue;
    glm::vec3 vp;
    float attenuation = 1.0f;
    if (l.position.w != 0.0f) {
      glm::vec3 d = glm::vec3(l.position) / l.position.w - eye;
      float dist = glm::length(d);
      vp = dist > 0 ? d / dist : glm::vec3(0);
      float k = l.constant_attenuation + l.linear_attenuation * dist + l.quadratic_attenuation * dist * dist;
      attenuation = k > 0 ? 1.0f / k : 0.0f;
    } else {
      vp = glm::length(glm::vec3(l.position)) > 0 ? glm::normalize(glm::vec3(l.position)) : glm::vec3(0);
    }
    float spot = 1.0f;
    if (l.spot_cutoff != 180.0f) {
      glm::vec3 sd = glm::length(l.spot_direction) > 0 ? glm::normalize(l.spot_direction) : glm::vec3(0);
      float cos_angle = std::max(glm::dot(-vp, sd), 0.0f);
      spot = cos_angle >= std::cos(glm::radians(l.spot_cutoff)) ? std::pow(cos_angle, l.spot_exponent) : 0.0f;
    }
    const float n_dot_vp = std::max(glm::dot(n, vp), 0.0f);
    glm::vec3 term = glm::vec3(m.ambient) * glm::vec3(l.ambient) + n_dot_vp * glm::vec3(m.diffuse) * glm::vec3(l.diffuse);
    if (n_dot_vp > 0.0f) {
      glm::vec3 h = vp + (s.local_viewer ? (glm::length(eye) > 0 ? -glm::normalize(eye) : glm::vec3(0)) : glm::vec3(0, 0, 1));
      float hl = glm::length(h);
      float n_dot_h = hl > 0 ? std::max(glm::dot(n, h / hl), 0.0f) : 0.0f;
      float spec = m.shininess == 0.0f ? 1.0f : std::pow(n_dot_h, m.shininess);
      term += spec * glm::vec3(m.specular) * glm::vec3(l.specular);
    }
    c += attenuation * spot * term;
  }
  return glm::clamp(glm::vec4(c, m.diffuse.a), 0.0f, 1.0f);
}

}  // namespace

// Random states -- positional and directional lights, spots, attenuation, a local viewer,
// disabled lights, a light straight behind the viewer (a zero half vector) -- random materials,
// points and normals: the prepared equation gives the direct equation's bits.
TEST(Lighting, PreparedEquationGivesTheDirectEquationsBits) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.0f, 1.0f);
  auto v3 = [&] { return glm::vec3(u(rng), u(rng), u(rng)); };
  auto colour = [&] { return glm::vec4(pos(rng), pos(rng), pos(rng), pos(rng)); };
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial) {
    pf::LightingState s;
    s.local_viewer = trial % 3 == 0;
    s.model_ambient = colour();
    for (int i = 0; i < pf::kMaxLights; ++i) {
      pf::Light& l = s.lights[i];
      l.enabled = rng() % 3 != 0;
      l.ambient = colour();
      l.diffuse = colour();
      l.specular = colour();
      const int kind = static_cast<int>(rng() % 4);
      l.position = kind == 0 ? glm::vec4(v3() * 4.0f, 1.0f)
                   : kind == 1 ? glm::vec4(v3(), 0.0f)
                   : kind == 2 ? glm::vec4(0, 0, -1, 0)  // behind the viewer: VP + z is zero
                               : glm::vec4(v3() * 2.0f, 0.5f);
      if (rng() % 2) {
        l.spot_direction = v3();
        l.spot_cutoff = 10.0f + 80.0f * pos(rng);
        l.spot_exponent = 8.0f * pos(rng);
      }
      if (rng() % 2) {
        l.constant_attenuation = pos(rng);
        l.linear_attenuation = pos(rng);
        l.quadratic_attenuation = pos(rng);
      }
    }
    const pf::LightingEquation equation(s);
    for (int k = 0; k < 20; ++k) {
      pf::Material m;
      m.ambient = colour();
      m.diffuse = colour();
      m.specular = colour();
      m.emission = colour() * 0.2f;
      m.shininess = k % 4 == 0 ? 0.0f : 100.0f * pos(rng);
      const glm::vec3 eye = v3() * 3.0f;
      const glm::vec3 n = k % 5 == 0 ? glm::vec3(0) : glm::normalize(v3() + glm::vec3(0, 0, 0.01f));
      const glm::vec4 want = directEquation(s, m, eye, n), got = equation.shade(m, eye, n);
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(std::bit_cast<uint32_t>(got[c]), std::bit_cast<uint32_t>(want[c])) << "trial " << trial << " k " << k;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 6000);
}

// shadeRun (the shading pass's: a row of points at once) gives shade()'s bits at every point.
TEST(Lighting, RunGivesTheBitsOfEachPoint) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.0f, 1.0f);
  for (int trial = 0; trial < 100; ++trial) {
    pf::LightingState s;
    s.local_viewer = trial % 2 == 0;
    for (int i = 0; i < 4; ++i) {
      pf::Light& l = s.lights[i];
      l.enabled = i < 3 || trial % 3 == 0;
      l.ambient = glm::vec4(pos(rng), pos(rng), pos(rng), 1);
      l.diffuse = glm::vec4(pos(rng), pos(rng), pos(rng), 1);
      l.specular = glm::vec4(pos(rng), pos(rng), pos(rng), 1);
      l.position = i % 2 ? glm::vec4(u(rng) * 3, u(rng) * 3, u(rng) * 3, 1) : glm::vec4(u(rng), u(rng), u(rng), 0);
      if (i >= 2) {
        l.spot_direction = glm::vec3(u(rng), u(rng), u(rng));
        l.spot_cutoff = 20.0f + 60.0f * pos(rng);
        l.spot_exponent = 3.0f * pos(rng);
        l.quadratic_attenuation = pos(rng);
      }
    }
    const pf::LightingEquation eq(s);
    constexpr int n = pf::LitPoints::kMax;
    std::vector<float> q(static_cast<size_t>(n) * 23);
    for (float& v : q) v = u(rng);
    auto plane = [&](int k) { return q.data() + static_cast<size_t>(k) * n; };
    for (int i = 0; i < n; ++i) {  // unit normals, some zero; positive shininess, some zero
      glm::vec3 nn(plane(3)[i], plane(4)[i], plane(5)[i]);
      nn = i % 9 == 0 ? glm::vec3(0) : glm::normalize(nn);
      plane(3)[i] = nn.x, plane(4)[i] = nn.y, plane(5)[i] = nn.z;
      plane(22)[i] = i % 4 == 0 ? 0.0f : 50.0f * std::abs(plane(22)[i]);
    }
    pf::LitPoints in;
    in.n = n - trial % 5;
    for (int k = 0; k < 3; ++k) in.eye[k] = plane(k), in.normal[k] = plane(3 + k);
    for (int k = 0; k < 4; ++k)
      in.ambient[k] = plane(6 + k), in.diffuse[k] = plane(10 + k), in.specular[k] = plane(14 + k),
      in.emission[k] = plane(18 + k);
    in.shininess = plane(22);
    std::vector<float> out(4 * n);
    float* const outs[4] = {out.data(), out.data() + n, out.data() + 2 * n, out.data() + 3 * n};
    eq.shadeRun(in, outs);
    for (int i = 0; i < in.n; ++i) {
      pf::Material m;
      m.ambient = glm::vec4(in.ambient[0][i], in.ambient[1][i], in.ambient[2][i], in.ambient[3][i]);
      m.diffuse = glm::vec4(in.diffuse[0][i], in.diffuse[1][i], in.diffuse[2][i], in.diffuse[3][i]);
      m.specular = glm::vec4(in.specular[0][i], in.specular[1][i], in.specular[2][i], in.specular[3][i]);
      m.emission = glm::vec4(in.emission[0][i], in.emission[1][i], in.emission[2][i], in.emission[3][i]);
      m.shininess = in.shininess[i];
      const glm::vec4 want = eq.shade(m, glm::vec3(in.eye[0][i], in.eye[1][i], in.eye[2][i]),
                                      glm::vec3(in.normal[0][i], in.normal[1][i], in.normal[2][i]));
      for (int k = 0; k < 4; ++k)
        EXPECT_EQ(std::bit_cast<uint32_t>(outs[k][i]), std::bit_cast<uint32_t>(want[k]))
            << "trial " << trial << " point " << i << " component " << k;
    }
  }
}
