// The interval operations of interval.h for one lane of a batch (IntervalBatchEvaluator,
// IntervalSlopeBatchEvaluator): the same float and double operations in the same order, so the
// same bits as the scalar operations, with every branch written as a select so that a loop of
// them over the lanes vectorizes. (& and | of bools, not && and ||: both sides are plain
// comparisons, and the short-circuit's branch would keep the loops from vectorizing. Files that
// use these compile with -fno-trapping-math, which lets GCC compute both arms of a select.)
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pf::field::interval_lanes {

constexpr float kInf = std::numeric_limits<float>::infinity();

// floatBelow / floatAbove (interval.h) without branches.
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

inline bool finite(float lo, float hi) { return std::isfinite(lo) & std::isfinite(hi); }

// intervalMul: the four products (exact in double), outward.
inline void mulLane(float alo, float ahi, float blo, float bhi, float& olo, float& ohi) {
  outwardOf4(static_cast<double>(alo) * blo, static_cast<double>(alo) * bhi, static_cast<double>(ahi) * blo,
             static_cast<double>(ahi) * bhi, true, olo, ohi);
}

// intervalDiv: the whole line where the divisor may be 0, else the four quotients, outward.
inline void divLane(float alo, float ahi, float blo, float bhi, float& olo, float& ohi) {
  const bool by_zero = (blo <= 0.0f) & (bhi >= 0.0f);
  float lo, hi;
  outwardOf4(static_cast<double>(alo) / blo, static_cast<double>(alo) / bhi, static_cast<double>(ahi) / blo,
             static_cast<double>(ahi) / bhi, false, lo, hi);
  olo = by_zero ? -kInf : lo;
  ohi = by_zero ? kInf : hi;
}

// intervalSquare: the squares of intervalAbs's ends. (Its selects one at a time: they vectorize.)
inline void squareLane(float alo, float ahi, float& olo, float& ohi) {
  const bool pos = alo >= 0.0f, neg = ahi <= 0.0f;
  float mlo = 0.0f, mhi = -alo < ahi ? ahi : -alo;
  mlo = neg ? -ahi : mlo;
  mhi = neg ? -alo : mhi;
  mlo = pos ? alo : mlo;
  mhi = pos ? ahi : mhi;
  const double lo = static_cast<double>(mlo) * mlo, hi = static_cast<double>(mhi) * mhi;
  const bool nan = isNan(lo) | isNan(hi);
  const float rl = roundDown(lo, true), rh = roundUp(hi, true);
  olo = nan ? -kInf : rl;
  ohi = nan ? kInf : rh;
}

// intervalSqrt: the whole line where some point gives NaN.
inline void sqrtLane(float alo, float ahi, float& olo, float& ohi) {
  const bool negative = alo < 0.0f;
  const float lo = rootLane(alo, false), hi = rootLane(ahi, true);
  olo = negative ? -kInf : lo;
  ohi = negative ? kInf : hi;
}

// intervalHull: the whole line if either is.
inline void hullLane(float alo, float ahi, float blo, float bhi, float& olo, float& ohi) {
  const bool any_whole = whole(alo, ahi) | whole(blo, bhi);
  olo = any_whole ? -kInf : (alo < blo ? alo : blo);
  ohi = any_whole ? kInf : (ahi > bhi ? ahi : bhi);
}

}  // namespace pf::field::interval_lanes
