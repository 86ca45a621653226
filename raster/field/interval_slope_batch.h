// The interval form with a directional derivative (interval_slope_evaluator.h) over many boxes
// at once: one pass over the tape for up to 64 (box, directions) pairs, each instruction a loop
// over them compiled as vector code, as IntervalBatchEvaluator does for the plain form. The
// interval method's sound search asks this of each lane of a 4x4-pixel slab at once -- is f
// monotone along the lane's ray over its bracket? -- where one lane at a time, with a dispatch
// per instruction, was a fifth of a frame of the bear.
//
// The results are IntervalSlopeEvaluator's, bit for bit (the same interval operations, lane for
// lane: interval_lanes.h; transcendentals call the scalar ones).
#pragma once

#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/interval_slope_evaluator.h"

namespace pf::field {

class IntervalSlopeBatchEvaluator {
 public:
  static constexpr int kBoxes = 64;

  // Pair j: the box [x_lo[j], x_hi[j]] x ... and the directions [dx_lo[j], dx_hi[j]] x ...
  struct Boxes {
    alignas(64) float x_lo[kBoxes], x_hi[kBoxes], y_lo[kBoxes], y_hi[kBoxes], z_lo[kBoxes], z_hi[kBoxes];
    alignas(64) float dx_lo[kBoxes], dx_hi[kBoxes], dy_lo[kBoxes], dy_hi[kBoxes], dz_lo[kBoxes], dz_hi[kBoxes];
  };

  // Makes this the evaluator of `tape`, keeping the storage (none allocated once grown).
  void reset(const FieldTape& tape);

  // f and its rate over pairs [0, n) (n <= kBoxes) into out[j]; the lanes run are n rounded up
  // to 16.
  void evaluate(const Boxes& boxes, int n, IntervalSlope* out);

 private:
  SlotProgram program_;
  SlotProgramScratch scratch_;
  // Per slot: kBoxes value lower ends, value upper ends, rate lower ends, rate upper ends.
  std::vector<float> values_;
};

}  // namespace pf::field
