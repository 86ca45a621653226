// The float form of a field, evaluated over a batch of points at once (a pixel block, or samples
// along rays): one pass over the tape per batch, each instruction a loop over the batch's lanes
// that the compiler vectorizes. Values live in slots reused once their last reader has run, so
// a 7,866-instruction tape (Prospero) needs a few hundred slots, not 7,866.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field {

class FloatEvaluator {
 public:
  static constexpr int kBatch = 64;  // points per evaluate() call at most

  explicit FloatEvaluator(const FieldTape& tape);

  // out[i] = f(x[i], y[i], z[i]) for i < n (n <= kBatch). z may be null for a tape without var-z.
  void evaluate(const float* x, const float* y, const float* z, int n, float* out);
  // One point (tests, root polishing).
  float evaluate(float x, float y, float z);

  int slotCount() const { return slot_count_; }
  size_t instructionCount() const { return code_.size(); }

 private:
  struct SlotInstr {
    FieldOp op;
    uint16_t out, a, b;  // slots
    float value;
  };
  std::vector<SlotInstr> code_;
  int slot_count_ = 0;
  int result_slot_ = 0;
  std::vector<float> slots_;  // slot_count_ x kBatch
};

}  // namespace pf::field
