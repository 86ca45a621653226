// The per-block state of FieldRayCaster's search, shared by its method files: each lane's ray
// and result, and which lanes are still searching.
#pragma once

#include <bit>
#include <cstdint>
#include <memory>

#include "raster/field/field_rays.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/ray_caster.h"
#include "raster/limits.h"

namespace pf::field {

struct CastLanes {
  PixelRay ray[kLanes];
  double t[kLanes];
  uint64_t pending = 0;  // lanes still searching
  // The tape that decided the hits being recorded now, and the box it holds over (null: the
  // field's own tape): recorded per lane for field_gradient() (HitTapes).
  std::shared_ptr<const FieldTape> deciding_tape;
  HitBox deciding_box;
  HitTapes* tapes = nullptr;

  void hit(int i, double t_hit) {
    t[i] = t_hit;
    pending &= ~(uint64_t(1) << i);
    if (tapes) {
      tapes->tape[i] = deciding_tape;
      tapes->box[i] = deciding_box;
    }
  }
  // f at ray[i].at(t[i]) for the lanes in `set`, in one batch: f[j] for lane index[j], j < the
  // count returned.
  int evaluateAt(FloatEvaluator& eval, uint64_t set, const double* t_at, float* f, int* index,
                 FieldCounters& c) const {
    if (!set) return 0;  // (and GCC then sees every point the evaluator reads written)
    float px[kLanes], py[kLanes], pz[kLanes];
    int n = 0;
    for (uint64_t p = set; p; p &= p - 1) {
      const int i = std::countr_zero(p);
      const Vec3d q = ray[i].at(t_at[i]);
      px[n] = static_cast<float>(q[0]);
      py[n] = static_cast<float>(q[1]);
      pz[n] = static_cast<float>(q[2]);
      index[n++] = i;
    }
    eval.evaluate(px, py, pz, n, f);
    c.point_evaluations += n;
    return n;
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
