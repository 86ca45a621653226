// The box of object space that a bundle of pixel rays sweeps over a range of the ray parameter,
// rounded outward to floats: what the interval form is evaluated over, for a tile's or a block's
// slab (several corner rays) and for one ray's segment (ray_search.h).
#pragma once

#include <algorithm>
#include <limits>

#include "raster/field/field_rays.h"
#include "raster/field/interval.h"

namespace pf::field {

struct RayBox {
  Interval x, y, z;
  bool empty = false;  // no point of the rays' segments lies in the field's box
};

inline float roundedDown(double v) { return floatBelow(static_cast<float>(v)); }
inline float roundedUp(double v) { return floatAbove(static_cast<float>(v)); }

// The box of points o + t d, t in [a, b], of the given rays, intersected with the field's box
// and rounded outward (one float step: the double points round to floats within half a step).
// Since each ray is a line, its segment lies in the box of its two end points.
template <int N>
RayBox rayBoxOf(const PixelRay* const (&rays)[N], double a, double b, const FieldRays& fr) {
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::numeric_limits<double>::infinity();
    hi[k] = -lo[k];
  }
  for (const PixelRay* r : rays) {
    for (double t : {a, b}) {
      const Vec3d p = r->at(t);
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  RayBox box;
  Interval* axes[3] = {&box.x, &box.y, &box.z};
  for (int k = 0; k < 3; ++k) {
    lo[k] = std::max(lo[k], fr.box_min[k]);
    hi[k] = std::min(hi[k], fr.box_max[k]);
    if (!(lo[k] <= hi[k])) box.empty = true;
    *axes[k] = {roundedDown(lo[k]), roundedUp(hi[k])};
  }
  return box;
}

}  // namespace pf::field
