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

glm::vec4 litColor(const LightingState& s, const Material& m, const glm::vec3& eye, const glm::vec3& n) {
  glm::vec3 c = glm::vec3(m.emission) + glm::vec3(m.ambient) * glm::vec3(s.model_ambient);
  for (const Light& l : s.lights) {
    if (!l.enabled) continue;
    // VP: from the vertex to the light (a direction for a light at infinity), and attenuation.
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

}  // namespace pf
