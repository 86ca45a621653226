// The sphere-impostor cloud (sphere_cloud.h): a counter-based hash per sphere, so ranks make
// their shares independently, and the same spheres written as a scene file for pfrender.
#include "sphere_cloud.h"

#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace pf::cloud {

namespace {

// splitmix64: one well-mixed 64-bit word per (seed, index, field).
uint64_t mix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// A float in [0, 1) with 24 random bits: exact in a float, so the scene file repeats it.
float unit(const SphereCloud& c, uint64_t index, uint64_t field) {
  const uint64_t h = mix(mix(static_cast<uint64_t>(c.seed) * 0x100000001b3ull + field) ^ index);
  return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

// The box the centres fill (16:9 like a 4K frame) and the base radius for `count` spheres:
// 2000 spheres get 0.1, and the radius goes as count^(-1/3), so the share of the box covered
// stays about the same.
constexpr float kBox[3] = {8.0f, 4.5f, 4.5f};

float baseRadius(const SphereCloud& c) {
  const double n = static_cast<double>(std::max<uint64_t>(c.count, 1));
  return static_cast<float>(0.1 * std::cbrt(2000.0 / n)) * c.radius_scale;
}

// Object o's slab of the box along x: a permutation of the objects (a stride coprime to their
// count), so an object is a thin slab somewhere in the box and consecutive objects are far apart.
uint64_t slabOf(const SphereCloud& c, uint64_t object) {
  const uint64_t n = objectCount(c);
  if (n <= 1) return 0;
  uint64_t stride = n * 5 / 8 + 1;
  while (std::gcd(stride, n) != 1) ++stride;
  return static_cast<uint64_t>((static_cast<unsigned __int128>(object) * stride) % n);
}

}  // namespace

Sphere sphereAt(const SphereCloud& c, uint64_t i) {
  Sphere s;
  // x within the slab of the sphere's object, y and z anywhere in the box.
  const uint64_t objects = objectCount(c);
  const uint64_t object = i / static_cast<uint64_t>(std::max(c.per_object, 1));
  const double x = (static_cast<double>(slabOf(c, object)) + unit(c, i, 0)) / static_cast<double>(objects);
  s.center[0] = static_cast<float>(x - 0.5) * kBox[0];
  for (int k = 1; k < 3; ++k) s.center[k] = (unit(c, i, k) - 0.5f) * kBox[k];
  s.radius = baseRadius(c) * (0.5f + unit(c, i, 3));
  // Colours from a few hues, so neighbours differ.
  static const float kPalette[6][3] = {{0.9f, 0.3f, 0.2f}, {0.95f, 0.75f, 0.2f}, {0.3f, 0.75f, 0.35f},
                                       {0.2f, 0.55f, 0.9f}, {0.7f, 0.4f, 0.85f}, {0.85f, 0.85f, 0.8f}};
  const float* p = kPalette[static_cast<int>(unit(c, i, 4) * 6.0f) % 6];
  for (int k = 0; k < 3; ++k) s.color[k] = p[k];
  return s;
}

uint64_t objectCount(const SphereCloud& c) {
  const uint64_t k = static_cast<uint64_t>(std::max(c.per_object, 1));
  return (c.count + k - 1) / k;
}

glm::dvec3 objectCentre(const SphereCloud& c, uint64_t object) {
  const uint64_t k = static_cast<uint64_t>(std::max(c.per_object, 1));
  const uint64_t first = object * k, last = std::min(c.count, first + k);
  glm::dvec3 sum(0.0);
  for (uint64_t i = first; i < last; ++i) {
    const Sphere s = sphereAt(c, i);
    sum += glm::dvec3(s.center[0], s.center[1], s.center[2]);
  }
  return last > first ? sum / static_cast<double>(last - first) : sum;
}

scene::Scene cloudFrame(int width, int height) {
  scene::Scene s;
  s.path = "sphere cloud";
  s.width = width;
  s.height = height;
  s.background = {0.05, 0.06, 0.09, 1};
  s.camera.eye = {0, 0, 9};
  s.camera.target = {0, 0, 0};
  s.camera.fov_degrees = 30;
  s.camera.near = 1;
  s.camera.far = 30;
  s.lighting = true;
  s.global_ambient = {0.25, 0.25, 0.25, 1};
  scene::Light light;
  light.position = {-0.4, 0.6, 0.7};
  s.lights.push_back(light);
  return s;
}

void drawCloudObject(const SphereCloud& c, uint64_t object) {
  // As drawObject does for {"primitive": "sphere_impostors", "instances": [...]} with the
  // default material: the material, then one sequence point per sphere.
  static const GLfloat kSpecular[4] = {0, 0, 0, 1}, kEmission[4] = {0, 0, 0, 1};
  const GLenum mode = pfglGetPrimitiveEXT("sphere_impostors");
  const GLuint center = pfglGetParamNameEXT("center"), color = pfglGetParamNameEXT("color"),
               radius = pfglGetParamNameEXT("radius");
  pfglMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, kSpecular);
  pfglMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, kEmission);
  pfglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0.0f);
  pfglColor4f(0.8f, 0.8f, 0.8f, 1.0f);
  pfglPushMatrix();
  const GLdouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  pfglMultMatrixd(identity);
  pfglBegin(mode);
  const uint64_t k = static_cast<uint64_t>(std::max(c.per_object, 1));
  const uint64_t first = object * k, last = std::min(c.count, first + k);
  for (uint64_t i = first; i < last; ++i) {
    const Sphere s = sphereAt(c, i);
    pfglRastParamfvEXT(center, 3, s.center);
    pfglRastParamfvEXT(color, 3, s.color);
    pfglRastParamfvEXT(radius, 1, &s.radius);
    pfglSequencePointEXT();
  }
  pfglEnd();
  pfglPopMatrix();
}

bool writeCloudScene(const SphereCloud& c, int width, int height, const std::string& path, std::string* error) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) {
    if (error) *error = "cannot write " + path;
    return false;
  }
  const scene::Scene frame = cloudFrame(width, height);
  const scene::Light& l = frame.lights[0];
  std::fprintf(f,
               "{\n  \"image\": {\"size\": [%d, %d], \"background\": [%.17g, %.17g, %.17g]},\n"
               "  \"camera\": {\"eye\": [%.17g, %.17g, %.17g], \"target\": [0, 0, 0], \"fov\": %.17g, \"near\": %.17g, "
               "\"far\": %.17g},\n"
               "  \"lighting\": {\"ambient\": [%.17g, %.17g, %.17g], \"lights\": [{\"type\": \"directional\", "
               "\"direction\": [%.17g, %.17g, %.17g]}]},\n  \"objects\": [",
               width, height, frame.background.r, frame.background.g, frame.background.b, frame.camera.eye.x,
               frame.camera.eye.y, frame.camera.eye.z, frame.camera.fov_degrees, frame.camera.near, frame.camera.far,
               frame.global_ambient.r, frame.global_ambient.g, frame.global_ambient.b, l.position.x, l.position.y,
               l.position.z);
  const uint64_t k = static_cast<uint64_t>(std::max(c.per_object, 1));
  for (uint64_t o = 0; o < objectCount(c); ++o) {
    std::fprintf(f, "%s\n    {\"primitive\": \"sphere_impostors\", \"instances\": [", o ? "," : "");
    const uint64_t first = o * k, last = std::min(c.count, first + k);
    for (uint64_t i = first; i < last; ++i) {
      const Sphere s = sphereAt(c, i);
      std::fprintf(f, "%s\n      {\"center\": [%.9g, %.9g, %.9g], \"radius\": %.9g, \"color\": [%.9g, %.9g, %.9g]}",
                   i > first ? "," : "", s.center[0], s.center[1], s.center[2], s.radius, s.color[0], s.color[1],
                   s.color[2]);
    }
    std::fprintf(f, "]}");
  }
  std::fprintf(f, "\n  ]\n}\n");
  const bool ok = std::fclose(f) == 0;
  if (!ok && error) *error = "cannot write " + path;
  return ok;
}

}  // namespace pf::cloud
