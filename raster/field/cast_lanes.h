// The per-block state of FieldRayCaster's search, shared by its method files: each lane's ray
// and result, and which lanes are still searching.
#pragma once

#include <bit>
#include <cstdint>

#include "raster/field/field_rays.h"
#include "raster/limits.h"

namespace pf::field {

struct CastLanes {
  PixelRay ray[kLanes];
  double t[kLanes];
  uint64_t pending = 0;  // lanes still searching

  void hit(int i, double t_hit) {
    t[i] = t_hit;
    pending &= ~(uint64_t(1) << i);
  }
  // The pending lanes whose span in the box overlaps [ta, tb].
  uint64_t overlapping(double ta, double tb) const {
    uint64_t m = 0;
    for (uint64_t p = pending; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      if (ray[i].entry <= tb && ray[i].exit >= ta) m |= uint64_t(1) << i;
    }
    return m;
  }
};

}  // namespace pf::field
