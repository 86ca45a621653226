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

#include <cmath>
#include <cstdint>
#include <limits>

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

Interval intervalNeg(Interval a);
Interval intervalAbs(Interval a);
Interval intervalSquare(Interval a);
Interval intervalSqrt(Interval a);
Interval intervalExp(Interval a);
Interval intervalLog(Interval a);
Interval intervalSin(Interval a);
Interval intervalCos(Interval a);
Interval intervalAtan(Interval a);
Interval intervalAdd(Interval a, Interval b);
Interval intervalSub(Interval a, Interval b);
Interval intervalMul(Interval a, Interval b);
Interval intervalDiv(Interval a, Interval b);
Interval intervalMin(Interval a, Interval b);
Interval intervalMax(Interval a, Interval b);
// The smallest interval holding both (either may be NaN, so the whole line if either is).
inline Interval intervalHull(Interval a, Interval b) {
  if (a.isWhole() || b.isWhole()) return Interval::whole();
  return {a.lo < b.lo ? a.lo : b.lo, a.hi > b.hi ? a.hi : b.hi};
}

}  // namespace pf::field
