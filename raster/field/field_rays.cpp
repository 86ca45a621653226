// Pixel rays of an implicit instance, in double, clipped to its box by the slab method.
#include "raster/field/field_rays.h"

#include <algorithm>
#include <cmath>

namespace pf::field {

PixelRay FieldRays::unclipped(double x, double y) const {
  const std::array<double, 16>& m = window_to_object;
  auto unproject = [&](double z) {
    double p[4];
    for (int r = 0; r < 4; ++r) p[r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
    return Vec3d{p[0] / p[3], p[1] / p[3], p[2] / p[3]};
  };
  PixelRay ray;
  ray.origin = unproject(depth_near);
  const Vec3d far = unproject(depth_far);
  for (int k = 0; k < 3; ++k) {
    ray.direction[k] = far[k] - ray.origin[k];
    if (!std::isfinite(ray.origin[k]) || !std::isfinite(ray.direction[k])) return PixelRay{};
  }
  ray.entry = 0.0;
  ray.exit = 1.0;
  return ray;
}

PixelRay FieldRays::ray(double x, double y) const {
  PixelRay ray = unclipped(x, y);
  if (ray.empty()) return ray;
  double t0 = 0.0, t1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double o = ray.origin[k], d = ray.direction[k];
    if (d == 0.0) {
      if (o < box_min[k] || o > box_max[k]) return PixelRay{};
      continue;
    }
    double ta = (box_min[k] - o) / d, tb = (box_max[k] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  ray.entry = t0;
  ray.exit = t1;
  return ray;
}

bool FieldRays::affine() const { return window_to_object[3] == 0.0 && window_to_object[7] == 0.0; }

}  // namespace pf::field
