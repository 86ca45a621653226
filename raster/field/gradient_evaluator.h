// The gradient form of a field: forward-mode automatic differentiation over the tape. Every value
// carries its partial derivatives in x, y and z; the surface normal is the normalized negative
// gradient (f >= 0 inside, so -grad f points out). Not finite differences: exact up to float
// rounding wherever the field is differentiable; at a kink (min, max, abs) it takes the side the
// float form takes. Evaluated like the float form: over a batch of points at once, on slots,
// in SIMD (slot_loops_simd.cpp, Highway's run-time dispatch).
#pragma once

#include <vector>

#include "compiler/field/field_tape.h"
#include "raster/field/float_evaluator.h"

namespace pf::field {

struct FieldGradient {
  float value = 0.0f;
  float dx = 0.0f, dy = 0.0f, dz = 0.0f;
};

// Runs `code` over lanes [0, n) of gradient slots at `slots`: each slot is four arrays of
// FloatEvaluator::kBatch floats (value, d/dx, d/dy, d/dz). As runFloatSlots for the rest.
void runGradientSlots(const FloatSlotInstr* code, size_t count, float* slots, const float* x, const float* y,
                      const float* z, int n);

class GradientEvaluator {
 public:
  static constexpr int kBatch = FloatEvaluator::kBatch;

  explicit GradientEvaluator(const FieldTape& tape);
  // No field yet: evaluate() gives zeros until reset() names one.
  GradientEvaluator() = default;
  // Makes this the evaluator of `tape`, reusing the program's and the slots' storage: once they
  // have grown to the largest tape it has run, reset() allocates nothing. A scratch evaluator for
  // many short tapes, one after the other. The slots are not cleared: a lane's result never
  // depends on what they held (every slot an instruction reads, an earlier one of the same run
  // wrote), so the values are those of GradientEvaluator(tape), bit for bit. Throws as the
  // constructor does, leaving the evaluator with no field.
  void reset(const FieldTape& tape);
  // out[i] = f and its gradient at (x[i], y[i], z[i]) for i < n (n <= kBatch).
  void evaluate(const float* x, const float* y, const float* z, int n, FieldGradient* out);
  // One point: the batch's computation for one lane (the same value, bit for bit).
  FieldGradient evaluate(float x, float y, float z);

 private:
  SlotProgram program_;
  std::vector<float> slots_;  // slot_count x 4 x kBatch (at least)
  SlotProgramScratch scratch_;  // reset()'s
};

}  // namespace pf::field
