// How far a rendering of a pfspheres scene is from the exact image: coverage, which sphere is
// seen, depth, and the lit colour.
#pragma once

#include <cstdint>
#include <limits>

#include "bench/sphere_reference.h"
#include "bench/sphere_scene.h"

namespace pfspheres {

struct Accuracy {
  int64_t missing = 0;        // the exact image has a sphere, the rendering none
  int64_t extra = 0;          // the rendering has a sphere, the exact image none
  int64_t wrong_surface = 0;  // both have one, not the same (from the ID frame)
  int64_t off_edge = 0;       // of the three, pixels not near an edge (ExactImage::near_edge)
  int64_t same_surface = 0;   // pixels where both show the same sphere
  // Over the same-surface pixels (a wrong-surface pixel's depth and colour differences are the gap
  // between two spheres, counted above): window depth error, and the largest difference of an
  // 8-bit lit colour channel.
  double max_depth_error = 0, mean_depth_error = 0;
  int max_color_error = 0;
  double psnr_db = std::numeric_limits<double>::infinity();  // lit RGB, every pixel, 8 bits
  int64_t mismatched() const { return missing + extra + wrong_surface; }
};

Accuracy measureAccuracy(const ExactImage& exact, const Rendering& r);

}  // namespace pfspheres
