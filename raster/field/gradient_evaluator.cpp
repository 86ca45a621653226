// GradientEvaluator: slot storage and the batch interface (the SIMD loops are in
// slot_loops_simd.cpp).
#include "raster/field/gradient_evaluator.h"

#include <algorithm>

namespace pf::field {

GradientEvaluator::GradientEvaluator(const FieldTape& tape)
    : program_(slotProgramOf(tape)), slots_(static_cast<size_t>(program_.slot_count) * 4 * kBatch, 0.0f) {}

void GradientEvaluator::reset(const FieldTape& tape) {
  try {
    buildSlotProgram(tape, program_, scratch_);
  } catch (...) {
    program_ = SlotProgram{};
    throw;
  }
  const size_t size = static_cast<size_t>(program_.slot_count) * 4 * kBatch;
  if (slots_.size() < size) slots_.resize(size, 0.0f);
}

void GradientEvaluator::evaluate(const float* x, const float* y, const float* z, int n, FieldGradient* out) {
  n = std::clamp(n, 0, kBatch);
  if (program_.code.empty()) {  // default-constructed: no field
    std::fill_n(out, n, FieldGradient{});
    return;
  }
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
