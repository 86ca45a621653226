// GradientEvaluator: slot storage and the batch interface (the SIMD loops are in
// slot_loops_simd.cpp).
#include "raster/field/gradient_evaluator.h"

#include <algorithm>

namespace pf::field {

GradientEvaluator::GradientEvaluator(const FieldTape& tape)
    : program_(slotProgramOf(tape)), slots_(static_cast<size_t>(program_.slot_count) * 4 * kBatch, 0.0f) {}

void GradientEvaluator::evaluate(const float* x, const float* y, const float* z, int n, FieldGradient* out) {
  n = std::clamp(n, 0, kBatch);
  runGradientSlots(program_.code.data(), program_.code.size(), slots_.data(), x, y, z, n);
  const float* r = slots_.data() + static_cast<size_t>(program_.result_slot) * 4 * kBatch;
  for (int i = 0; i < n; ++i) out[i] = {r[i], r[kBatch + i], r[2 * kBatch + i], r[3 * kBatch + i]};
}

FieldGradient GradientEvaluator::evaluate(float x, float y, float z) {
  FieldGradient g;
  evaluate(&x, &y, &z, 1, &g);
  return g;
}

}  // namespace pf::field
