// pfspheres' scenes: spheres placed by a fixed-seed RNG inside a glFrustum, seen through a rigid
// modelview (see sphere_scene.h).
#include "bench/sphere_scene.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <random>

namespace pfspheres {

namespace {

constexpr double kNear = 1.0, kFar = 30.0, kHalfWidth = 0.4;  // glFrustum(-0.4, 0.4, -0.4, 0.4, 1, 30)
constexpr double kZClose = -4.0, kZFar = -10.0;               // sphere centres' eye depth range

glm::dmat4 viewMatrix() {
  glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(0, 0, -7));
  return glm::rotate(m, glm::radians(25.0), glm::normalize(glm::dvec3(1, 1, 0)));
}

void storeMatrix(const glm::dmat4& m, float* out) {
  const double* p = glm::value_ptr(m);
  for (int i = 0; i < 16; ++i) out[i] = static_cast<float>(p[i]);
}

}  // namespace

SphereScene makeSphereScene(int count, int size) {
  SphereScene s;
  s.width = s.height = size;
  storeMatrix(glm::frustum(-kHalfWidth, kHalfWidth, -kHalfWidth, kHalfWidth, kNear, kFar), s.projection);
  const glm::dmat4 view = viewMatrix();
  storeMatrix(view, s.modelview);
  const glm::dmat4 world_from_eye = glm::inverse(view);

  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double base_radius = 1.5 * std::cbrt(1.0 / count);
  for (int i = 0; i < count; ++i) {
    // A centre inside the frustum's slice at its depth (70% of the half-width, so most of each
    // sphere is on screen), in eye coordinates, taken back to world coordinates.
    const double z = kZClose + (kZFar - kZClose) * u01(rng);
    const double half = 0.7 * kHalfWidth * -z / kNear;
    const double x = (2 * u01(rng) - 1) * half;  // one draw a statement: a fixed order
    const double y = (2 * u01(rng) - 1) * half;
    const glm::dvec3 eye(x, y, z);
    const glm::dvec3 world = glm::dvec3(world_from_eye * glm::dvec4(eye, 1));
    Sphere sp;
    for (int k = 0; k < 3; ++k) sp.center[k] = static_cast<float>(world[k]);
    sp.radius = static_cast<float>(base_radius * (0.6 + 0.4 * u01(rng)));
    for (float& c : sp.color) c = static_cast<float>(0.25 + 0.75 * u01(rng));
    s.spheres.push_back(sp);
  }
  return s;
}

}  // namespace pfspheres
