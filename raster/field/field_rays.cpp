// Pixel rays of an implicit instance, in double, clipped to its box by the slab method.
#include "raster/field/field_rays.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "raster/simd_clones.h"

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

// ray() for 64 pixels, each step a loop over the lanes (axis by axis) with its branches as
// selects -- both sides computed, then chosen: -fno-trapping-math lets GCC do that for this file
// -- in the same operations and order as unclipped() and ray(), so the same bits.
PF_SIMD_CLONES void FieldRays::blockRays(int bx, int by, PixelRay out[64]) const {
  constexpr int kN = 64;
  constexpr double kMax = std::numeric_limits<double>::max();
  alignas(64) double px[kN], py[kN], o[3][kN], d[3][kN], t0[kN], t1[kN], miss[kN];
  for (int i = 0; i < kN; ++i) {
    px[i] = static_cast<double>(bx + i % 8) + 0.5;
    py[i] = static_cast<double>(by + i / 8) + 0.5;
  }
  // unclipped(): the points at the near and far planes, the direction between them; no ray
  // where one is not finite.
  const std::array<double, 16>& m = window_to_object;
  const double zn = depth_near, zf = depth_far;
  const double nw0 = m[8 + 3] * zn, fw0 = m[8 + 3] * zf;
  for (int i = 0; i < kN; ++i) miss[i] = 0.0;
  {
    const double mx = m[3], my = m[7], mw = m[15];
    double nw[kN], fw[kN];
    for (int i = 0; i < kN; ++i) {
      nw[i] = m[3] * px[i] + m[7] * py[i] + nw0 + mw;
      fw[i] = mx * px[i] + my * py[i] + fw0 + mw;
    }
    for (int k = 0; k < 3; ++k) {
      const double ax = m[k], ay = m[4 + k], nz = m[8 + k] * zn, fz = m[8 + k] * zf, aw = m[12 + k];
      for (int i = 0; i < kN; ++i) {
        const double ok = (ax * px[i] + ay * py[i] + nz + aw) / nw[i];
        const double dk = (ax * px[i] + ay * py[i] + fz + aw) / fw[i] - ok;
        o[k][i] = ok;
        d[k][i] = dk;
        miss[i] = (std::fabs(ok) <= kMax && std::fabs(dk) <= kMax) ? miss[i] : 1.0;  // (NaN: not <=)
      }
    }
  }
  // ray(): clipped to the box by the slab method; an axis the ray runs parallel to either holds
  // it (skipped) or misses it (no ray).
  for (int i = 0; i < kN; ++i) {
    t0[i] = 0.0;
    t1[i] = 1.0;
  }
  for (int k = 0; k < 3; ++k) {
    const double lo_k = box_min[k], hi_k = box_max[k];
    for (int i = 0; i < kN; ++i) {
      const double ok = o[k][i], dk = d[k][i];
      const bool parallel = dk == 0.0;
      miss[i] = (parallel && (ok < lo_k || ok > hi_k)) ? 1.0 : miss[i];
      const double safe = parallel ? 1.0 : dk;
      const double a = (lo_k - ok) / safe, b = (hi_k - ok) / safe;
      const double ta = a > b ? b : a, tb = a > b ? a : b;  // (swapped when ta > tb)
      const double lo = t0[i], hi = t1[i];
      const double new_lo = lo < ta ? ta : lo;  // std::max(lo, ta)
      const double new_hi = tb < hi ? tb : hi;  // std::min(hi, tb)
      t0[i] = parallel ? lo : new_lo;
      t1[i] = parallel ? hi : new_hi;
    }
  }
  for (int i = 0; i < kN; ++i) {
    const bool none = miss[i] != 0.0;  // PixelRay{}: zeros, entry 0, exit -1
    PixelRay& r = out[i];
    for (int k = 0; k < 3; ++k) {
      r.origin[k] = none ? 0.0 : o[k][i];
      r.direction[k] = none ? 0.0 : d[k][i];
    }
    r.entry = none ? 0.0 : t0[i];
    r.exit = none ? -1.0 : t1[i];
  }
}

bool FieldRays::affine() const { return window_to_object[3] == 0.0 && window_to_object[7] == 0.0; }

}  // namespace pf::field
