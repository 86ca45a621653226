// The interval form with a directional derivative: over a box of points and a box of
// directions, an enclosure of f and of its rate of change along any of those directions
// (forward-mode differentiation in interval arithmetic). When the rate's enclosure excludes 0,
// f is strictly monotone along every such ray through the box -- at most one crossing, no
// sliver -- which is what lets the interval method's sound search (ray_search.h) stop splitting
// a segment or a whole 4x4-pixel slab at once.
//
// Monotonicity needs continuity as well as a sign: min, max and abs are continuous and their
// rate lies in the hull of their operands' (Clarke's generalised derivative), but a comparison or
// a select the box does not decide can jump, so its rate is the whole line; so is the rate of
// anything whose value may be NaN or infinite.
#pragma once

#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/interval.h"

namespace pf::field {

struct IntervalSlope {
  Interval value;  // f over the box
  Interval rate;   // df/dt along the directions, over the box
  // f is continuous and strictly monotone along each ray through the box in those directions.
  bool monotone() const {
    return std::isfinite(value.lo) && std::isfinite(value.hi) && !rate.isWhole() && (rate.lo > 0.0f || rate.hi < 0.0f);
  }
};

class IntervalSlopeEvaluator {
 public:
  explicit IntervalSlopeEvaluator(const FieldTape& tape)
      : tape_(&tape), values_(tape.instrs.size()), rates_(tape.instrs.size()) {}
  // No field yet: evaluate() gives the whole line until reset() names one.
  IntervalSlopeEvaluator() = default;
  // Makes this the evaluator of `tape` (which must outlive its use), keeping the storage.
  void reset(const FieldTape& tape) {
    tape_ = &tape;
    if (values_.size() < tape.instrs.size()) {
      values_.resize(tape.instrs.size());
      rates_.resize(tape.instrs.size());
    }
  }

  // Over the box [x] x [y] x [z] and the directions [dx] x [dy] x [dz].
  IntervalSlope evaluate(Interval x, Interval y, Interval z, Interval dx, Interval dy, Interval dz);

 private:
  const FieldTape* tape_ = nullptr;
  std::vector<Interval> values_, rates_;
};

}  // namespace pf::field
