// The exact image of a pfspheres scene, computed in double precision: per pixel, the ray through
// the pixel centre cast against every sphere (through the scene's projection and modelview), giving
// the nearest sphere, its window depth and its colour under GL's lighting equation.
#pragma once

#include <cstdint>
#include <vector>

#include "bench/sphere_scene.h"

namespace pfspheres {

struct ExactImage {
  int width = 0, height = 0;
  std::vector<uint32_t> id;        // the nearest sphere at the pixel centre: i + 1; 0 = none
  std::vector<double> depth;       // its window depth in [0, 1] (1 where id = 0)
  std::vector<uint8_t> rgb;        // lit colour, rounded to 8 bits as GL stores it; else the clear colour
  std::vector<uint8_t> near_edge;  // 1: the answer (id) changes within `edge_pixels` of the pixel centre
};

// `edge_pixels` sets near_edge: a pixel is near an edge when one of 8 rays at that distance around
// its centre (every 45 degrees) has a different nearest sphere (or none) -- the pixel is that close
// to a silhouette or to the curve where two spheres intersect, where a float renderer may
// legitimately decide either way.
ExactImage computeExactImage(const SphereScene& s, double edge_pixels);

}  // namespace pfspheres
