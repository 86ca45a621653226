// FloatEvaluator: slot allocation and the batched float loops.
#include "raster/field/float_evaluator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "compiler/field/field_scalar.h"

namespace pf::field {

FloatEvaluator::FloatEvaluator(const FieldTape& tape) {
  const size_t n = tape.instrs.size();
  if (n == 0) throw std::invalid_argument("FloatEvaluator: empty field tape");
  // The last instruction that reads each value; the result is read "after the end".
  std::vector<uint32_t> last_use(n, 0);
  for (uint32_t i = 0; i < n; ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    if (arity >= 1) last_use[in.a] = i;
    if (arity == 2) last_use[in.b] = i;
  }
  last_use[tape.result] = static_cast<uint32_t>(n);
  std::vector<uint16_t> slot_of(n, 0);
  std::vector<uint16_t> free_slots;
  code_.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    const FieldInstr& in = tape.instrs[i];
    const int arity = fieldOpArity(in.op);
    SlotInstr s{in.op, 0, 0, 0, in.value};
    if (arity >= 1) s.a = slot_of[in.a];
    if (arity == 2) s.b = slot_of[in.b];
    // The result takes a slot before the operands read for the last time free theirs: a result
    // never shares a slot with an operand, so the loops below have no aliasing to check for
    // and vectorize (GCC's cheap cost model at -O2 does not version loops for aliasing).
    if (free_slots.empty()) {
      if (slot_count_ == 0xffff) throw std::length_error("FloatEvaluator: field needs more than 65535 slots");
      s.out = static_cast<uint16_t>(slot_count_++);
    } else {
      s.out = free_slots.back();
      free_slots.pop_back();
    }
    if (arity >= 1 && last_use[in.a] == i) free_slots.push_back(s.a);
    if (arity == 2 && last_use[in.b] == i && in.b != in.a) free_slots.push_back(s.b);
    slot_of[i] = s.out;
    // A value nobody reads (only possible for the result) keeps its slot to the end.
    code_.push_back(s);
  }
  result_slot_ = slot_of[tape.result];
  slots_.assign(static_cast<size_t>(slot_count_) * kBatch, 0.0f);
}

void FloatEvaluator::evaluate(const float* x, const float* y, const float* z, int n, float* out) {
  n = std::clamp(n, 0, kBatch);
  float* base = slots_.data();
  for (const SlotInstr& in : code_) {
    float* __restrict o = base + static_cast<size_t>(in.out) * kBatch;
    const float* __restrict a = base + static_cast<size_t>(in.a) * kBatch;
    const float* __restrict b = base + static_cast<size_t>(in.b) * kBatch;
    switch (in.op) {
      case FieldOp::X: std::copy(x, x + n, o); break;
      case FieldOp::Y: std::copy(y, y + n, o); break;
      case FieldOp::Z:
        if (z) std::copy(z, z + n, o);
        else std::fill(o, o + n, 0.0f);
        break;
      case FieldOp::Const: std::fill(o, o + n, in.value); break;
      case FieldOp::Neg: for (int j = 0; j < n; ++j) o[j] = -a[j]; break;
      case FieldOp::Abs: for (int j = 0; j < n; ++j) o[j] = std::fabs(a[j]); break;
      case FieldOp::Square: for (int j = 0; j < n; ++j) o[j] = a[j] * a[j]; break;
      case FieldOp::Sqrt: for (int j = 0; j < n; ++j) o[j] = std::sqrt(a[j]); break;
      case FieldOp::Exp: for (int j = 0; j < n; ++j) o[j] = std::exp(a[j]); break;
      case FieldOp::Log: for (int j = 0; j < n; ++j) o[j] = std::log(a[j]); break;
      case FieldOp::Sin: for (int j = 0; j < n; ++j) o[j] = std::sin(a[j]); break;
      case FieldOp::Cos: for (int j = 0; j < n; ++j) o[j] = std::cos(a[j]); break;
      case FieldOp::Add: for (int j = 0; j < n; ++j) o[j] = a[j] + b[j]; break;
      case FieldOp::Sub: for (int j = 0; j < n; ++j) o[j] = a[j] - b[j]; break;
      case FieldOp::Mul: for (int j = 0; j < n; ++j) o[j] = a[j] * b[j]; break;
      case FieldOp::Div: for (int j = 0; j < n; ++j) o[j] = a[j] / b[j]; break;
      case FieldOp::Min: for (int j = 0; j < n; ++j) o[j] = fieldMin(a[j], b[j]); break;
      case FieldOp::Max: for (int j = 0; j < n; ++j) o[j] = fieldMax(a[j], b[j]); break;
    }
  }
  const float* r = base + static_cast<size_t>(result_slot_) * kBatch;
  std::copy(r, r + n, out);
}

float FloatEvaluator::evaluate(float x, float y, float z) {
  float out = 0.0f;
  evaluate(&x, &y, &z, 1, &out);
  return out;
}

}  // namespace pf::field
