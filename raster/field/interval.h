// Sound interval arithmetic on floats, for the interval form of a field.
//
// Each operation is computed in double from the float endpoints and rounded outward to float:
// down for the lower end, up for the upper, stepping one float further whenever the double
// result was itself inexact (sums with a large exponent gap, quotients, square roots that are not
// exact, and every transcendental, which is also widened by one more float step because libm is
// only within an ulp). The result therefore encloses every value the float evaluator can produce
// for points in the box: correctly rounded float operations are monotone, so they cannot leave
// an outward-rounded enclosure of the exact range.
//
// NaN: an interval whose computation meets a NaN (0 * inf, inf - inf, sqrt or log of a negative
// part, division by an interval holding 0, sin of an infinite end) becomes the whole line
// [-inf, +inf], which means "any value, or NaN". Since fieldMin/fieldMax ignore a NaN operand,
// min and max of such an interval are still sound.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "compiler/field/field_tape.h"

namespace pf::field {

struct Interval {
  float lo = 0.0f, hi = 0.0f;

  static Interval whole() {
    return {-std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()};
  }
  static Interval point(float v) { return {v, v}; }
  bool isWhole() const { return lo == -std::numeric_limits<float>::infinity() && hi == std::numeric_limits<float>::infinity(); }
  bool contains(float v) const { return lo <= v && v <= hi; }
  bool allNegative() const { return hi < 0.0f; }      // every point outside (f < 0)
  bool allNonNegative() const { return lo >= 0.0f; }  // every point inside (f >= 0)
};

// The next float below / above v (v itself for -inf / +inf and NaN): std::nextafter without the
// library call, for the interval form's inner loop.
inline float floatBelow(float v) {
  if (!(v > -std::numeric_limits<float>::infinity())) return v;
  if (v == 0.0f) return -std::numeric_limits<float>::denorm_min();
  uint32_t bits;
  __builtin_memcpy(&bits, &v, 4);
  bits += v > 0.0f ? -1 : 1;
  __builtin_memcpy(&v, &bits, 4);
  return v;
}
inline float floatAbove(float v) { return -floatBelow(-v); }

Interval intervalAbs(Interval a);
Interval intervalSquare(Interval a);
Interval intervalSqrt(Interval a);
Interval intervalExp(Interval a);
Interval intervalLog(Interval a);
Interval intervalSin(Interval a);
Interval intervalCos(Interval a);
Interval intervalAtan(Interval a);
Interval intervalFloor(Interval a);
// A look-up in HyperFun's Perlin tables (FieldOp::NoisePerm ... NoiseGradZ) over a: the least and
// greatest entry its indices reach, exact; a NaN end gives the whole line.
Interval intervalNoiseTable(FieldOp op, Interval a);
Interval intervalDiv(Interval a, Interval b);

// The operations every field is made of most, inline: the interval evaluators' inner loops.
namespace interval_detail {

// The largest float <= d (one step lower still when d is not exact).
inline float roundDown(double d, bool exact) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d || (!exact && static_cast<double>(f) == d)) f = floatBelow(f);
  return f;
}
inline float roundUp(double d, bool exact) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) < d || (!exact && static_cast<double>(f) == d)) f = floatAbove(f);
  return f;
}
// [lo, hi] from double ends, or the whole line where either end is NaN.
inline Interval outward(double lo, double hi, bool exact) {
  if (std::isnan(lo) || std::isnan(hi)) return Interval::whole();
  return {roundDown(lo, exact), roundUp(hi, exact)};
}
// Whether a + b is exact in double (a and b floats, so the only loss is a large exponent gap).
inline bool sumExact(double a, double b, double sum) {
  if (std::fabs(a) < std::fabs(b)) {
    const double t = a;
    a = b;
    b = t;
  }
  return (sum - a) == b;  // Fast2Sum: the rounding error is b - (sum - a), computed exactly
}

}  // namespace interval_detail

inline Interval intervalNeg(Interval a) { return {-a.hi, -a.lo}; }

inline Interval intervalAdd(Interval a, Interval b) {
  using namespace interval_detail;
  const double lo = static_cast<double>(a.lo) + b.lo, hi = static_cast<double>(a.hi) + b.hi;
  if (std::isnan(lo) || std::isnan(hi)) return Interval::whole();
  return {roundDown(lo, sumExact(a.lo, b.lo, lo)), roundUp(hi, sumExact(a.hi, b.hi, hi))};
}

inline Interval intervalSub(Interval a, Interval b) { return intervalAdd(a, intervalNeg(b)); }

// A product of two floats is exact in double; a NaN product (0 * inf) makes the whole line.
inline Interval intervalMul(Interval a, Interval b) {
  const double p0 = static_cast<double>(a.lo) * b.lo, p1 = static_cast<double>(a.lo) * b.hi,
               p2 = static_cast<double>(a.hi) * b.lo, p3 = static_cast<double>(a.hi) * b.hi;
  if (std::isnan(p0) || std::isnan(p1) || std::isnan(p2) || std::isnan(p3)) return Interval::whole();
  double lo = p0, hi = p0;  // the first least and greatest, as std::min_element / max_element
  for (double p : {p1, p2, p3}) {
    if (p < lo) lo = p;
    if (hi < p) hi = p;
  }
  return interval_detail::outward(lo, hi, true);
}

inline Interval intervalMin(Interval a, Interval b) { return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)}; }
inline Interval intervalMax(Interval a, Interval b) { return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)}; }
// The smallest interval holding both (either may be NaN, so the whole line if either is).
inline Interval intervalHull(Interval a, Interval b) {
  if (a.isWhole() || b.isWhole()) return Interval::whole();
  return {a.lo < b.lo ? a.lo : b.lo, a.hi > b.hi ? a.hi : b.hi};
}

}  // namespace pf::field
