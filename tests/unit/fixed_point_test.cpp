// fixed<bits,frac> (docs/language.md, "Fixed-point numbers"): the arithmetic of
// compiler/fixed_point.h against references computed here another way (exact double and
// int64 arithmetic for formats small enough, hand-derived values for 64-bit ones), then the
// language: conversions, operators, built-ins, control flow, arrays, functions, setup-to-pixel
// values, constant folding, in both execution modes (runBlock compares the SIMD executor with
// the reference interpreter lane by lane), and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "compile_helpers.h"
#include "compiler/fixed_point.h"
#include "raster/setup_batch.h"

using namespace pf;
using namespace pf::test;

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

// ---- the language ----

namespace {

float laneX(int i) { return static_cast<float>(i % 8) + 0.5f; }
float laneY(int i) { return static_cast<float>(i / 8) + 0.5f; }

// Runs `body` (which sets `float z`) in primitive p on one block, optimized or not.
std::vector<float> runBody(const std::string& body, const std::string& params = "",
                           const std::vector<float>& values = {}, bool optimize = true,
                           const std::string& functions = "") {
  Compiled c = compile(functions + "primitive p(" + params + "varying float X, Y; inout varying float Z) {\n" + body +
                           "\n  Z = z;\n}\n",
                       "test.pfl", optimize);
  EXPECT_TRUE(c.ok) << c.diagnostics;
  if (!c.ok) return {};
  return runBlock(*c.find("p"), values, {}, 0, true, 1e30f).depth;
}

void expectLanes(const std::vector<float>& got, const std::function<double(double x, double y)>& want) {
  ASSERT_EQ(got.size(), 64u);
  for (int i = 0; i < 64; ++i)
    EXPECT_EQ(got[i], static_cast<float>(want(laneX(i), laneY(i)))) << "lane " << i << " x " << laneX(i) << " y " << laneY(i);
}

// Value of format f of a double that the format holds exactly after rounding by the rule.
double rounded(double x, FixedFormat f) { return value(refFromFloat(x, f), f); }

}  // namespace

TEST(FixedLanguage, ArithmeticPerPixel) {
  const FixedFormat f{16, 8};
  // x * y - x / 3 + 1 in fixed<16,8>, y = Y * 0.3 (rounded into the format), per lane.
  const std::string body =
      "  fixed<16,8> x = X;\n"
      "  fixed<16,8> y = Y * 0.3;\n"
      "  fixed<16,8> q = x * y - x / 3 + 1;\n"
      "  float z = float(q);";
  auto want = [&](double x, double y) {
    const int64_t rx = refFromFloat(x, f), ry = refFromFloat(static_cast<float>(static_cast<float>(y) * 0.3f), f);
    const int64_t r = refWrap(refWrap(refMul(rx, ry, f) - refDiv(rx, 3 << 8, f), 16) + 256, 16);
    return value(r, f);
  };
  expectLanes(runBody(body), want);
  expectLanes(runBody(body, "", {}, false), want);  // unoptimized: the same
}

TEST(FixedLanguage, WrapOnArithmeticSaturateOnConversion) {
  // fixed<8,4> holds [-8, 7.9375]: X + Y wraps past it; a conversion of 3 X saturates.
  expectLanes(runBody("  fixed<8,4> s = fixed<8,4>(X) + fixed<8,4>(Y);\n"
                      "  fixed<8,4> t = X * 3.0;\n"
                      "  float z = float(s) * 100.0 + float(t);"),
              [](double x, double y) {
                const double s = value(refWrap((int64_t)(x * 16) + (int64_t)(y * 16), 8), FixedFormat{8, 4});
                return s * 100.0 + std::min(x * 3.0, 7.9375);
              });
}

TEST(FixedLanguage, ComparisonsAndBuiltIns) {
  // Exact comparisons, abs, min, max, clamp, negation; ints convert; floats make it a float.
  expectLanes(runBody("  fixed<24,12> a = X - 4.0;\n"
                      "  fixed<24,12> b = (Y - 4.0) * 0.5;\n"
                      "  float z = 0.0;\n"
                      "  if (a < b) z += 1.0;\n"
                      "  if (a >= b) z += 2.0;\n"
                      "  if (a == b) z += 4.0;\n"
                      "  if (a != 1) z += 8.0;\n"
                      "  if (a > 0.25) z += 16.0;\n"  // against a float: as floats
                      "  z += 100.0 * float(abs(a)) + 1000.0 * float(min(a, b)) + 10000.0 * float(max(a, -b));\n"
                      "  z += 100000.0 * float(clamp(a, -1, 2));\n"
                      "  z += 0.5 * float(-a);"),
              [](double x, double y) {
                const double a = x - 4.0, b = (y - 4.0) * 0.5;
                double z = 0;
                if (a < b) z += 1;
                if (a >= b) z += 2;
                if (a == b) z += 4;
                if (a != 1) z += 8;
                if (a > 0.25) z += 16;
                z += 100.0 * std::abs(a) + 1000.0 * std::min(a, b) + 10000.0 * std::max(a, -b);
                z += 100000.0 * std::clamp(a, -1.0, 2.0);
                return static_cast<float>(z + 0.5 * -a);
              });
}

TEST(FixedLanguage, MixingWithIntsStaysExactWithFloatsBecomesFloat) {
  // q * 3 + 1 stays fixed (exact); q += 0.3 is computed as a float and rounds back into q.
  expectLanes(runBody("  fixed<16,8> q = X;\n"
                      "  fixed<16,8> r = q * 3 + 1;\n"
                      "  q += 0.3;\n"
                      "  float z = float(r) + 100.0 * float(q);"),
              [](double x, double) {
                const double q = rounded(static_cast<float>(static_cast<float>(x) + 0.3f), FixedFormat{16, 8});
                return x * 3 + 1 + 100.0 * q;  // exact in float: multiples of 1/256 below 2^15
              });
  // q * 0.1 is a float product (of q's float, here X itself).
  expectLanes(runBody("  fixed<16,8> q = X;\n  float z = q * 0.1;"),
              [](double x, double) { return static_cast<float>(x) * 0.1f; });
}

TEST(FixedLanguage, SixtyFourBitValuesCarryAcrossWords) {
  // 2^40 + X - 2^40: X again, exactly (a float would round at 2^40 to multiples of 2^17); and
  // (2^20 + X)(2^20 - X) - 2^40 = -X^2, whose product needs the 64-bit multiply.
  const std::string big = "  fixed<64,16> big = fixed<64,16>(1073741824) * 1024;\n";  // 2^40
  expectLanes(runBody(big + "  fixed<64,16> x = X;\n  float z = float((big + x) - big) + 100.0 * float((x - big) + big);"),
              [](double x, double) { return 101.0 * x; });
  expectLanes(runBody(big + "  fixed<64,16> m = fixed<64,16>(1048576);\n"
                            "  fixed<64,16> x = X - 4.0;\n"
                            "  float z = float((m + x) * (m - x) - big);"),
              [](double x, double) { return -(x - 4.0) * (x - 4.0); });
  // The float path on the same numbers loses X entirely: the test above can fail.
  expectLanes(runBody("  float big = 1073741824.0 * 1024.0;\n  float z = (big + X) - big;"),
              [](double, double) { return 0.0; });
}

TEST(FixedLanguage, ControlFlowArraysFunctionsAndUniformValues) {
  const std::string functions =
      "fixed<32,16> half_of(fixed<32,16> v) { return v / 2; }\n"
      "fixed<32,16> pick(fixed<32,16> a[3], int i) { return a[i]; }\n";
  // A varying if, a loop carrying a fixed value, an array at a run-time index, a function
  // taking and returning fixed, a uniform fixed value from setup (parameter k), ?: with an int.
  expectLanes(runBody("  uniform fixed<32,16> u = fixed<32,16>(k) * 3;\n"
                      "  fixed<32,16> acc = 0;\n"
                      "  for (int i = 0; i < int(Y); i += 1) acc += fixed<32,16>(X);\n"
                      "  if (X > 4.0) acc = half_of(acc); else acc = -acc;\n"
                      "  fixed<32,16> a[3];\n"
                      "  a[0] = 1; a[1] = u; a[2] = acc;\n"
                      "  fixed<32,16> e = pick(a, int(X) % 3);\n"
                      "  fixed<32,16> t = X > 2.0 ? e : 7;\n"
                      "  float z = float(acc) + 1000.0 * float(t);",
                      "float k; ", {0.75f}, true, functions),
              [](double x, double y) {
                double acc = x * std::floor(y);
                acc = x > 4.0 ? acc / 2 : -acc;  // exact: halves of multiples of 0.5
                const double a[3] = {1.0, 2.25, acc};
                const double e = a[static_cast<int>(x) % 3];
                const double t = x > 2.0 ? e : 7.0;
                return acc + 1000.0 * t;
              });
}

TEST(FixedLanguage, ConstantsFoldToTheExecutorsValues) {
  // Everything here is constant: the optimizer folds it with the same arithmetic the executors
  // run, and the unoptimized program computes it at run time.
  const std::string body =
      "  fixed<64,40> third = fixed<64,40>(1) / 3;\n"
      "  fixed<32,6> c = fixed<32,6>(third * 3000000);\n"
      "  float z = float(c) - 1000000.0 + float(int(third * 7)) * 0.25;";
  const std::vector<float> opt = runBody(body), raw = runBody(body, "", {}, false);
  ASSERT_EQ(opt.size(), 64u);
  ASSERT_EQ(raw.size(), 64u);
  // round(2^40/3) = 366503875925 (2^40 = 1099511627776 = 3 * 366503875925 + 1); times 3e6 it
  // is 1099511627775000000 / 2^40 = 999999.99999909, 1000000 at 6 fraction bits; times 7 it is
  // 2.333..., int 2.
  for (int i = 0; i < 64; ++i) {
    EXPECT_EQ(opt[i], 0.5f) << i;
    EXPECT_EQ(raw[i], 0.5f) << i;
  }
  // Folded away: no fixed-point instruction is left in either program.
  Compiled c = compile("primitive p(inout varying float Z) {\n" + body + "\n  Z = z;\n}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  for (const std::vector<Instr>* code : {&p.setup.code, &p.pixel.code})
    for (const Instr& in : *code) EXPECT_FALSE(in.op >= Op::QAdd && in.op <= Op::QConv) << opName(in.op);
}

TEST(FixedLanguage, Errors) {
  struct Case {
    const char* body;
    const char* message;
  };
  const Case cases[] = {
      {"fixed<0,0> a;", "the bits of fixed<bits,frac> must be between 1 and 64, not 0"},
      {"fixed<65,0> a;", "the bits of fixed<bits,frac> must be between 1 and 64, not 65"},
      {"fixed<16,17> a;", "the fraction bits of fixed<bits,frac> must be between 0 and 16, not 17"},
      {"fixed<16> a;", "expected ',' between the bits and the fraction bits"},
      {"fixed a;", "expected '<' after 'fixed'"},
      {"fixed<16,8> a = 1; fixed<32,8> b = 2; fixed<16,8> c = a + b;",
       "operator '+' cannot combine fixed<16,8> and fixed<32,8>: values of two fixed-point formats meet only after a conversion"},
      {"fixed<16,8> a = 1; fixed<32,8> b = 2; fixed<16,8> c = min(a, b);", "min() cannot mix fixed<16,8> and fixed<32,8>"},
      {"fixed<16,8> a = 1; fixed<16,8> c = a % 2;", "operator '%' cannot combine fixed<16,8> and int"},
      {"fixed<16,8> a = 1; int i = a;", "cannot initialise 'i': expected int, found fixed<16,8>"},
      {"fixed<16,8> a = 1; float f = a.x;", "'.x' needs a point, vector, normal or color, not fixed<16,8>"},
      {"fixed<16,8> a = 1; float f = a[0];", "cannot index a value of type fixed<16,8>"},
      {"fixed<16,8> a = fixed<16,8>(1, 2);", "fixed<16,8>() converts one number, not 2"},
      {"fixed<16,8> a = fixed<16,8>(point(1, 2, 3));", "fixed<16,8>() converts an int, a float or another fixed-point value, not point"},
  };
  for (const Case& k : cases) {
    Compiled c = compile(std::string("primitive p(inout varying float Z) {\n  ") + k.body + "\n}\n");
    EXPECT_FALSE(c.ok) << k.body;
    EXPECT_NE(c.diagnostics.find(k.message), std::string::npos) << k.body << "\n" << c.diagnostics;
    EXPECT_NE(c.diagnostics.find("test.pfl:2:"), std::string::npos) << c.diagnostics;  // file:line:col
  }
  Compiled param = compile("primitive p(fixed<16,8> a; inout varying float Z) { Z = 0.0; }\n");
  EXPECT_FALSE(param.ok);
  EXPECT_NE(param.diagnostics.find("parameter 'a' cannot be fixed<16,8>: parameters arrive from the API as floats"),
            std::string::npos)
      << param.diagnostics;
}

TEST(FixedLanguage, BatchedSetupMatchesScalarSetupBitForBit) {
  // Fixed-point setup arithmetic on per-instance parameters: the 16-lane batched setup
  // (raster/setup_batch.cpp) and the scalar setup leave the same records.
  Compiled c = compile(
      "primitive q(float a; float b; varying float X, Y; inout varying float Z) {\n"
      "  fixed<48,20> s = fixed<48,20>(a) * fixed<48,20>(b) / 7 - a;\n"
      "  if (s < 0) s = -s;\n"
      "  uniform fixed<48,20> t = max(s, fixed<48,20>(b));\n"
      "  bound(0, 0, 8, 8);\n"
      "  Z = float(fixed<48,20>(X) * t + s);\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& prim = *c.find("q");
  ASSERT_TRUE(BatchSetupExecutor::batchable(prim));
  RasterState state;
  state.vp_scale_x = state.vp_offset_x = state.vp_scale_y = state.vp_offset_y = 4;
  state.vp_x1 = state.vp_y1 = 8;
  const ChannelLayout layout;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(-3000.0f, 3000.0f);
  const size_t words = SetupExecutor::recordWords(prim, 0);
  std::vector<std::vector<uint32_t>> params(kSetupBatchLanes), want(kSetupBatchLanes, std::vector<uint32_t>(words, 0u)),
      got = want;
  SetupInput in[kSetupBatchLanes];
  uint32_t* records[kSetupBatchLanes];
  SetupOutput out[kSetupBatchLanes];
  SetupExecutor scalar;
  for (int l = 0; l < kSetupBatchLanes; ++l) {
    params[l] = {f2u(value(rng)), f2u(value(rng))};
    in[l] = SetupInput{params[l].data(), nullptr, &layout, &state, 1, nullptr, 0};
    records[l] = got[l].data();
    scalar.run(prim, in[l], want[l].data());
  }
  BatchSetupExecutor batch;
  batch.run(prim, in, kSetupBatchLanes, records, out);
  for (int l = 0; l < kSetupBatchLanes; ++l) EXPECT_EQ(want[l], got[l]) << "instance " << l;
  // The instances part at `if (s < 0)`: those on the minority side finish scalar, the rest in
  // the batch; all ran the fixed-point arithmetic before it in the batch's lanes.
  EXPECT_GE(batch.counters.lanes_batched, static_cast<uint64_t>(kMinBatchLanes));
}

// ---- the pixel built-ins declared in fixed point (the paper's figures 6 and 7) ----

// Figure 7 declares `varying fixed<32,16> X, Y; inout varying fixed<32,32> Z`. The shipped
// screen_triangle in that form: pixel centres (k + 1/2) are exact in fixed<32,16>, so every
// lane's coverage, depth and channels equal the float form's, bit for bit.
TEST(FixedLanguage, PaperFigure7DeclaresThePixelBuiltinsFixed) {
  FILE* fp = std::fopen((std::string(PF_SOURCE_DIR) + "/primitives/screen_triangle.pfl").c_str(), "rb");
  ASSERT_NE(fp, nullptr);
  std::string text;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, fp)) > 0;) text.append(buf, n);
  std::fclose(fp);
  const std::string floats = "varying float X, Y; inout varying float Z)";
  const size_t at = text.find(floats);
  ASSERT_NE(at, std::string::npos);
  std::string fixed = text;
  fixed.replace(at, floats.size(), "varying fixed<32,16> X, Y; inout varying fixed<32,32> Z)");
  Compiled a = compile(text, "float.pfl"), b = compile(fixed, "fixed.pfl");
  ASSERT_TRUE(a.ok) << a.diagnostics;
  ASSERT_TRUE(b.ok) << b.diagnostics;
  const std::vector<float> verts = {0.5f, 0.25f, 0.1f, 1.0f, 7.75f, 1.5f, 0.6f, 2.0f, 2.25f, 7.5f, 0.9f, 4.0f};
  const std::vector<float> ch = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};
  for (InterpKind kind : {InterpKind::PerspectiveLinear, InterpKind::Linear}) {
    BlockRun fa = runBlock(*a.find("screen_triangle"), verts, ch, 4, true, 1.0f, kind);
    BlockRun fb = runBlock(*b.find("screen_triangle"), verts, ch, 4, true, 1.0f, kind);
    int covered = 0;
    for (int i = 0; i < 64; ++i) {
      EXPECT_EQ(fa.depth[i], fb.depth[i]) << i;
      covered += fa.depth[i] < 1.0f;
      for (int k = 0; k < 4; ++k) EXPECT_EQ(fa.channel(k, i % 8, i / 8), fb.channel(k, i % 8, i / 8)) << i;
    }
    EXPECT_GT(covered, 10);
  }
}

// Reading a fixed-declared built-in converts it into its format as any conversion does: rounded
// to nearest and saturated. X in fixed<8,2> (range [-32, 31.75]) rounds X * 1 exactly but
// saturates X * 16; Z in the paper's fixed<32,32> holds [-1/2, 1/2), so a depth of 0.75 reads
// as its largest value. Writes to Z convert the fixed value back into the float depth.
TEST(FixedLanguage, FixedPixelBuiltinsRoundAndSaturateOnRead) {
  Compiled c = compile(
      "primitive p(varying fixed<8,2> X, Y; inout varying fixed<32,32> Z) {\n"
      "  fixed<8,2> big = X * 16.0;\n"  // a float product, converted into the format: saturates
      "  float z = float(X) / 64.0 + float(big) / 4096.0;\n"
      "  if (Y > 4) z = float(Z);\n"
      "  if (!ztest(0.0)) return;\n"
      "  Z = fixed<32,32>(z);\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const std::vector<float> depth = runBlock(*c.find("p"), {}, {}, 0, true, 0.75f).depth;
  ASSERT_EQ(depth.size(), 64u);
  const double zmax = 0.5 - std::ldexp(1.0, -32);
  for (int i = 0; i < 64; ++i) {
    const double x = laneX(i), y = laneY(i);
    const double big = std::min(x * 16.0, 31.75);
    const double want = y > 4 ? zmax : std::min(x / 64.0 + big / 4096.0, zmax);
    EXPECT_EQ(depth[i], static_cast<float>(want)) << "lane " << i;
  }
  // The float built-ins stay what functions see; a non-fixed, non-float declaration is an error.
  Compiled bad = compile("primitive p(varying int X; inout varying float Z) { Z = 0.5; }\n");
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.diagnostics.find("the built-in 'X' has type float or fixed<bits,frac>"), std::string::npos) << bad.diagnostics;
}
