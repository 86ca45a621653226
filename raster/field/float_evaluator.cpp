// Slot programs and FloatEvaluator (the SIMD loops are in slot_loops_simd.cpp).
#include "raster/field/float_evaluator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pf::field {

void buildSlotProgram(const FieldTape& tape, SlotProgram& p, SlotProgramScratch& scratch) {
  const size_t n = tape.instrs.size();
  if (n == 0) throw std::invalid_argument("field evaluator: empty field tape");
  p.code.clear();
  p.slot_count = 0;
  p.result_slot = 0;
  // The last instruction that reads each value; the result is read "after the end".
  std::vector<uint32_t>& last_use = scratch.last_use;
  last_use.assign(n, 0);
  for (uint32_t i = 0; i < n; ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    if (arity >= 1) last_use[in.a] = i;
    if (arity >= 2) last_use[in.b] = i;
    if (arity == 3) last_use[in.c] = i;
  }
  last_use[tape.result] = static_cast<uint32_t>(n);
  std::vector<uint16_t>& slot_of = scratch.slot_of;
  slot_of.assign(n, 0);
  std::vector<uint16_t>& free_slots = scratch.free_slots;
  free_slots.clear();
  p.code.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    FloatSlotInstr s{in.op, 0, 0, 0, in.value};
    if (in.op == FieldOp::Sample) s.grid = tape.grids.at(static_cast<size_t>(in.value)).get();
    if (arity >= 1) s.a = slot_of[in.a];
    if (arity >= 2) s.b = slot_of[in.b];
    if (arity == 3) s.c = slot_of[in.c];
    // The result takes a slot before the operands read for the last time free theirs: a result
    // never shares a slot with an operand, so the SIMD loops may take them as restrict.
    if (free_slots.empty()) {
      if (p.slot_count == 0xffff) throw std::length_error("field evaluator: field needs more than 65535 slots");
      s.out = static_cast<uint16_t>(p.slot_count++);
    } else {
      s.out = free_slots.back();
      free_slots.pop_back();
    }
    if (arity >= 1 && last_use[in.a] == i) free_slots.push_back(s.a);
    if (arity >= 2 && last_use[in.b] == i && in.b != in.a) free_slots.push_back(s.b);
    if (arity == 3 && last_use[in.c] == i && in.c != in.a && in.c != in.b) free_slots.push_back(s.c);
    slot_of[i] = s.out;
    // A value nobody reads (only possible for the result) keeps its slot to the end.
    p.code.push_back(s);
  }
  p.result_slot = slot_of[tape.result];
}

SlotProgram slotProgramOf(const FieldTape& tape) {
  SlotProgram p;
  SlotProgramScratch scratch;
  buildSlotProgram(tape, p, scratch);
  return p;
}

FloatEvaluator::FloatEvaluator(const FieldTape& tape)
    : program_(slotProgramOf(tape)), slots_(static_cast<size_t>(program_.slot_count) * kBatch, 0.0f) {}

void FloatEvaluator::reset(const FieldTape& tape) {
  try {
    buildSlotProgram(tape, program_, scratch_);
  } catch (...) {
    program_ = SlotProgram{};
    throw;
  }
  const size_t size = static_cast<size_t>(program_.slot_count) * kBatch;
  if (slots_.size() < size) slots_.resize(size, 0.0f);
}

void FloatEvaluator::evaluate(const float* x, const float* y, const float* z, int n, float* out) {
  n = std::clamp(n, 0, kBatch);
  if (program_.code.empty()) {
    std::fill(out, out + n, 0.0f);
    return;
  }
  runFloatSlots(program_.code.data(), program_.code.size(), slots_.data(), x, y, z, n);
  const float* r = slots_.data() + static_cast<size_t>(program_.result_slot) * kBatch;
  std::copy(r, r + n, out);
}

float FloatEvaluator::evaluate(float x, float y, float z) {
  float out = 0.0f;
  evaluate(&x, &y, &z, 1, &out);
  return out;
}

}  // namespace pf::field
