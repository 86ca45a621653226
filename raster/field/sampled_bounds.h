// A sampled field's `sample` leaf (compiler/field/sampled_grid.h, seed 000 section 3) in the
// interval forms: its value over a box, and its rate along a box of directions, from the grid's
// sound bounds (the samples' min and max over the cells the box touches -- a convex hull the
// trilinear and B-spline interpolants stay in -- and the same for the samples' differences,
// which bound the partial derivatives). Shared by the scalar and the batched evaluators, so the
// two agree to the bit.
#pragma once

#include "compiler/field/sampled_grid.h"
#include "raster/field/interval.h"

namespace pf::field {

// The grid's value over the box [x] x [y] x [z]; the whole line where a coordinate may be NaN.
inline Interval sampleInterval(const SampledGrid& grid, Interval x, Interval y, Interval z) {
  if (x.isWhole() || y.isWhole() || z.isWhole()) return Interval::whole();
  const float lo[3] = {x.lo, y.lo, z.lo}, hi[3] = {x.hi, y.hi, z.hi};
  Interval r;
  grid.valueBounds(lo, hi, r.lo, r.hi);
  return r;
}

// The value over the box and the rate d/dt = grad . direction over the directions [dx] x [dy] x
// [dz]. (The interpolants are continuous, so a rate that excludes 0 proves monotonicity.)
inline void sampleSlope(const SampledGrid& grid, Interval x, Interval y, Interval z, Interval dx, Interval dy,
                        Interval dz, Interval& value, Interval& rate) {
  value = sampleInterval(grid, x, y, z);
  if (value.isWhole()) {
    rate = Interval::whole();
    return;
  }
  const float lo[3] = {x.lo, y.lo, z.lo}, hi[3] = {x.hi, y.hi, z.hi};
  float glo[3], ghi[3];
  grid.gradientBounds(lo, hi, glo, ghi);
  rate = intervalAdd(intervalAdd(intervalMul({glo[0], ghi[0]}, dx), intervalMul({glo[1], ghi[1]}, dy)),
                     intervalMul({glo[2], ghi[2]}, dz));
}

}  // namespace pf::field
