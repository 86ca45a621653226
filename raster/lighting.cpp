// GL's lighting equation (GL 1.5 section 2.14.1): the API evaluates it per vertex, the shading
// pass per pixel for primitives that set their surface normal N.
#include "raster/lighting.h"

#include <algorithm>
#include <cmath>

namespace pf {

void LightingState::trackColor(const glm::vec4& color) {
  if (!color_material) return;
  for (int face = 0; face < 2; ++face) material[face] = trackedMaterial(*this, face, color);
}

glm::vec4 litColor(const LightingState& s, const glm::vec3& eye, const glm::vec3& normal_in, int face) {
  return litColor(s, s.material[face], eye, face == 0 ? normal_in : -normal_in);
}

Material trackedMaterial(const LightingState& s, int face, const glm::vec4& color) {
  Material m = s.material[face];
  if (!s.color_material || (face == 0 && s.color_material_face == GL_BACK) ||
      (face == 1 && s.color_material_face == GL_FRONT))
    return m;
  switch (s.color_material_mode) {
    case GL_AMBIENT: m.ambient = color; break;
    case GL_DIFFUSE: m.diffuse = color; break;
    case GL_SPECULAR: m.specular = color; break;
    case GL_EMISSION: m.emission = color; break;
    default: m.ambient = m.diffuse = color; break;
  }
  return m;
}

namespace {

float spotFactor(const glm::vec3& vp, const glm::vec3& sd, float cos_cutoff, float exponent) {
  const float cos_angle = std::max(glm::dot(-vp, sd), 0.0f);
  return cos_angle >= cos_cutoff ? std::pow(cos_angle, exponent) : 0.0f;
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
      const float spec = m.shininess == 0.0f ? 1.0f : std::pow(n_dot_h, m.shininess);
      term += spec * glm::vec3(m.specular) * l.specular;
    }
    c += attenuation * spot * term;
  }
  return glm::clamp(glm::vec4(c, m.diffuse.a), 0.0f, 1.0f);
}

glm::vec4 litColor(const LightingState& s, const Material& m, const glm::vec3& eye, const glm::vec3& n) {
  return LightingEquation(s).shade(m, eye, n);
}

}  // namespace pf
