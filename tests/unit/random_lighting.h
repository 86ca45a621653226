// A random GL lighting state for the tests that check a lighting path against
// LightingEquation::shade(): two-sided or not, local viewer or not, colour material in any
// face and mode, random materials (shininess 0 a third of the time), a directional light, a
// positional one and an attenuated spot light.
#pragma once

#include <random>

#include <glm/glm.hpp>

#include "raster/lighting.h"

namespace pf::test {

inline LightingState randomLighting(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), pos(0.0f, 1.0f);
  auto colour = [&] { return glm::vec4(pos(rng), pos(rng), pos(rng), pos(rng)); };
  LightingState s;
  s.enabled = true;
  s.two_side = rng() % 2 == 0;
  s.local_viewer = rng() % 3 == 0;
  s.model_ambient = colour();
  s.color_material = rng() % 4 != 0;
  const GLenum faces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
  const GLenum modes[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
  s.color_material_face = faces[rng() % 3];
  s.color_material_mode = modes[rng() % 5];
  for (Material& m : s.material) {
    m.ambient = colour();
    m.diffuse = colour();
    m.specular = colour();
    m.emission = colour() * 0.3f;
    m.shininess = rng() % 3 == 0 ? 0.0f : 60.0f * pos(rng);
  }
  for (int i = 0; i < 3; ++i) {
    Light& l = s.lights[i];
    l.enabled = true;
    l.ambient = colour();
    l.diffuse = colour();
    l.specular = colour();
    l.position = i == 0 ? glm::vec4(u(rng), u(rng), 1.0f, 0.0f) : glm::vec4(u(rng) * 3, u(rng) * 3, u(rng) * 3, 1.0f);
    if (i == 2) {
      l.spot_direction = glm::vec3(u(rng), u(rng), -1.0f);
      l.spot_cutoff = 30.0f + 40.0f * pos(rng);
      l.spot_exponent = 4.0f * pos(rng);
      l.linear_attenuation = 0.3f * pos(rng);
    }
  }
  return s;
}

}  // namespace pf::test
