// lightPow (raster/light_pow.h), the lighting equation's power function, against the C
// library's pow in double precision rounded to float: over GL's domain (bases in [0, 1], the
// exponents glMaterial and glLight accept, [0, 128]) within one ulp everywhere and exactly
// the reference's float but for a handful of rounding ties; and C's results at the edges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "raster/light_pow.h"

using pf::lightPow;

namespace {

// The double-precision power rounded once to float: the correctly rounded result but for the
// rare case where the double itself sits within its own error of a float rounding tie.
float reference(float x, float y) { return static_cast<float>(std::pow(static_cast<double>(x), static_cast<double>(y))); }

// |a - b| in units of b's last place (b's spacing toward a), for finite values.
double ulps(float a, float b) {
  if (a == b) return 0;
  const float step = std::fabs(std::nextafter(b, a) - b);
  return std::fabs(static_cast<double>(a) - static_cast<double>(b)) / step;
}

}  // namespace

TEST(LightPow, MatchesDoublePrecisionPowOverTheLightingDomain) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<float> base(0.0f, 1.0f), exponent(0.0f, 128.0f);
  int inexact = 0;
  double worst = 0;
  constexpr int kSamples = 2000000;
  for (int i = 0; i < kSamples; ++i) {
    const float x = base(rng);
    // Shininess is often a whole number; spot exponents and interpolated materials are not.
    const float y = i % 3 == 0 ? std::round(exponent(rng)) : exponent(rng);
    const float got = lightPow(x, y), want = reference(x, y);
    ASSERT_TRUE(std::isfinite(got)) << x << "^" << y;
    const double e = ulps(got, want);
    worst = std::max(worst, e);
    inexact += e != 0 ? 1 : 0;
    ASSERT_LE(e, 1.0) << std::hexfloat << x << "^" << y << " = " << got << ", reference " << want;
  }
  EXPECT_LE(inexact, kSamples / 100000) << "worst " << worst << " ulp";
}

TEST(LightPow, MatchesNearOneAndForSmallAndSubnormalBases) {
  // Near 1 (a highlight's centre, n.h -> 1) the logarithm is the series alone; small and
  // subnormal bases take the exponent path and the 2^24 rescaling.
  const float bases[] = {1.0f - 0x1p-24f, 1.0f - 0x1p-20f, 0.999f, 0.7071067f, 0.7071068f, 0.5f, 1e-3f, 1e-20f,
                         0x1p-126f, 0x1.fffffcp-127f, 1e-40f, 1e-45f, std::numeric_limits<float>::denorm_min()};
  const float exponents[] = {0.01f, 0.5f, 1.0f, 2.0f, 3.0f, 10.0f, 33.3f, 64.0f, 127.5f, 128.0f};
  for (float x : bases)
    for (float y : exponents) EXPECT_LE(ulps(lightPow(x, y), reference(x, y)), 1.0) << std::hexfloat << x << "^" << y;
  // Bases above 1 (a normal interpolated slightly past unit length) and results that overflow.
  for (float x : {1.0000001f, 1.001f, 1.5f, 2.0f, 100.0f})
    for (float y : exponents) {
      const float want = reference(x, y);
      if (std::isinf(want))
        EXPECT_EQ(lightPow(x, y), want) << x << "^" << y;
      else
        EXPECT_LE(ulps(lightPow(x, y), want), 1.0) << x << "^" << y;
    }
}

TEST(LightPow, EdgesAsCPowHasThem) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float cases[][2] = {{0, 0},   {0, 1},   {0, 0.5f}, {0, -1},  {0, -0.5f}, {inf, 1},   {inf, -1}, {inf, 0},
                            {1, 0},   {1, 128}, {1, -7},   {1, nan}, {nan, 0},   {0.5f, 0},  {0.5f, -2}, {2, -3},
                            {0.25f, 0.5f}};
  for (const auto& c : cases) {
    const float want = std::pow(c[0], c[1]);
    EXPECT_EQ(lightPow(c[0], c[1]), want) << c[0] << "^" << c[1];
  }
  EXPECT_TRUE(std::isnan(lightPow(nan, 1.0f)));
  EXPECT_TRUE(std::isnan(lightPow(0.5f, nan)));
  EXPECT_TRUE(std::isnan(lightPow(-0.5f, 2.0f))) << "a negative base is outside the domain";
}

TEST(LightPow, WholeExponentsByBinaryPoweringMatchDoublePrecisionPow) {
  // Every whole exponent GL allows, over random bases and the edges of the domain: within one
  // ulp of the double-precision power (exactly it but for rounding ties) and C's edges.
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> base(0.0f, 1.0f);
  int inexact = 0, total = 0;
  for (int e = 0; e <= pf::kLightPowMaxWhole; ++e) {
    ASSERT_TRUE(pf::lightPowIsWhole(static_cast<float>(e)));
    for (int i = 0; i < 4000; ++i) {
      const float x = i < 3000 ? base(rng) : 1.0f - base(rng) * 0x1p-12f;  // and near 1
      const float got = lightPow(x, static_cast<float>(e)), want = reference(x, static_cast<float>(e));
      ASSERT_EQ(got, pf::lightPowWhole(x, e));
      const double err = ulps(got, want);
      ASSERT_LE(err, 1.0) << std::hexfloat << x << "^" << e << " = " << got << ", reference " << want;
      inexact += err != 0 ? 1 : 0;
      ++total;
    }
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (float x : {0.0f, 1.0f, 1e-30f, 1e-45f, 1.5f, 3.0f, inf}) {
      const float want = std::pow(x, static_cast<float>(e));
      if (std::isinf(want) || want == 0.0f || e == 0 || x == 1.0f)
        EXPECT_EQ(lightPow(x, static_cast<float>(e)), want) << x << "^" << e;
      else
        EXPECT_LE(ulps(lightPow(x, static_cast<float>(e)), reference(x, static_cast<float>(e))), 1.0) << x << "^" << e;
    }
    EXPECT_EQ(lightPow(nan, static_cast<float>(e)) == 1.0f, e == 0);
    EXPECT_EQ(std::isnan(lightPow(-0.5f, static_cast<float>(e))), e != 0);
  }
  EXPECT_LE(inexact, total / 100000);
  // Not whole: a fraction, NaN, outside [0, 128].
  for (float y : {0.5f, 31.999998f, 128.5f, -1.0f, 129.0f, std::numeric_limits<float>::quiet_NaN()})
    EXPECT_FALSE(pf::lightPowIsWhole(y)) << y;
}

TEST(LightPow, WholePowersOverARunAreLightPowLaneByLane) {
  // The shading pass's uniform-exponent loop against lightPow point by point, to the bit.
  constexpr int kRun = 64;
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> base(0.0f, 1.0f);
  float x[kRun], out[kRun];
  for (int e = 0; e <= pf::kLightPowMaxWhole; ++e) {
    for (int i = 0; i < kRun; ++i) x[i] = base(rng);
    x[0] = 0.0f;
    x[1] = 1.0f;
    x[2] = std::numeric_limits<float>::quiet_NaN();
    x[3] = 2.5f;  // overflows for large e
    x[4] = 1e-40f;
    for (int n : {kRun, 17, 1}) {
      pf::wholePowers<kRun>(x, e, n, out);
      for (int i = 0; i < n; ++i) {
        const float want = lightPow(x[i], static_cast<float>(e));
        ASSERT_TRUE(std::memcmp(&out[i], &want, sizeof want) == 0 || (std::isnan(out[i]) && std::isnan(want)))
            << std::hexfloat << x[i] << "^" << e << ": " << out[i] << " vs " << want;
      }
    }
  }
}
