// The arithmetic of fixed-point values (compiler/fixed_point.h) against references computed
// here another way (exact double and int64 arithmetic for formats small enough, hand-derived
// values for 64-bit ones).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "compiler/fixed_point.h"

using namespace pf;

namespace {

// ---- an independent reference for formats of up to 24 bits: every intermediate is an integer
// below 2^53, so doubles and int64 hold it exactly ----

// n / d rounded to nearest, ties away from zero: sign * floor((2|n| + |d|) / 2|d|).
int64_t refRoundedDiv(int64_t n, int64_t d) {
  const int64_t an = n < 0 ? -n : n, ad = d < 0 ? -d : d;
  const int64_t q = (2 * an + ad) / (2 * ad);
  return (n < 0) != (d < 0) ? -q : q;
}

// Modulo 2^bits into [-2^(bits-1), 2^(bits-1)).
int64_t refWrap(int64_t v, int bits) {
  const int64_t m = int64_t{1} << bits;
  int64_t r = ((v % m) + m) % m;
  return r >= m / 2 ? r - m : r;
}

int64_t refMul(int64_t a, int64_t b, FixedFormat f) { return refWrap(refRoundedDiv(a * b, int64_t{1} << f.frac), f.bits); }
int64_t refDiv(int64_t a, int64_t b, FixedFormat f) {
  return b == 0 ? 0 : refWrap(refRoundedDiv(a * (int64_t{1} << f.frac), b), f.bits);
}

// float x as a raw value of format f: x 2^frac rounded half away from zero, saturated.
int64_t refFromFloat(double x, FixedFormat f) {
  if (std::isnan(x)) return 0;
  double s = x * std::ldexp(1.0, f.frac);
  s = s < 0 ? -std::floor(-s + 0.5) : std::floor(s + 0.5);
  const double top = std::ldexp(1.0, f.bits - 1);
  if (s >= top) return static_cast<int64_t>(top) - 1;
  if (s < -top) return -static_cast<int64_t>(top);
  return static_cast<int64_t>(s);
}

double value(int64_t raw, FixedFormat f) { return std::ldexp(static_cast<double>(raw), -f.frac); }

}  // namespace

TEST(FixedArithmetic, SmallFormatsMatchExactIntegerArithmetic) {
  std::mt19937_64 rng(12345);
  for (FixedFormat f : {FixedFormat{8, 4}, FixedFormat{12, 0}, FixedFormat{16, 8}, FixedFormat{20, 19}, FixedFormat{24, 10},
                        FixedFormat{5, 5}, FixedFormat{1, 0}}) {
    std::uniform_int_distribution<int64_t> raw(fixedMin(f.bits), fixedMax(f.bits));
    for (int i = 0; i < 4000; ++i) {
      const int64_t a = raw(rng), b = raw(rng);
      SCOPED_TRACE(::testing::Message() << "fixed<" << f.bits << "," << f.frac << "> a=" << a << " b=" << b);
      EXPECT_EQ(fixedWrap(static_cast<__int128>(a) + b, f.bits), refWrap(a + b, f.bits));
      EXPECT_EQ(fixedWrap(static_cast<__int128>(a) - b, f.bits), refWrap(a - b, f.bits));
      EXPECT_EQ(fixedMul(a, b, f), refMul(a, b, f));
      EXPECT_EQ(fixedDiv(a, b, f), refDiv(a, b, f));
      // A float of the value's neighbourhood converts back by the rounding rule.
      const double x = value(a, f) + (static_cast<double>(b) / static_cast<double>(fixedMax(f.bits) + 1)) * 1.5 *
                                         std::ldexp(1.0, -f.frac);
      const float xf = static_cast<float>(x);
      EXPECT_EQ(fixedFromFloat(xf, f), refFromFloat(xf, f));
      EXPECT_EQ(fixedToFloat(a, f.frac), static_cast<float>(value(a, f)));  // exact here: <= 24 bits
      EXPECT_EQ(fixedToInt(a, f.frac), static_cast<int32_t>(std::trunc(value(a, f))));
    }
  }
}

TEST(FixedArithmetic, RoundingTiesGoAwayFromZero) {
  const FixedFormat f{16, 8};
  // Products whose exact value lies half-way between two units.
  EXPECT_EQ(fixedMul(1, 128, f), 1);    // 0.5 units -> 1
  EXPECT_EQ(fixedMul(-1, 128, f), -1);  // -0.5 units -> -1
  EXPECT_EQ(fixedMul(3, 128, f), 2);    // 1.5 units -> 2
  EXPECT_EQ(fixedMul(1, 127, f), 0);    // 0.496 units -> 0
  EXPECT_EQ(fixedMul(384, 576, f), 864);  // 1.5 * 2.25 = 3.375
  // Quotients likewise: 1 unit / 2 = 0.5 units -> 1; 3 units / 2 -> 2 (not banker's 2, 1 -> 0 ...)
  EXPECT_EQ(fixedDiv(1, 512, f), 1);
  EXPECT_EQ(fixedDiv(-1, 512, f), -1);
  EXPECT_EQ(fixedDiv(256, 768, f), 85);  // 1/3 = 85.33 units
  EXPECT_EQ(fixedFromFloat(0.5f / 256, f), 1);
  EXPECT_EQ(fixedFromFloat(-0.5f / 256, f), -1);
  EXPECT_EQ(fixedFromFloat(2.5f, FixedFormat{8, 0}), 3);
  EXPECT_EQ(fixedFromFloat(-2.5f, FixedFormat{8, 0}), -3);
  // Conversions between formats: 1.75 -> 2 and 2.5 -> 3 without fraction bits.
  EXPECT_EQ(fixedConvert(448, 8, FixedFormat{8, 0}), 2);
  EXPECT_EQ(fixedConvert(640, 8, FixedFormat{8, 0}), 3);
  EXPECT_EQ(fixedConvert(-640, 8, FixedFormat{8, 0}), -3);
  EXPECT_EQ(fixedConvert(3, 0, FixedFormat{32, 16}), 3 << 16);
  // int() truncates toward zero.
  EXPECT_EQ(fixedToInt(-384, 8), -1);
  EXPECT_EQ(fixedToInt(384, 8), 1);
}

TEST(FixedArithmetic, ArithmeticWrapsConversionsSaturate) {
  const FixedFormat f{8, 4};  // [-8, 7.9375]
  EXPECT_EQ(fixedWrap(static_cast<__int128>(127) + 1, 8), -128);
  EXPECT_EQ(fixedMul(64, 64, f), 0);  // 4 * 4 = 16 = 256 units: 0 modulo 2^8
  EXPECT_EQ(fixedMul(48, 64, f), -64);  // 3 * 4 = 12 = 192 units: -64 modulo 2^8
  EXPECT_EQ(fixedFromFloat(100.0f, f), 127);
  EXPECT_EQ(fixedFromFloat(-100.0f, f), -128);
  EXPECT_EQ(fixedFromFloat(std::numeric_limits<float>::infinity(), f), 127);
  EXPECT_EQ(fixedFromFloat(std::numeric_limits<float>::quiet_NaN(), f), 0);
  EXPECT_EQ(fixedFromInt(9, f), 127);
  EXPECT_EQ(fixedFromInt(-9, f), -128);
  EXPECT_EQ(fixedConvert(1000 << 8, 8, f), 127);
  EXPECT_EQ(fixedDiv(16, 0, f), 0);  // division by zero gives 0
  // fixed<1,0> holds -1 and 0.
  EXPECT_EQ(fixedFromInt(1, FixedFormat{1, 0}), 0);
  EXPECT_EQ(fixedFromFloat(-1.0f, FixedFormat{1, 0}), -1);
  EXPECT_EQ(fixedToInt(int64_t{1} << 40, 0), INT32_MAX);
  EXPECT_EQ(fixedToInt(-(int64_t{1} << 40), 0), INT32_MIN);
}

TEST(FixedArithmetic, SixtyFourBitFormats) {
  const int64_t kMin = std::numeric_limits<int64_t>::min(), kMax = std::numeric_limits<int64_t>::max();
  const FixedFormat q32{64, 32}, q0{64, 0}, q64{64, 64};
  // 1.5 * 2.25 = 3.375 with 32 fraction bits: the product needs 128 bits before the shift.
  EXPECT_EQ(fixedMul(int64_t{3} << 31, int64_t{9} << 30, q32), int64_t{27} << 29);
  // (2^20 + 2^-32)^2 = 2^40 + 2^-11 + 2^-64: the integer part wraps modulo 2^32 to 0 and the
  // last term rounds away, leaving 2^-11 (raw 2^21).
  EXPECT_EQ(fixedMul((int64_t{1} << 52) + 1, (int64_t{1} << 52) + 1, q32), int64_t{1} << 21);
  EXPECT_EQ(fixedMul(int64_t{1} << 62, 4, q0), 0);                 // 2^64 wraps to 0
  EXPECT_EQ(fixedWrap(static_cast<__int128>(kMax) + 1, 64), kMin);  // max + 1 wraps to min
  EXPECT_EQ(fixedDiv(kMin, -1, q0), kMin);                          // -min wraps to min
  EXPECT_EQ(fixedDiv(kMin, -1, q32), 0);                            // -2^63 * 2^32 mod 2^64
  EXPECT_EQ(fixedDiv(1, 3, q32), 1431655765);                       // 2^32 / 3 = 1431655765.33
  EXPECT_EQ(fixedDiv(-2, 3, q32), -2863311531);                     // 2^33 / 3 = 2863311530.67
  // fixed<64,64>: values in [-0.5, 0.5), 2^-64 apart.
  EXPECT_EQ(fixedFromFloat(0.25f, q64), int64_t{1} << 62);
  EXPECT_EQ(fixedFromFloat(0.5f, q64), kMax);
  EXPECT_EQ(fixedFromFloat(-0.5f, q64), kMin);
  EXPECT_EQ(fixedMul(int64_t{1} << 62, int64_t{1} << 62, q64), int64_t{1} << 60);  // 1/4 * 1/4
  EXPECT_EQ(fixedToInt(kMax, 64), 0);
  // To float: one correct rounding of the raw value (2^40 + 1 -> 2^40; 2^24 + 1 -> 2^24 (tie to
  // even); 2^24 + 3 -> 2^24 + 4).
  EXPECT_EQ(fixedToFloat((int64_t{1} << 40) + 1, 0), std::ldexp(1.0f, 40));
  EXPECT_EQ(fixedToFloat((int64_t{1} << 24) + 1, 0), std::ldexp(1.0f, 24));
  EXPECT_EQ(fixedToFloat((int64_t{1} << 24) + 3, 0), std::ldexp(1.0f, 24) + 4.0f);
  EXPECT_EQ(fixedToFloat(1, 64), std::ldexp(1.0f, -64));
  EXPECT_EQ(fixedConvert(kMax, 0, FixedFormat{64, 1}), kMax);  // saturates
  EXPECT_EQ(fixedConvert(kMin, 0, FixedFormat{64, 64}), kMin);
  EXPECT_EQ(fixedConvert(kMax, 64, FixedFormat{64, 0}), 0);    // 0.49999... -> 0
  EXPECT_EQ(fixedConvert(int64_t{1} << 63 >> 1, 64, FixedFormat{8, 2}), -1);  // -0.25 -> -1 unit
}

