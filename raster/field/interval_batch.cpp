// IntervalBatchEvaluator: the scalar interval operations of interval.h, lane for lane over up to
// 64 boxes, with their branches as selects so that GCC vectorizes each instruction's loop
// (-fno-trapping-math for this file: both arms of a select are computed). Every lane computes
// what the scalar operation computes, in the same order, from the same float and double
// operations; tests/field/interval_batch_test.cpp holds the two to the bit.
#include "raster/field/interval_batch.h"

#include "raster/field/interval_lanes.h"
#include "raster/field/sampled_bounds.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "raster/simd_clones.h"

namespace pf::field {
namespace {

constexpr int K = IntervalBatchEvaluator::kBoxes;
using namespace interval_lanes;

// minChoice (interval_evaluator.cpp): a of min(a, b) is the result where a <= b throughout.
// (As a float, 0, 1 or 2 -- Choice's values -- so that the loop stays in float lanes; the
// caller narrows it to bytes.)
inline float minChoice(float alo, float ahi, float blo, float bhi) {
  const bool decidable = !whole(alo, ahi) & !whole(blo, bhi);
  const float side = ahi <= blo ? 1.0f : bhi <= alo ? 2.0f : 0.0f;
  return decidable ? side : 0.0f;
}
// Narrows choices computed as floats (0, 1, 2) to the bytes IntervalBatchEvaluator keeps.
inline void storeChoices(const float* c, int n, uint8_t* out) {
  for (int j = 0; j < n; ++j) out[j] = static_cast<uint8_t>(static_cast<int>(c[j]));
}

// One instruction over lanes [0, n) (n a multiple of 16): its result's ends and its operands'
// (restrict: a result never shares a slot with an operand), and where to write its choices
// (null: not asked).
PF_SIMD_CLONES void runInstruction(const FloatSlotInstr& in, int n, float* __restrict olo, float* __restrict ohi,
                                   const float* __restrict alo, const float* __restrict ahi,
                                   const float* __restrict blo, const float* __restrict bhi,
                                   const float* __restrict clo, const float* __restrict chi,
                                   uint8_t* __restrict choice) {
  switch (in.op) {
    case FieldOp::Const:
      for (int j = 0; j < n; ++j) olo[j] = ohi[j] = in.value;
      return;
    case FieldOp::Neg:
      for (int j = 0; j < n; ++j) {
        const float lo = -ahi[j], hi = -alo[j];
        olo[j] = lo;
        ohi[j] = hi;
      }
      return;
    case FieldOp::Abs:
      for (int j = 0; j < n; ++j) absLane(alo[j], ahi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Square:
      for (int j = 0; j < n; ++j) squareLane(alo[j], ahi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Sqrt:
      for (int j = 0; j < n; ++j) sqrtLane(alo[j], ahi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Add:
      for (int j = 0; j < n; ++j) addLane(alo[j], ahi[j], blo[j], bhi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Sub:  // a + (-b)
      for (int j = 0; j < n; ++j) addLane(alo[j], ahi[j], -bhi[j], -blo[j], olo[j], ohi[j]);
      return;
    case FieldOp::Mul:
      for (int j = 0; j < n; ++j) mulLane(alo[j], ahi[j], blo[j], bhi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Div:
      for (int j = 0; j < n; ++j) divLane(alo[j], ahi[j], blo[j], bhi[j], olo[j], ohi[j]);
      return;
    case FieldOp::Min:
    case FieldOp::Max: {
      const bool is_min = in.op == FieldOp::Min;
      for (int j = 0; j < n; ++j) {
        const float a0 = alo[j], a1 = ahi[j], b0 = blo[j], b1 = bhi[j];
        // std::min(x, y) = y < x ? y : x; std::max(x, y) = x < y ? y : x.
        const float min_lo = b0 < a0 ? b0 : a0, min_hi = b1 < a1 ? b1 : a1;
        const float max_lo = a0 < b0 ? b0 : a0, max_hi = a1 < b1 ? b1 : a1;
        olo[j] = is_min ? min_lo : max_lo;
        ohi[j] = is_min ? min_hi : max_hi;
      }
      // max(a, b) is a where b <= a everywhere: minChoice(b, a).
      if (choice) {
        alignas(64) float c[K];
        if (is_min)
          for (int j = 0; j < n; ++j) c[j] = minChoice(alo[j], ahi[j], blo[j], bhi[j]);
        else
          for (int j = 0; j < n; ++j) c[j] = minChoice(blo[j], bhi[j], alo[j], ahi[j]);
        storeChoices(c, n, choice);
      }
      return;
    }
    case FieldOp::Less:
    case FieldOp::LessEq: {
      const bool or_equal = in.op == FieldOp::LessEq;
      for (int j = 0; j < n; ++j) {
        const float a0 = alo[j], a1 = ahi[j], b0 = blo[j], b1 = bhi[j];
        const bool decidable = !whole(a0, a1) & !whole(b0, b1);
        const bool yes = decidable & (or_equal ? a1 <= b0 : a1 < b0);
        const bool no = decidable & !yes & (or_equal ? a0 > b1 : a0 >= b1);
        olo[j] = yes ? 1.0f : 0.0f;
        ohi[j] = no ? 0.0f : 1.0f;
      }
      return;
    }
    case FieldOp::Select:
      for (int j = 0; j < n; ++j) {
        const float a0 = alo[j], a1 = ahi[j];
        const bool left = (!whole(a0, a1)) & ((a0 > 0.0f) | (a1 < 0.0f));
        const bool right = !whole(a0, a1) & !left & (a0 == 0.0f) & (a1 == 0.0f);
        float hull_lo, hull_hi;
        hullLane(blo[j], bhi[j], clo[j], chi[j], hull_lo, hull_hi);
        olo[j] = left ? blo[j] : right ? clo[j] : hull_lo;
        ohi[j] = left ? bhi[j] : right ? chi[j] : hull_hi;
      }
      if (choice) {
        alignas(64) float c[K];
        for (int j = 0; j < n; ++j) {
          const float a0 = alo[j], a1 = ahi[j];
          const bool left = (!whole(a0, a1)) & ((a0 > 0.0f) | (a1 < 0.0f));
          const bool right = !whole(a0, a1) & !left & (a0 == 0.0f) & (a1 == 0.0f);
          c[j] = left ? 1.0f : right ? 2.0f : 0.0f;
        }
        storeChoices(c, n, choice);
      }
      return;
    case FieldOp::Exp:
    case FieldOp::Log:
    case FieldOp::Sin:
    case FieldOp::Cos:
    case FieldOp::Atan:
    case FieldOp::Floor: {
      // Transcendentals and floor: the scalar operations, lane by lane.
      Interval (*op)(Interval) = in.op == FieldOp::Exp   ? intervalExp
                                 : in.op == FieldOp::Log ? intervalLog
                                 : in.op == FieldOp::Sin ? intervalSin
                                 : in.op == FieldOp::Cos ? intervalCos
                                 : in.op == FieldOp::Atan ? intervalAtan
                                                          : intervalFloor;
      for (int j = 0; j < n; ++j) {
        const Interval r = op({alo[j], ahi[j]});
        olo[j] = r.lo;
        ohi[j] = r.hi;
      }
      return;
    }
    case FieldOp::NoisePerm:
    case FieldOp::NoiseGradX:
    case FieldOp::NoiseGradY:
    case FieldOp::NoiseGradZ:  // table look-ups: the scalar operation, lane by lane
      for (int j = 0; j < n; ++j) {
        const Interval r = intervalNoiseTable(in.op, {alo[j], ahi[j]});
        olo[j] = r.lo;
        ohi[j] = r.hi;
      }
      return;
    case FieldOp::X:
    case FieldOp::Y:
    case FieldOp::Z:
    case FieldOp::Sample: return;  // (the evaluator fills these from the boxes)
  }
}

}  // namespace

void IntervalBatchEvaluator::reset(const FieldTape& tape) {
  try {
    buildSlotProgram(tape, program_, scratch_);
  } catch (...) {
    program_ = SlotProgram{};
    throw;
  }
  const size_t size = static_cast<size_t>(program_.slot_count) * 2 * K;
  if (values_.size() < size) values_.resize(size, 0.0f);
  if (choices_.size() < program_.code.size() * K) choices_.resize(program_.code.size() * K, 0);
}

void IntervalBatchEvaluator::evaluate(const Boxes& boxes, int n, Interval* out, bool choices) {
  n = n < 0 ? 0 : n > K ? K : n;
  if (program_.code.empty()) {
    for (int j = 0; j < n; ++j) out[j] = Interval::whole();
    return;
  }
  const size_t count = program_.code.size();
  if (choices) std::memset(choices_.data(), static_cast<int>(Choice::Both), count * K);
  // The lanes run: n rounded up to whole 16-lane groups (a few boxes cost a group, not 64).
  const int lanes = (n + 15) / 16 * 16;
  float* const base = values_.data();
  for (size_t k = 0; k < count; ++k) {
    const FloatSlotInstr& in = program_.code[k];
    float* const o = base + static_cast<size_t>(in.out) * 2 * K;
    if (in.op == FieldOp::X || in.op == FieldOp::Y || in.op == FieldOp::Z) {
      const float* lo = in.op == FieldOp::X ? boxes.x_lo : in.op == FieldOp::Y ? boxes.y_lo : boxes.z_lo;
      const float* hi = in.op == FieldOp::X ? boxes.x_hi : in.op == FieldOp::Y ? boxes.y_hi : boxes.z_hi;
      // Lanes past n repeat box 0, so every lane run holds a box.
      for (int j = 0; j < lanes; ++j) {
        o[j] = lo[j < n ? j : 0];
        o[K + j] = hi[j < n ? j : 0];
      }
      continue;
    }
    if (in.op == FieldOp::Sample) {  // the grid over each box (lanes past n: box 0)
      for (int j = 0; j < lanes; ++j) {
        const int q = j < n ? j : 0;
        const Interval r = sampleInterval(*in.grid, {boxes.x_lo[q], boxes.x_hi[q]}, {boxes.y_lo[q], boxes.y_hi[q]},
                                          {boxes.z_lo[q], boxes.z_hi[q]});
        o[j] = r.lo;
        o[K + j] = r.hi;
      }
      continue;
    }
    const float* const a = base + static_cast<size_t>(in.a) * 2 * K;
    const float* const b = base + static_cast<size_t>(in.b) * 2 * K;
    const float* const c = base + static_cast<size_t>(in.c) * 2 * K;
    runInstruction(in, lanes, o, o + K, a, a + K, b, b + K, c, c + K, choices ? choices_.data() + k * K : nullptr);
  }
  const float* const r = base + static_cast<size_t>(program_.result_slot) * 2 * K;
  for (int j = 0; j < n; ++j) out[j] = {r[j], r[K + j]};
}

void IntervalBatchEvaluator::choicesOf(int j, std::vector<Choice>& out) const {
  const size_t count = program_.code.size();
  out.resize(count);
  for (size_t k = 0; k < count; ++k) out[k] = static_cast<Choice>(choices_[k * K + static_cast<size_t>(j)]);
}

}  // namespace pf::field
