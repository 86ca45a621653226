// A cloud of sphere impostors made from a count and a seed: the scene that shows why a frame
// outgrows one machine (100M spheres; each rank of pfrender-mpi makes and draws only its share,
// so no process ever holds the whole scene), after PixelFlow's renderers that each drew a
// fraction of the primitives (Molnar et al. 1992, cited in seed 003 section 1). Sphere i's
// centre, radius and colour come from a hash of (seed, i), so any rank makes any sphere alone,
// and writeCloudScene writes the same spheres as a scene file (docs/scenes.md) for pfrender.
// Each object (per_object consecutive spheres, one glBegin) fills a thin slab of the box along
// x, the slabs in a scrambled order: so `spatial` splits the screen into strips, `block` and
// `round-robin` give every rank spheres all over it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace pf::cloud {

struct SphereCloud {
  uint64_t count = 0;
  uint32_t seed = 1;
  int per_object = 256;       // spheres per scene object (one glBegin each)
  float radius_scale = 1.0f;  // radii times this (the default keeps the covered share of the image
                              // about the same for any count: radii shrink as count^(-1/3))
};

struct Sphere {
  float center[3], radius, color[3];
};

Sphere sphereAt(const SphereCloud& cloud, uint64_t index);
uint64_t objectCount(const SphereCloud& cloud);
// The world centre of an object's spheres (their mean), for the spatial split.
glm::dvec3 objectCentre(const SphereCloud& cloud, uint64_t object);

// The scene around the spheres: size, camera, background and light, and no objects.
scene::Scene cloudFrame(int width, int height);

// Draws object `object` (per_object spheres, the last one fewer) exactly as drawObject draws
// the same object read from writeCloudScene's file.
void drawCloudObject(const SphereCloud& cloud, uint64_t object);

// Writes the cloud as a scene file; false with *error set when the file cannot be written.
bool writeCloudScene(const SphereCloud& cloud, int width, int height, const std::string& path, std::string* error);

}  // namespace pf::cloud
