// The power function of GL's lighting equation (GL 1.5 section 2.14.1): the specular term
// (n.h)^shininess and the spot factor (-VP.s)^exponent, bases in [0, 1] and exponents in
// [0, 128] (glMaterial and glLight refuse others).
//
// Why not std::pow: the shading pass lights a row of pixels in loops that GCC vectorizes, and a
// call to the C library's powf is the one thing in them it cannot -- a light's specular term was
// a third of the time of a lit sphere filling a quarter of the frame. lightPow is written in
// plain IEEE double arithmetic with selects, no calls and no branches, so the same inline
// definition vectorizes in LightingEquation::shadeRun and runs scalar in shade() (per vertex,
// per point), and the two agree to the bit, on every machine (no contraction: CMakeLists'
// -ffp-contract=off).
//
// Two ways, chosen by the exponent, each far more exact than a float:
// - a whole exponent e (shininess is almost always one: 10, 32, 64, 128): x^e by binary
//   powering in double (lightPowWhole), at most 7 squarings and 8 products, each rounding by at
//   most 2^-53, so the relative error stays below 128 * 2^-53 ~ 1.4e-14 -- a few times cheaper
//   than a logarithm and an exponential, and the shading pass runs it with the exponent uniform
//   over a run (wholePowers);
// - any other: exp(y ln x) in double (lightPowExpLog), ln x from the float's exponent and an
//   atanh series for the mantissa, exp from Cody and Waite's reduction and a Taylor polynomial;
//   their relative error is ~1e-14.
// Either is far below a float's half ulp, so the float result is the correctly rounded power
// except within ~2e-7 ulp of a rounding tie (tests/unit/light_pow_test.cpp checks it against
// double std::pow).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace pf {

namespace detail {
// c[0] x^(N-1) + ... + c[N-1] by Horner's rule, highest coefficient first (a loop of constant
// trip count: unrolled, and the same operations in the same order wherever it is inlined).
template <size_t N>
inline double horner(double x, const double (&c)[N]) {
  double p = c[0];
  for (size_t i = 1; i < N; ++i) p = p * x + c[i];
  return p;
}
}  // namespace detail

// The largest whole exponent lightPowWhole takes: GL's largest shininess and spot exponent.
constexpr int kLightPowMaxWhole = 128;

// Whether lightPow takes exponent y as a whole number (lightPowWhole): y in [0, 128] with no
// fraction. NaN is not.
inline bool lightPowIsWhole(float y) {
  const bool in_range = y >= 0.0f && y <= static_cast<float>(kLightPowMaxWhole);
  const int e = in_range ? static_cast<int>(y) : 0;
  return in_range && static_cast<float>(e) == y;
}

// The double x^e of lightPowWhole before its edges, e in [0, 128]: the powers x^(2^k) of the
// bits of e multiplied in from the lowest bit up (a loop of constant trip count: unrolled, and
// the same operations in the same order wherever it is inlined; wholePowers runs the same
// products).
inline double wholePower(double x, int e) {
  double power = 1.0, square = x;
  for (int bit = 0; bit < 8; ++bit) {
    power = (e >> bit) & 1 ? power * square : power;
    square = square * square;
  }
  return power;
}

// lightPow's edges for a whole exponent, as C's powf has them: x^0 = 1, a negative x (outside
// the lighting equation's domain) NaN.
inline float wholePowerEdges(float x, int e, double power) {
  float out = static_cast<float>(power);
  out = x < 0.0f ? __builtin_nanf("") : out;
  out = e == 0 ? 1.0f : out;
  return out;
}

// x^e for a whole e in [0, 128] (lightPowIsWhole), x >= 0 or NaN: 0^e = 0 for e > 0, inf^e = inf,
// NaN^e = NaN for e > 0; overflow gives inf and underflow 0, as powf.
inline float lightPowWhole(float x, int e) { return wholePowerEdges(x, e, wholePower(x, e)); }

// x^y through exp(y ln x) for x >= 0 (or NaN) and finite y, as C's powf gives it there: x^0 = 1
// and 1^y = 1, 0^y = 0 for y > 0 and +inf for y < 0, +inf^y = +inf for y > 0 and 0 for y < 0,
// NaN in, NaN out. A negative x, outside the lighting equation's domain, gives NaN.
inline float lightPowExpLog(float x, float y) {
  // ln x = e ln 2 + ln m, with x = m 2^e and m in [sqrt(1/2), sqrt(2)). A subnormal x is scaled
  // by 2^24 first (exactly) to give its mantissa the leading bit.
  const bool subnormal = x < 0x1p-126f;
  const float xs = subnormal ? x * 0x1p24f : x;
  const uint32_t bits = std::bit_cast<uint32_t>(xs);
  int e = static_cast<int>((bits >> 23) & 0xffu) - 127 - (subnormal ? 24 : 0);
  float m = std::bit_cast<float>((bits & 0x7fffffu) | 0x3f800000u);  // [1, 2)
  const bool high = m > 1.41421356f;
  m = high ? m * 0.5f : m;
  e = high ? e + 1 : e;
  // ln m = 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...), s = (m - 1) / (m + 1), |s| <= 0.1716: nine
  // terms leave a relative error below 1e-15.
  const double md = m;
  const double s = (md - 1.0) / (md + 1.0);
  const double s2 = s * s;
  constexpr double kAtanhSeries[] = {1.0 / 17, 1.0 / 15, 1.0 / 13, 1.0 / 11, 1.0 / 9,
                                     1.0 / 7,  1.0 / 5,  1.0 / 3,  1.0};
  const double series = detail::horner(s2, kAtanhSeries);
  constexpr double kLn2 = 0x1.62e42fefa39efp-1;
  const double ln_x = static_cast<double>(e) * kLn2 + 2.0 * s * series;
  // exp(t) = 2^k exp(r), k = round(t / ln 2), r = t - k ln 2 (ln 2 split in two so that k ln2_hi
  // is exact), |r| <= ln 2 / 2: a Taylor polynomial to r^11 / 11! (relative error below 1e-14).
  // t is clamped to where the float result has under- or overflowed (e^-120, e^120), which keeps
  // 2^k a normal double.
  double t = static_cast<double>(y) * ln_x;
  t = t < -120.0 ? -120.0 : t;
  t = t > 120.0 ? 120.0 : t;
  constexpr double kInvLn2 = 0x1.71547652b82fep0;
  constexpr double kLn2Hi = 0x1.62e42fee00000p-1;  // 32 significant bits: k ln2_hi is exact
  constexpr double kLn2Lo = 0x1.a39ef35793c76p-33;
  constexpr double kRound = 0x1.8p52;  // adding it rounds to an integer (to nearest, even)
  const double kr = t * kInvLn2 + kRound;
  const double k = kr - kRound;
  // kr's low 32 bits hold k in two's complement (kr's ulp is 1, its integer part 3 2^51 + k), and
  // k + 1023 is 2^k's biased exponent (unsigned arithmetic: a NaN's bits wrap harmlessly).
  const uint32_t biased = static_cast<uint32_t>(std::bit_cast<uint64_t>(kr)) + 1023u;
  const double r = (t - k * kLn2Hi) - k * kLn2Lo;
  constexpr double kExpTaylor[] = {1.0 / 39916800, 1.0 / 3628800, 1.0 / 362880, 1.0 / 40320,
                                   1.0 / 5040,     1.0 / 720,     1.0 / 120,    1.0 / 24,
                                   1.0 / 6,        1.0 / 2,       1.0,          1.0};  // 1/11! .. 1/0!
  const double p = detail::horner(r, kExpTaylor);
  const double scale = std::bit_cast<double>(static_cast<uint64_t>(biased) << 52);
  const float power = static_cast<float>(p * scale);
  // The edges, as powf has them.
  const float zero_or_inf = y > 0.0f ? 0.0f : __builtin_inff();
  const float inf_or_zero = y > 0.0f ? __builtin_inff() : 0.0f;
  float out = x == 0.0f ? zero_or_inf : x == __builtin_inff() ? inf_or_zero : power;
  out = x < 0.0f ? __builtin_nanf("") : out;
  out = x != x || y != y ? x + y : out;  // NaN
  out = y == 0.0f || x == 1.0f ? 1.0f : out;
  return out;
}

// x^y as the lighting equation needs it (the domain and edges of lightPowExpLog): by
// lightPowWhole where y is whole, by lightPowExpLog elsewhere. Both are computed and one chosen
// (no branch), so a loop of it vectorizes.
inline float lightPow(float x, float y) {
  const bool whole = lightPowIsWhole(y);
  const float by_whole = lightPowWhole(x, whole ? static_cast<int>(y) : 0);
  const float by_exp_log = lightPowExpLog(x, y);
  return whole ? by_whole : by_exp_log;
}

// out[i] = lightPowWhole(x[i], e) for i < n: the exponent uniform, so each bit of it is a
// product over the whole run or none -- the same products, in the same order, as wholePower's
// selects make lane by lane, so the same bits, at the cost of only the bits e has.
template <int kMax>
inline void wholePowers(const float* x, int e, int n, float* out) {
  alignas(64) double power[kMax], square[kMax];
  for (int i = 0; i < n; ++i) {
    power[i] = 1.0;
    square[i] = x[i];
  }
  for (int bit = 0; bit < 8 && (e >> bit) != 0; ++bit) {
    if ((e >> bit) & 1)
      for (int i = 0; i < n; ++i) power[i] = power[i] * square[i];
    if ((e >> (bit + 1)) != 0)
      for (int i = 0; i < n; ++i) square[i] = square[i] * square[i];
  }
  for (int i = 0; i < n; ++i) out[i] = wholePowerEdges(x[i], e, power[i]);
}

}  // namespace pf
