// IntervalBatchEvaluator: the scalar interval operations of interval.h, lane for lane over up to
// 64 boxes, with their branches as selects so that GCC vectorizes each instruction's loop
// (-fno-trapping-math for this file: both arms of a select are computed). Every lane computes
// what the scalar operation computes, in the same order, from the same float and double
// operations; tests/field/interval_batch_test.cpp holds the two to the bit.
#include "raster/field/interval_batch.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "raster/simd_clones.h"

namespace pf::field {
namespace {

constexpr int K = IntervalBatchEvaluator::kBoxes;
constexpr float kInf = std::numeric_limits<float>::infinity();

// floatBelow / floatAbove (interval.h) without branches. (Here and below, & and | of bools, not
// && and ||: both sides are plain comparisons, and the short-circuit's branch would keep the
// loops from vectorizing.)
inline float below(float v) {
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  const float stepped = std::bit_cast<float>(bits + (v > 0.0f ? 0xffffffffu : 1u));
  const float r = v == 0.0f ? -std::numeric_limits<float>::denorm_min() : stepped;
  return !(v > -kInf) ? v : r;  // -inf and NaN stay
}
inline float above(float v) { return -below(-v); }

// interval_detail's roundDown, roundUp and sumExact (interval.h), as selects.
inline float roundDown(double d, bool exact) {
  const float f = static_cast<float>(d);
  const bool step = (static_cast<double>(f) > d) | (!exact & (static_cast<double>(f) == d));
  return step ? below(f) : f;
}
inline float roundUp(double d, bool exact) {
  const float f = static_cast<float>(d);
  const bool step = (static_cast<double>(f) < d) | (!exact & (static_cast<double>(f) == d));
  return step ? above(f) : f;
}
inline bool sumExact(double a, double b, double sum) {
  const bool swap = std::fabs(a) < std::fabs(b);
  const double big = swap ? b : a, small = swap ? a : b;
  return (sum - big) == small;
}
inline bool isNan(double v) { return v != v; }
inline bool whole(float lo, float hi) { return (lo == -kInf) & (hi == kInf); }

// minChoice (interval_evaluator.cpp): a of min(a, b) is the result where a <= b throughout.
// (As a float, 0, 1 or 2 -- Choice's values -- so that the loop stays in float lanes; the
// caller narrows it to bytes.)
inline float minChoice(float alo, float ahi, float blo, float bhi) {
  const bool decidable = !whole(alo, ahi) & !whole(blo, bhi);
  const float side = ahi <= blo ? 1.0f : bhi <= alo ? 2.0f : 0.0f;
  return decidable ? side : 0.0f;
}
// Narrows choices computed as floats (0, 1, 2) to the bytes IntervalBatchEvaluator keeps.
inline void storeChoices(const float* c, uint8_t* out) {
  for (int j = 0; j < K; ++j) out[j] = static_cast<uint8_t>(static_cast<int>(c[j]));
}

// interval.h's intervalAdd(a, b), with b = {-b.hi, -b.lo} for a subtraction.
inline void addLane(float alo, float ahi, float blo, float bhi, float& olo, float& ohi) {
  const double lo = static_cast<double>(alo) + blo, hi = static_cast<double>(ahi) + bhi;
  const bool nan = isNan(lo) | isNan(hi);
  const float rl = roundDown(lo, sumExact(alo, blo, lo)), rh = roundUp(hi, sumExact(ahi, bhi, hi));
  olo = nan ? -kInf : rl;
  ohi = nan ? kInf : rh;
}

// outward(lo, hi, exact) of four double candidates: the first least and the first greatest.
inline void outwardOf4(double p0, double p1, double p2, double p3, bool exact, float& olo, float& ohi) {
  const bool nan = isNan(p0) | isNan(p1) | isNan(p2) | isNan(p3);
  double lo = p0, hi = p0;
  lo = p1 < lo ? p1 : lo;
  hi = hi < p1 ? p1 : hi;
  lo = p2 < lo ? p2 : lo;
  hi = hi < p2 ? p2 : hi;
  lo = p3 < lo ? p3 : lo;
  hi = hi < p3 ? p3 : hi;
  const float rl = roundDown(lo, exact), rh = roundUp(hi, exact);
  olo = nan ? -kInf : rl;
  ohi = nan ? kInf : rh;
}

// intervalAbs.
inline void absLane(float alo, float ahi, float& olo, float& ohi) {
  const bool pos = alo >= 0.0f, neg = ahi <= 0.0f;
  float lo = 0.0f, hi = -alo < ahi ? ahi : -alo;  // std::max(-a.lo, a.hi)
  lo = neg ? -ahi : lo;
  hi = neg ? -alo : hi;
  olo = pos ? alo : lo;
  ohi = pos ? ahi : hi;
}

// intervalSqrt's root of one end.
inline float rootLane(float v, bool up) {
  const double d = std::sqrt(static_cast<double>(v));
  const float f = static_cast<float>(d);
  const bool exact = (static_cast<double>(f) == d) & (static_cast<double>(f) * f == static_cast<double>(v));
  return up ? roundUp(d, exact) : roundDown(d, exact);
}

// One instruction over the lanes: its result's ends and its operands' (restrict: a result never
// shares a slot with an operand), and where to write its choices (null: not asked).
PF_SIMD_CLONES void runInstruction(const FloatSlotInstr& in, float* __restrict olo, float* __restrict ohi,
                                   const float* __restrict alo_, const float* __restrict ahi_,
                                   const float* __restrict blo_, const float* __restrict bhi_,
                                   const float* __restrict clo_, const float* __restrict chi_,
                                   uint8_t* __restrict choice) {
  switch (in.op) {
    case FieldOp::Const:
      for (int j = 0; j < K; ++j) olo[j] = ohi[j] = in.value;
      return;
    case FieldOp::Neg:
      for (int j = 0; j < K; ++j) {
        const float lo = -ahi_[j], hi = -alo_[j];
        olo[j] = lo;
        ohi[j] = hi;
      }
      return;
    case FieldOp::Abs:
      for (int j = 0; j < K; ++j) absLane(alo_[j], ahi_[j], olo[j], ohi[j]);
      return;
    case FieldOp::Square:
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j];
        const bool pos = alo >= 0.0f, neg = ahi <= 0.0f;  // intervalAbs, then the squares of its ends
        float mlo = 0.0f, mhi = -alo < ahi ? ahi : -alo;  // (selects one at a time: they vectorize)
        mlo = neg ? -ahi : mlo;
        mhi = neg ? -alo : mhi;
        mlo = pos ? alo : mlo;
        mhi = pos ? ahi : mhi;
        const double lo = static_cast<double>(mlo) * mlo, hi = static_cast<double>(mhi) * mhi;
        const bool nan = isNan(lo) | isNan(hi);
        const float rl = roundDown(lo, true), rh = roundUp(hi, true);
        olo[j] = nan ? -kInf : rl;
        ohi[j] = nan ? kInf : rh;
      }
      return;
    case FieldOp::Sqrt:
      for (int j = 0; j < K; ++j) {
        const bool negative = alo_[j] < 0.0f;  // some points give NaN
        const float lo = rootLane(alo_[j], false), hi = rootLane(ahi_[j], true);
        olo[j] = negative ? -kInf : lo;
        ohi[j] = negative ? kInf : hi;
      }
      return;
    case FieldOp::Add:
      for (int j = 0; j < K; ++j) addLane(alo_[j], ahi_[j], blo_[j], bhi_[j], olo[j], ohi[j]);
      return;
    case FieldOp::Sub:
      for (int j = 0; j < K; ++j) addLane(alo_[j], ahi_[j], -bhi_[j], -blo_[j], olo[j], ohi[j]);
      return;
    case FieldOp::Mul:
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j], blo = blo_[j], bhi = bhi_[j];
        outwardOf4(static_cast<double>(alo) * blo, static_cast<double>(alo) * bhi, static_cast<double>(ahi) * blo,
                   static_cast<double>(ahi) * bhi, true, olo[j], ohi[j]);
      }
      return;
    case FieldOp::Div:
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j], blo = blo_[j], bhi = bhi_[j];
        const bool by_zero = (blo <= 0.0f) & (bhi >= 0.0f);  // division by (possibly) zero
        float lo, hi;
        outwardOf4(static_cast<double>(alo) / blo, static_cast<double>(alo) / bhi, static_cast<double>(ahi) / blo,
                   static_cast<double>(ahi) / bhi, false, lo, hi);
        olo[j] = by_zero ? -kInf : lo;
        ohi[j] = by_zero ? kInf : hi;
      }
      return;
    case FieldOp::Min:
    case FieldOp::Max: {
      const bool is_min = in.op == FieldOp::Min;
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j], blo = blo_[j], bhi = bhi_[j];
        // std::min(x, y) = y < x ? y : x; std::max(x, y) = x < y ? y : x.
        const float min_lo = blo < alo ? blo : alo, min_hi = bhi < ahi ? bhi : ahi;
        const float max_lo = alo < blo ? blo : alo, max_hi = ahi < bhi ? bhi : ahi;
        olo[j] = is_min ? min_lo : max_lo;
        ohi[j] = is_min ? min_hi : max_hi;
      }
      // max(a, b) is a where b <= a everywhere: minChoice(b, a).
      if (choice) {
        alignas(64) float c[K];
        if (is_min)
          for (int j = 0; j < K; ++j) c[j] = minChoice(alo_[j], ahi_[j], blo_[j], bhi_[j]);
        else
          for (int j = 0; j < K; ++j) c[j] = minChoice(blo_[j], bhi_[j], alo_[j], ahi_[j]);
        storeChoices(c, choice);
      }
      return;
    }
    case FieldOp::Less:
    case FieldOp::LessEq: {
      const bool or_equal = in.op == FieldOp::LessEq;
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j], blo = blo_[j], bhi = bhi_[j];
        const bool decidable = !whole(alo, ahi) & !whole(blo, bhi);
        const bool yes = decidable & (or_equal ? ahi <= blo : ahi < blo);
        const bool no = decidable & !yes & (or_equal ? alo > bhi : alo >= bhi);
        olo[j] = yes ? 1.0f : 0.0f;
        ohi[j] = no ? 0.0f : 1.0f;
      }
      return;
    }
    case FieldOp::Select:
      for (int j = 0; j < K; ++j) {
        const float alo = alo_[j], ahi = ahi_[j];
        const float blo = blo_[j], bhi = bhi_[j], clo = clo_[j], chi = chi_[j];
        const bool left = (!whole(alo, ahi)) & ((alo > 0.0f) | (ahi < 0.0f));
        const bool right = !whole(alo, ahi) & !left & (alo == 0.0f) & (ahi == 0.0f);
        // intervalHull(b, c)
        const bool any_whole = whole(blo, bhi) | whole(clo, chi);
        const float hull_lo = any_whole ? -kInf : (blo < clo ? blo : clo);
        const float hull_hi = any_whole ? kInf : (bhi > chi ? bhi : chi);
        olo[j] = left ? blo : right ? clo : hull_lo;
        ohi[j] = left ? bhi : right ? chi : hull_hi;
      }
      if (choice) {
        alignas(64) float c[K];
        for (int j = 0; j < K; ++j) {
          const float alo = alo_[j], ahi = ahi_[j];
          const bool left = (!whole(alo, ahi)) & ((alo > 0.0f) | (ahi < 0.0f));
          const bool right = !whole(alo, ahi) & !left & (alo == 0.0f) & (ahi == 0.0f);
          c[j] = left ? 1.0f : right ? 2.0f : 0.0f;
        }
        storeChoices(c, choice);
      }
      return;
    case FieldOp::Exp:
    case FieldOp::Log:
    case FieldOp::Sin:
    case FieldOp::Cos:
    case FieldOp::Atan: {
      // Transcendentals: the scalar operations, lane by lane.
      Interval (*op)(Interval) = in.op == FieldOp::Exp   ? intervalExp
                                 : in.op == FieldOp::Log ? intervalLog
                                 : in.op == FieldOp::Sin ? intervalSin
                                 : in.op == FieldOp::Cos ? intervalCos
                                                         : intervalAtan;
      for (int j = 0; j < K; ++j) {
        const Interval r = op({alo_[j], ahi_[j]});
        olo[j] = r.lo;
        ohi[j] = r.hi;
      }
      return;
    }
    case FieldOp::X:
    case FieldOp::Y:
    case FieldOp::Z: return;  // (the evaluator copies the boxes in)
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
  float* const base = values_.data();
  for (size_t k = 0; k < count; ++k) {
    const FloatSlotInstr& in = program_.code[k];
    float* const o = base + static_cast<size_t>(in.out) * 2 * K;
    if (in.op == FieldOp::X || in.op == FieldOp::Y || in.op == FieldOp::Z) {
      const float* lo = in.op == FieldOp::X ? boxes.x_lo : in.op == FieldOp::Y ? boxes.y_lo : boxes.z_lo;
      const float* hi = in.op == FieldOp::X ? boxes.x_hi : in.op == FieldOp::Y ? boxes.y_hi : boxes.z_hi;
      // Lanes past n repeat box 0, so every lane holds a box.
      for (int j = 0; j < K; ++j) {
        o[j] = lo[j < n ? j : 0];
        o[K + j] = hi[j < n ? j : 0];
      }
      continue;
    }
    const float* const a = base + static_cast<size_t>(in.a) * 2 * K;
    const float* const b = base + static_cast<size_t>(in.b) * 2 * K;
    const float* const c = base + static_cast<size_t>(in.c) * 2 * K;
    runInstruction(in, o, o + K, a, a + K, b, b + K, c, c + K, choices ? choices_.data() + k * K : nullptr);
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
