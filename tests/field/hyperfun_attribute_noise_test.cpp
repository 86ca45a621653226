// HyperFun's Perlin noise (hfA_NoiseP, hfA_Turbulence): the tables its init() builds, and each
// attribute tape -- evaluated in double and by the float form the renderer runs -- against
// perlin.h's noise3 written out here in double, as HyperFun's C code computes it, at random
// points (negative ones, whole-number cell corners and points past -4096 included); misuse at
// file:line:col.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "compiler/field/perlin_tables.h"
#include "field/hyperfun_attribute_helpers.h"
#include "field/perlin_reference.h"
#include "raster/field/interval_evaluator.h"

namespace pf::field {
namespace {

using namespace attribute_testing;
using testing::noise3;
using testing::turbulence;

TEST(HyperFunNoise, TablesAreHyperFunsInitDrawnByMinstdRand) {
  const PerlinTables& t = perlinTables();
  // p: a permutation of 0..255, then its first 258 entries again.
  std::set<int> seen(t.perm, t.perm + 256);
  EXPECT_EQ(seen.size(), 256u);
  EXPECT_EQ(*seen.begin(), 0);
  EXPECT_EQ(*seen.rbegin(), 255);
  for (int k = 0; k < 258; ++k) {
    EXPECT_EQ(t.perm[256 + k], t.perm[k]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(t.grad[256 + k][c], t.grad[k][c]);
  }
  // g3: unit vectors, each component (m - 256) / 256 before normalising, m < 512.
  for (int k = 0; k < kPerlinTableSize; ++k) {
    const double* g = t.grad[k];
    EXPECT_NEAR(g[0] * g[0] + g[1] * g[1] + g[2] * g[2], 1.0, 1e-12) << k;
    EXPECT_EQ(t.values[0][k], static_cast<float>(t.perm[k]));
    for (int c = 0; c < 3; ++c) EXPECT_EQ(t.values[1 + c][k], static_cast<float>(g[c]));
  }
  // The texture is fixed: std::minstd_rand's draws at its default seed (a change of generator or
  // of the order of draws changes these).
  const int first_perm[8] = {115, 152, 136, 197, 22, 211, 135, 228};
  for (int k = 0; k < 8; ++k) EXPECT_EQ(t.perm[k], first_perm[k]) << k;
  EXPECT_DOUBLE_EQ(t.grad[0][0], 0.95659841474172613);
  EXPECT_DOUBLE_EQ(t.grad[0][1], -0.11479180976900714);
  EXPECT_DOUBLE_EQ(t.grad[0][2], 0.26784755612768335);
}

TEST(HyperFunNoise, TableLookUpsFloorAndClampTheirIndex) {
  const PerlinTables& t = perlinTables();
  EXPECT_EQ(perlinTableValue(FieldOp::NoisePerm, 7.9f), static_cast<float>(t.perm[7]));
  EXPECT_EQ(perlinTableValue(FieldOp::NoiseGradZ, 300.0f), static_cast<float>(t.grad[300][2]));
  EXPECT_EQ(perlinTableValue(FieldOp::NoisePerm, -3.0f), static_cast<float>(t.perm[0]));
  EXPECT_EQ(perlinTableValue(FieldOp::NoisePerm, 1e9f), static_cast<float>(t.perm[kPerlinTableSize - 1]));
  EXPECT_TRUE(std::isnan(perlinTableValue(FieldOp::NoiseGradX, std::nanf(""))));
  // The range over a few indices is their least and greatest entry; over many, the table's.
  const PerlinRange few = perlinTableRange(FieldOp::NoisePerm, 2.5f, 4.0f);
  EXPECT_EQ(few.lo, static_cast<float>(std::min({t.perm[2], t.perm[3], t.perm[4]})));
  EXPECT_EQ(few.hi, static_cast<float>(std::max({t.perm[2], t.perm[3], t.perm[4]})));
  const PerlinRange many = perlinTableRange(FieldOp::NoisePerm, 0.0f, 400.0f);
  EXPECT_EQ(many.lo, 0.0f);
  EXPECT_EQ(many.hi, 255.0f);
  EXPECT_TRUE(perlinTableRange(FieldOp::NoisePerm, std::nanf(""), 1.0f).nan);
}

TEST(HyperFunNoise, NoisePIsPerlinsNoise3OfThePoint) {
  expectAttributes(model("s[1] = hfA_NoiseP(x);\ns[2] = 0.5 + 0.5 * hfA_NoiseP(x);\ns[3] = 0;"),
                   [](double x, double y, double z) {
                     const double p[3] = {x, y, z};
                     const double n = noise3(p);
                     return std::vector<double>{n, 0.5 + 0.5 * n, 0.0};
                   });
}

// Scaled and shifted points: many cells, whole-number corners (the scale puts some samples on
// them), and coordinates below -4096, where HyperFun's (int) truncates towards zero.
TEST(HyperFunNoise, NoisePAtCellCornersAndFarFromTheOrigin) {
  const std::string body =
      "array y[3], w[3];\ny[1] = 4*x[1];\ny[2] = 4*x[2] - 0.5;\ny[3] = 2*x[3];\n"
      "w[1] = 1000*x[1] - 5000;\nw[2] = x[2] - 4100;\nw[3] = -3*x[3] - 7000;\n"
      "s[1] = hfA_NoiseP(y);\ns[2] = hfA_NoiseP(w);\ns[3] = 1;";
  const Compiled c = compileOk(model(body));
  ASSERT_EQ(c.attributes.size(), 3u);
  FloatEvaluator near_origin(c.attributes[0]), far(c.attributes[1]);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  for (int k = 0; k < 600; ++k) {
    double x = u(rng), y = u(rng), z = u(rng);
    if (k % 3 == 0) x = std::round(x * 4) / 4, z = std::round(z * 2) / 2;  // on cell faces
    const double p[3] = {4 * x, 4 * y - 0.5, 2 * z};
    const double q[3] = {1000 * x - 5000, y - 4100, -3 * z - 7000};
    EXPECT_NEAR(testing::evaluateDouble(c.attributes[0], x, y, z), noise3(p), 2e-6) << x << ", " << y << ", " << z;
    EXPECT_NEAR(testing::evaluateDouble(c.attributes[1], x, y, z), noise3(q), 2e-6) << x << ", " << y << ", " << z;
    const float fx = static_cast<float>(x), fy = static_cast<float>(y), fz = static_cast<float>(z);
    // The float form at the float point: its own rounding (4x the point and, far out, a float
    // grid of 2^-10 or 2^-11 at |w| of 4096 to 8192: noise3's slope is below 4).
    EXPECT_NEAR(near_origin.evaluate(fx, fy, fz), noise3(p), 1e-4) << x << ", " << y << ", " << z;
    const double fq[3] = {1000.0f * fx - 5000.0f, fy - 4100.0f, -3.0f * fz - 7000.0f};
    EXPECT_NEAR(far.evaluate(fx, fy, fz), noise3(fq), 1e-4) << x << ", " << y << ", " << z;
  }
}

// The bounds the tape clamps noise3 to (hyperfun_attribute_noise.cpp) hold for HyperFun's own
// noise3: within [-1.75, 1.75] where every coordinate is >= -4096, within [-2600, 2600] below,
// where its truncation extrapolates (and the values are far outside the first bound).
TEST(HyperFunNoise, Noise3StaysWithinTheBoundsTheTapeClampsItTo) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> near(-4096.0, 300.0), far(-9000.0, -4096.5), any(-9000.0, 300.0);
  double near_max = 0, far_max = 0;
  for (int k = 0; k < 200000; ++k) {
    const double p[3] = {near(rng), near(rng), near(rng)};
    near_max = std::max(near_max, std::fabs(noise3(p)));
    const double q[3] = {far(rng), k % 2 ? far(rng) : any(rng), k % 3 ? far(rng) : any(rng)};
    far_max = std::max(far_max, std::fabs(noise3(q)));
  }
  EXPECT_LT(near_max, 1.75);
  EXPECT_GT(far_max, 1.75);  // (so the second bound is needed)
  EXPECT_LT(far_max, 2600.0);
}

TEST(HyperFunNoise, TurbulenceSumsTheOctavesDownToFrequencyOne) {
  for (double freq : {1.0, 6.0, 8.0, 0.5}) {
    SCOPED_TRACE(freq);
    expectAttributes(model("s[1] = hfA_Turbulence(x, " + std::to_string(freq) + ");\ns[2] = 0;\ns[3] = 0;"),
                     [&](double x, double y, double z) {
                       const double p[3] = {x, y, z};
                       return std::vector<double>{turbulence(p, freq), 0.0, 0.0};
                     });
  }
}

TEST(HyperFunNoise, AKnownPointFoldsInDoubleAsHyperFunComputes) {
  const Compiled c = compileOk(model("array k[3];\nk = [0.3, -1.7, 2.2];\ns[1] = hfA_NoiseP(k);\n"
                                     "s[2] = hfA_Turbulence(k, 4);\ns[3] = 0;"));
  ASSERT_EQ(c.attributes.size(), 3u);
  const double k[3] = {0.3, -1.7, 2.2};
  ASSERT_EQ(c.attributes[0].size(), 1u);  // one constant each
  ASSERT_EQ(c.attributes[1].size(), 1u);
  EXPECT_EQ(c.attributes[0].instrs[0].value, static_cast<float>(noise3(k)));
  EXPECT_EQ(c.attributes[1].instrs[0].value, static_cast<float>(turbulence(k, 4)));
}

TEST(HyperFunNoise, NoiseInTheShapeIsAnOrdinaryTape) {
  // A bumpy ball: every evaluator reads the tables (the interval form soundly, step by step).
  const Compiled c = compileOk("my_model(x[3], a[1]) {\n my_model = 4 - x[1]*x[1] - x[2]*x[2] - x[3]*x[3] + "
                               "hfA_NoiseP(x);\n}\n");
  FloatEvaluator f(c.shape);
  IntervalEvaluator ie(c.shape);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-2.5f, 2.5f);
  for (int k = 0; k < 50; ++k) {
    const float x0 = u(rng), y0 = u(rng), z0 = u(rng);
    const Interval box = ie.evaluate({x0, x0 + 0.3f}, {y0, y0 + 0.2f}, {z0, z0 + 0.1f});
    for (int s = 0; s < 27; ++s) {
      const float x = x0 + 0.15f * (s % 3), y = y0 + 0.1f * (s / 3 % 3), z = z0 + 0.05f * (s / 9);
      const double p[3] = {x, y, z};
      const float v = f.evaluate(x, y, z);
      EXPECT_NEAR(v, 4.0 - p[0] * p[0] - p[1] * p[1] - p[2] * p[2] + noise3(p), 1e-4);
      EXPECT_TRUE(v >= box.lo && v <= box.hi) << v << " outside [" << box.lo << ", " << box.hi << "]";
    }
  }
}

TEST(HyperFunNoise, ItsIntervalOverManyCellsIsTheClampsBound) {
  const Compiled c = compileOk(model("s[1] = hfA_NoiseP(x);\ns[2] = 0;\ns[3] = 0;"));
  IntervalEvaluator ie(c.attributes[0]);
  const Interval wide = ie.evaluate({-2.0f, 2.0f}, {-2.0f, 2.0f}, {-2.0f, 2.0f});
  EXPECT_GE(wide.lo, -1.75f);
  EXPECT_LE(wide.hi, 1.75f);
  const Interval far = ie.evaluate({-5000.0f, -4000.0f}, {0.0f, 1.0f}, {0.0f, 1.0f});
  EXPECT_GE(far.lo, -2600.0f);
  EXPECT_LE(far.hi, 2600.0f);
  EXPECT_LT(far.lo, -1.75f);  // (a box reaching below -4096 takes the wider bound)
}

TEST(HyperFunNoise, MisuseIsReportedAtTheArgument) {
  expectHas(compileError(model("d = hfA_Turbulence(x, x[1]);")),
            "m.hf:2:23: error: 'freq' (argument 2 of 'hfA_Turbulence') depends on the point x; it must be known");
  expectHas(compileError(model("d = hfA_Turbulence(x, exp(1000));")),
            "error: 'freq' (argument 2 of 'hfA_Turbulence') is infinite");
  expectHas(compileError("my_model(x[3], a[1], s[3]) {\n array p[2];\n p = [1, 2];\n d = hfA_NoiseP(p);\n my_model = 1;\n}\n"),
            "m.hf:4:17: error: 'x' (argument 1 of 'hfA_NoiseP') must be an array of at least 3 items; 'p' has 2");
  expectHas(compileError(model("d = hfA_NoiseP(x, 2);")), "m.hf:2:5: error: 'hfA_NoiseP' takes 1 argument");
}

}  // namespace
}  // namespace pf::field
