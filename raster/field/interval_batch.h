// The interval form over many boxes at once: one pass over the tape for up to 64 boxes, each
// instruction a loop over the boxes compiled as vector code (AVX-512, AVX2 or the baseline:
// PF_SIMD_CLONES). Where the interval method judges every 8x8 block of a tile against the tile's
// simplified tape, the scalar evaluator's dispatch, operand loads and branches per instruction
// and per box were a third of a 2D model's frame; here they are paid once per instruction for
// all the boxes.
//
// The intervals are the scalar IntervalEvaluator's, bit for bit: the same operations in double
// with the same outward rounding (interval.h), branches written as selects. So are the choices
// of min, max and select, from which each box's tape is simplified -- a block judged in a batch
// draws exactly what it would draw judged alone. exp, log, sin, cos and atan call the scalar
// operations lane by lane.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/interval.h"

namespace pf::field {

class IntervalBatchEvaluator {
 public:
  static constexpr int kBoxes = 64;

  // The boxes of one evaluation: box j is [x_lo[j], x_hi[j]] x [y...] x [z...].
  struct Boxes {
    alignas(64) float x_lo[kBoxes], x_hi[kBoxes], y_lo[kBoxes], y_hi[kBoxes], z_lo[kBoxes], z_hi[kBoxes];
  };

  // Makes this the evaluator of `tape`, keeping the storage (none allocated once grown).
  void reset(const FieldTape& tape);

  // f over boxes [0, n) (n <= kBoxes) into out[j]. With `choices`, also each min/max/select's
  // proven operand per box: choice(i, j) afterwards, as IntervalEvaluator fills its vector.
  void evaluate(const Boxes& boxes, int n, Interval* out, bool choices);

  // Box j's choices, one per instruction (after an evaluate() with choices), into `out`.
  void choicesOf(int j, std::vector<Choice>& out) const;

 private:
  // The tape on slots (float_evaluator.h: a slot reused once its value's last reader has run),
  // instruction k of the program being instruction k of the tape.
  SlotProgram program_;
  SlotProgramScratch scratch_;
  // Per slot, kBoxes lower ends then kBoxes upper ends.
  std::vector<float> values_;
  std::vector<uint8_t> choices_;  // per instruction, kBoxes Choice values
  size_t instructions_ = 0;
};

}  // namespace pf::field
