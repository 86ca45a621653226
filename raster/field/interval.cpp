// Interval operations with outward rounding (see interval.h for the rules).
#include "raster/field/interval.h"

#include <algorithm>
#include <numbers>

#include "compiler/field/perlin_tables.h"

namespace pf::field {
using namespace interval_detail;
namespace {

// A transcendental's double ends are within an ulp of double: one more float step each way.
Interval outwardLibm(double lo, double hi) {
  Interval r = outward(lo, hi, false);
  if (r.isWhole()) return r;
  return {floatBelow(r.lo), floatAbove(r.hi)};
}

}  // namespace

Interval intervalAbs(Interval a) {
  if (a.lo >= 0.0f) return a;
  if (a.hi <= 0.0f) return {-a.hi, -a.lo};
  return {0.0f, std::max(-a.lo, a.hi)};
}

Interval intervalSquare(Interval a) {
  const Interval m = intervalAbs(a);
  const double lo = static_cast<double>(m.lo) * m.lo, hi = static_cast<double>(m.hi) * m.hi;
  return outward(lo, hi, true);  // a product of two floats is exact in double
}

Interval intervalSqrt(Interval a) {
  if (a.lo < 0.0f) return Interval::whole();  // some points give NaN
  auto root = [](float v, bool up) {
    const double d = std::sqrt(static_cast<double>(v));
    const float f = static_cast<float>(d);
    const bool exact = static_cast<double>(f) == d && static_cast<double>(f) * f == static_cast<double>(v);
    return up ? roundUp(d, exact) : roundDown(d, exact);
  };
  return {root(a.lo, false), root(a.hi, true)};
}

Interval intervalExp(Interval a) {
  Interval r = outwardLibm(std::exp(static_cast<double>(a.lo)), std::exp(static_cast<double>(a.hi)));
  r.lo = std::max(r.lo, 0.0f);
  return r;
}

Interval intervalLog(Interval a) {
  if (a.lo < 0.0f || std::isnan(a.lo)) return Interval::whole();
  return outwardLibm(std::log(static_cast<double>(a.lo)), std::log(static_cast<double>(a.hi)));
}

// atan is increasing; a NaN-able operand (the whole line) stays NaN-able.
Interval intervalAtan(Interval a) {
  if (a.isWhole() || std::isnan(a.lo) || std::isnan(a.hi)) return Interval::whole();
  return outwardLibm(std::atan(static_cast<double>(a.lo)), std::atan(static_cast<double>(a.hi)));
}

// floor is non-decreasing and exact in float: [floor(lo), floor(hi)]; a NaN end stays NaN-able.
Interval intervalFloor(Interval a) {
  if (std::isnan(a.lo) || std::isnan(a.hi)) return Interval::whole();
  return {std::floor(a.lo), std::floor(a.hi)};
}

Interval intervalNoiseTable(FieldOp op, Interval a) {
  const PerlinRange r = perlinTableRange(op, a.lo, a.hi);
  if (r.nan) return Interval::whole();
  return {r.lo, r.hi};
}

// sin over [lo, hi] reaches +1 where lo <= pi/2 + 2k pi <= hi, and -1 at -pi/2 + 2k pi.
static Interval periodicRange(Interval a, double phase_max, double (*fn)(double)) {
  if (!std::isfinite(a.lo) || !std::isfinite(a.hi)) return Interval::whole();
  const double two_pi = 2.0 * std::numbers::pi;
  if (static_cast<double>(a.hi) - a.lo >= two_pi || std::fabs(a.lo) > 1e6f || std::fabs(a.hi) > 1e6f)
    return {-1.0f, 1.0f};
  auto reaches = [&](double phase) {
    const double k = std::ceil((a.lo - phase) / two_pi);
    return phase + k * two_pi <= a.hi;
  };
  const double f_lo = fn(a.lo), f_hi = fn(a.hi);
  double lo = std::min(f_lo, f_hi), hi = std::max(f_lo, f_hi);
  if (reaches(phase_max)) hi = 1.0;
  if (reaches(phase_max + std::numbers::pi)) lo = -1.0;
  Interval r = outwardLibm(lo, hi);
  return {std::max(r.lo, -1.0f), std::min(r.hi, 1.0f)};
}

Interval intervalSin(Interval a) { return periodicRange(a, std::numbers::pi / 2, [](double x) { return std::sin(x); }); }
Interval intervalCos(Interval a) { return periodicRange(a, 0.0, [](double x) { return std::cos(x); }); }

Interval intervalDiv(Interval a, Interval b) {
  if (b.lo <= 0.0f && b.hi >= 0.0f) return Interval::whole();  // division by (possibly) zero
  const double q[4] = {static_cast<double>(a.lo) / b.lo, static_cast<double>(a.lo) / b.hi,
                       static_cast<double>(a.hi) / b.lo, static_cast<double>(a.hi) / b.hi};
  for (double v : q)
    if (std::isnan(v)) return Interval::whole();
  return outward(*std::min_element(q, q + 4), *std::max_element(q, q + 4), false);
}


}  // namespace pf::field
