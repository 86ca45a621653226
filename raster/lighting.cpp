// GL's lighting equation (GL 1.5 section 2.14.1): the API evaluates it per vertex, the shading
// pass per pixel for primitives that set their surface normal N.
#include "raster/lighting.h"

#include <algorithm>
#include <cmath>

#include "raster/light_pow.h"

namespace pf {

namespace {

// The properties glColorMaterial makes `face` track, set to `color` in `m` (in place: glColor
// calls it at every vertex of a lit mesh).
void trackInto(const LightingState& s, int face, const glm::vec4& color, Material& m) {
  if (!s.color_material || (face == 0 && s.color_material_face == GL_BACK) ||
      (face == 1 && s.color_material_face == GL_FRONT))
    return;
  switch (s.color_material_mode) {
    case GL_AMBIENT: m.ambient = color; break;
    case GL_DIFFUSE: m.diffuse = color; break;
    case GL_SPECULAR: m.specular = color; break;
    case GL_EMISSION: m.emission = color; break;
    default: m.ambient = m.diffuse = color; break;
  }
}

}  // namespace

void LightingState::trackColor(const glm::vec4& color) {
  if (!color_material) return;
  for (int face = 0; face < 2; ++face) trackInto(*this, face, color, material[face]);
}

glm::vec4 litColor(const LightingState& s, const glm::vec3& eye, const glm::vec3& normal_in, int face) {
  return litColor(s, s.material[face], eye, face == 0 ? normal_in : -normal_in);
}

Material trackedMaterial(const LightingState& s, int face, const glm::vec4& color) {
  Material m = s.material[face];
  trackInto(s, face, color, m);
  return m;
}

bool lightReadsEye(const LightingState& s) {
  if (s.local_viewer || s.two_side) return true;
  for (const Light& l : s.lights)
    if (l.enabled && l.position.w != 0.0f) return true;
  return false;
}

namespace {

float spotFactor(const glm::vec3& vp, const glm::vec3& sd, float cos_cutoff, float exponent) {
  const float cos_angle = std::max(glm::dot(-vp, sd), 0.0f);
  return cos_angle >= cos_cutoff ? lightPow(cos_angle, exponent) : 0.0f;
}

}  // namespace

LightingEquation::LightingEquation(const LightingState& s)
    : model_ambient_(s.model_ambient), local_viewer_(s.local_viewer) {
  for (const Light& l : s.lights) {
    if (!l.enabled) continue;
    Prepared& p = lights_[count_++];
    p.ambient = glm::vec3(l.ambient);
    p.diffuse = glm::vec3(l.diffuse);
    p.specular = glm::vec3(l.specular);
    p.positional = l.position.w != 0.0f;
    p.position = p.positional ? glm::vec3(l.position) / l.position.w : glm::vec3(0);
    p.constant = l.constant_attenuation;
    p.linear = l.linear_attenuation;
    p.quadratic = l.quadratic_attenuation;
    p.direction = !p.positional && glm::length(glm::vec3(l.position)) > 0 ? glm::normalize(glm::vec3(l.position))
                                                                           : glm::vec3(0);
    p.spot = l.spot_cutoff != 180.0f;
    p.spot_direction = glm::length(l.spot_direction) > 0 ? glm::normalize(l.spot_direction) : glm::vec3(0);
    p.spot_cos_cutoff = std::cos(glm::radians(l.spot_cutoff));
    p.spot_exponent = l.spot_exponent;
    p.directional_spot = p.spot ? spotFactor(p.direction, p.spot_direction, p.spot_cos_cutoff, p.spot_exponent) : 1.0f;
    p.has_half = !p.positional && !s.local_viewer;
    const glm::vec3 h = p.direction + glm::vec3(0, 0, 1);
    const float hl = glm::length(h);
    p.half_zero = !(hl > 0);
    p.half = hl > 0 ? h / hl : glm::vec3(0);
  }
}

glm::vec4 LightingEquation::shade(const Material& m, const glm::vec3& eye, const glm::vec3& n) const {
  glm::vec3 c = glm::vec3(m.emission) + glm::vec3(m.ambient) * model_ambient_;
  for (int i = 0; i < count_; ++i) {
    const Prepared& l = lights_[i];
    // VP: from the point to the light (a direction for a light at infinity), and attenuation.
    glm::vec3 vp = l.direction;
    float attenuation = 1.0f;
    float spot = l.directional_spot;
    if (l.positional) {
      const glm::vec3 d = l.position - eye;
      const float dist = glm::length(d);
      vp = dist > 0 ? d / dist : glm::vec3(0);
      const float k = l.constant + l.linear * dist + l.quadratic * dist * dist;
      attenuation = k > 0 ? 1.0f / k : 0.0f;
      spot = l.spot ? spotFactor(vp, l.spot_direction, l.spot_cos_cutoff, l.spot_exponent) : 1.0f;
    }
    const float n_dot_vp = std::max(glm::dot(n, vp), 0.0f);
    glm::vec3 term = glm::vec3(m.ambient) * l.ambient + n_dot_vp * glm::vec3(m.diffuse) * l.diffuse;
    if (n_dot_vp > 0.0f) {
      float n_dot_h;
      if (l.has_half) {
        n_dot_h = l.half_zero ? 0.0f : std::max(glm::dot(n, l.half), 0.0f);
      } else {
        const glm::vec3 h = vp + (local_viewer_ ? (glm::length(eye) > 0 ? -glm::normalize(eye) : glm::vec3(0))
                                                : glm::vec3(0, 0, 1));
        const float hl = glm::length(h);
        n_dot_h = hl > 0 ? std::max(glm::dot(n, h / hl), 0.0f) : 0.0f;
      }
      const float spec = m.shininess == 0.0f ? 1.0f : lightPow(n_dot_h, m.shininess);
      term += spec * glm::vec3(m.specular) * l.specular;
    }
    c += attenuation * spot * term;
  }
  return glm::clamp(glm::vec4(c, m.diffuse.a), 0.0f, 1.0f);
}

// Written as shade() is, operation for operation (glm's vec3 dot is (x x' + y y') + z z', its
// length sqrt(dot), its max (x < y) ? y : x, its min (y < x) ? y : x), over arrays.
PF_SIMD_CLONES void LightingEquation::shadeRun(const LitPoints& in, float* const out[4]) const {
  const int n = in.n;
  alignas(64) float c[3][LitPoints::kMax], term[3][LitPoints::kMax], vp[3][LitPoints::kMax], scale[LitPoints::kMax],
      n_dot_vp[LitPoints::kMax];
  for (int k = 0; k < 3; ++k) {
    const float* const emission = in.emission[k];
    const float* const ambient = in.ambient[k];
    const float global = model_ambient_[k];
    for (int i = 0; i < n; ++i) c[k][i] = emission[i] + ambient[i] * global;
  }
  const float* const ex = in.eye[0];
  const float* const ey = in.eye[1];
  const float* const ez = in.eye[2];
  const float* const nx = in.normal[0];
  const float* const ny = in.normal[1];
  const float* const nz = in.normal[2];
  for (int li = 0; li < count_; ++li) {
    const Prepared& l = lights_[li];
    if (l.positional) {
      for (int i = 0; i < n; ++i) {
        const float dx = l.position.x - ex[i], dy = l.position.y - ey[i], dz = l.position.z - ez[i];
        const float dist = std::sqrt(dx * dx + dy * dy + dz * dz);
        const bool far = dist > 0;
        vp[0][i] = far ? dx / dist : 0.0f;
        vp[1][i] = far ? dy / dist : 0.0f;
        vp[2][i] = far ? dz / dist : 0.0f;
        const float k = l.constant + l.linear * dist + l.quadratic * dist * dist;
        scale[i] = k > 0 ? 1.0f / k : 0.0f;  // attenuation; the spot factor below
      }
      for (int i = 0; i < n; ++i) {
        float spot = 1.0f;
        if (l.spot) {
          const glm::vec3 v(vp[0][i], vp[1][i], vp[2][i]);
          spot = spotFactor(v, l.spot_direction, l.spot_cos_cutoff, l.spot_exponent);
        }
        scale[i] = scale[i] * spot;
      }
    } else {
      const float s = 1.0f * l.directional_spot;
      for (int i = 0; i < n; ++i) {
        vp[0][i] = l.direction.x;
        vp[1][i] = l.direction.y;
        vp[2][i] = l.direction.z;
        scale[i] = s;
      }
    }
    for (int i = 0; i < n; ++i) {
      const float d = nx[i] * vp[0][i] + ny[i] * vp[1][i] + nz[i] * vp[2][i];
      n_dot_vp[i] = d < 0.0f ? 0.0f : d;  // std::max(d, 0): (d < 0) ? 0 : d
    }
    for (int k = 0; k < 3; ++k) {
      const float la = l.ambient[k], ld = l.diffuse[k];
      for (int i = 0; i < n; ++i) term[k][i] = in.ambient[k][i] * la + n_dot_vp[i] * in.diffuse[k][i] * ld;
    }
    // The specular term, where the light reaches the front of the surface (n_dot_vp > 0).
    alignas(64) float spec[LitPoints::kMax];
    if (l.has_half) {  // a directional light, the viewer at infinity: one half vector
      for (int i = 0; i < n; ++i) {
        const float d = nx[i] * l.half.x + ny[i] * l.half.y + nz[i] * l.half.z;
        spec[i] = l.half_zero ? 0.0f : (d < 0.0f ? 0.0f : d);  // n_dot_h
      }
    } else {
      for (int i = 0; i < n; ++i) {
        const glm::vec3 e(ex[i], ey[i], ez[i]), v(vp[0][i], vp[1][i], vp[2][i]);
        const glm::vec3 h = v + (local_viewer_ ? (glm::length(e) > 0 ? -glm::normalize(e) : glm::vec3(0))
                                               : glm::vec3(0, 0, 1));
        const float hl = glm::length(h);
        spec[i] = hl > 0 ? std::max(glm::dot(glm::vec3(nx[i], ny[i], nz[i]), h / hl), 0.0f) : 0.0f;
      }
    }
    // (Every lane's value computed, then chosen, here and below: an operation in one arm of a
    // select is one the compiler may not run for every lane, and the loop would not vectorize.)
    int shiny = 0, varies = 0;
    const float shininess = in.shininess[0];
    for (int i = 0; i < n; ++i) {
      shiny |= in.shininess[i] != 0.0f ? 1 : 0;
      varies |= in.shininess[i] != shininess ? 1 : 0;
    }
    if (shiny) {
      // One whole exponent over the run (a material's shininess, as a rule): its powers by
      // wholePowers, the bits lightPow would give each lane.
      alignas(64) float power[LitPoints::kMax];
      if (!varies && lightPowIsWhole(shininess))
        wholePowers<LitPoints::kMax>(spec, static_cast<int>(shininess), n, power);
      else
        for (int i = 0; i < n; ++i) power[i] = lightPow(spec[i], in.shininess[i]);
      for (int i = 0; i < n; ++i)
        spec[i] = in.shininess[i] == 0.0f ? 1.0f : n_dot_vp[i] > 0.0f ? power[i] : 0.0f;
    } else
      for (int i = 0; i < n; ++i) spec[i] = 1.0f;
    for (int k = 0; k < 3; ++k) {
      const float ls = l.specular[k];
      const float* const material = in.specular[k];
      for (int i = 0; i < n; ++i) {
        const float lit = term[k][i] + spec[i] * material[i] * ls;
        term[k][i] = n_dot_vp[i] > 0.0f ? lit : term[k][i];
      }
    }
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < n; ++i) c[k][i] = c[k][i] + scale[i] * term[k][i];
  }
  // glm::clamp(x, 0, 1): min(max(x, 0), 1).
  auto clamp01 = [](float x) {
    const float lo = x < 0.0f ? 0.0f : x;
    return 1.0f < lo ? 1.0f : lo;
  };
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < n; ++i) out[k][i] = clamp01(c[k][i]);
  for (int i = 0; i < n; ++i) out[3][i] = clamp01(in.diffuse[3][i]);
}

glm::vec4 litColor(const LightingState& s, const Material& m, const glm::vec3& eye, const glm::vec3& n) {
  return LightingEquation(s).shade(m, eye, n);
}

}  // namespace pf
