// The float form of a field, evaluated over a batch of points at once (a pixel block, or samples
// along rays): one pass over the tape per batch, each instruction a loop over the batch's lanes
// in SIMD -- Highway, dispatched at run time to the widest instruction set the machine has
// (slot_loops_simd.cpp), exp/log/sin/cos included. Values live in slots reused once their
// last reader has run, so a 7,866-instruction tape (Prospero) needs a few hundred slots.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compiler/field/field_tape.h"

namespace pf::field {

// One instruction of the float form: its operation on slots (value arrays of kBatch floats).
struct FloatSlotInstr {
  FieldOp op;
  uint16_t out, a, b;
  float value;     // Const
  uint16_t c = 0;  // Select's third operand
  const SampledGrid* grid = nullptr;  // Sample: the grid (held by the tape)
};

// A tape as instructions on slots, a slot reused once the last reader of its value has run, and
// a result never sharing a slot with an operand (so the loops have no aliasing). Shared by the
// float and the gradient forms.
struct SlotProgram {
  std::vector<FloatSlotInstr> code;
  int slot_count = 0;
  int result_slot = 0;
};
SlotProgram slotProgramOf(const FieldTape& tape);  // throws std::invalid_argument for an empty tape

// The working arrays of building a slot program, kept to build the next one without allocating.
struct SlotProgramScratch {
  std::vector<uint32_t> last_use;
  std::vector<uint16_t> slot_of;
  std::vector<uint16_t> free_slots;
};
// slotProgramOf(tape) into `program`, reusing its code's and the scratch's storage: once they
// have grown to the tapes' size, building allocates nothing. The same program, instruction for
// instruction, as slotProgramOf (which is this with fresh storage).
void buildSlotProgram(const FieldTape& tape, SlotProgram& program, SlotProgramScratch& scratch);

// Runs `code` over lanes [0, n) of the slots at `slots` (Highway, the best target of this
// machine). Lanes past n up to the next multiple of the vector width (<= 64) are computed too,
// on whatever they hold. x, y, z: n inputs each (z null: 0).
void runFloatSlots(const FloatSlotInstr* code, size_t count, float* slots, const float* x, const float* y,
                   const float* z, int n);
// The instruction set the dispatch chose ("AVX3", "AVX2", "SSE4", ...), for reports.
const char* floatSlotsTarget();
// The instruction sets the float loops can run on here, best first.
std::vector<std::string> floatSlotsTargets();
// Makes the float loops run on `name`, one of floatSlotsTargets() ("" or "best": the best again).
// False, nothing changed, for another name. Process-wide, for benchmarks and tests: call it while
// no field is being evaluated.
bool useFloatSlotsTarget(const std::string& name);

class FloatEvaluator {
 public:
  static constexpr int kBatch = 64;  // points per evaluate() call at most

  explicit FloatEvaluator(const FieldTape& tape);
  // No field yet: evaluate() gives zeros until reset() names one.
  FloatEvaluator() = default;
  // Makes this the evaluator of `tape`, reusing the program's and the slots' storage (as
  // GradientEvaluator::reset: a scratch evaluator for many short tapes, allocating nothing once
  // grown; the same values as FloatEvaluator(tape), bit for bit). Throws as the constructor
  // does, leaving the evaluator with no field.
  void reset(const FieldTape& tape);

  // out[i] = f(x[i], y[i], z[i]) for i < n (n <= kBatch). z may be null for a tape without var-z.
  void evaluate(const float* x, const float* y, const float* z, int n, float* out);
  // One point (tests, root polishing).
  float evaluate(float x, float y, float z);

  int slotCount() const { return program_.slot_count; }
  size_t instructionCount() const { return program_.code.size(); }

 private:
  SlotProgram program_;
  std::vector<float> slots_;  // slot_count x kBatch (at least)
  SlotProgramScratch scratch_;  // reset()'s
};

}  // namespace pf::field
