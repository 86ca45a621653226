// Sampled fields (voxel arrays, seed 000 section 3): the grid's trilinear and cubic B-spline
// values and derivatives against an independent double evaluation (a kernel sum over the
// samples, field_reference.h) and central differences; linear functions reproduced exactly;
// the interval and slope forms enclosing dense float samples of the value and the derivatives
// over random boxes (inside, across the edge, outside, huge); batched forms bit for bit the
// scalar ones; the same bits on every SIMD target; and the .pfgrid reader's errors with file,
// line and byte offset.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "compiler/field/field_source.h"
#include "compiler/field/sampled_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/interval_batch.h"
#include "raster/field/interval_evaluator.h"
#include "raster/field/interval_slope_batch.h"
#include "raster/field/interval_slope_evaluator.h"

namespace pf::field {
namespace {

constexpr SampleInterpolation kBoth[] = {SampleInterpolation::Trilinear, SampleInterpolation::CubicBSpline};

std::shared_ptr<const SampledGrid> randomGrid(SampleInterpolation interpolation, int nx, int ny, int nz, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> v(static_cast<size_t>(nx) * ny * nz);
  for (float& s : v) s = u(rng);
  const double lo[3] = {-1.0, -0.5, -2.0}, hi[3] = {1.0, 1.5, 0.0};
  return std::make_shared<const SampledGrid>(nx, ny, nz, lo, hi, interpolation, std::move(v));
}

TEST(SampledGrid, ValuesMatchAnIndependentKernelSumInDouble) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 5, 7, 4, 3);
    const FieldTape tape = sampledFieldTape(grid);
    FloatEvaluator fe(tape);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> ux(-1.4, 1.4), uy(-0.9, 1.9), uz(-2.4, 0.4);  // past the box too
    for (int k = 0; k < 2000; ++k) {
      const float x = static_cast<float>(ux(rng)), y = static_cast<float>(uy(rng)), z = static_cast<float>(uz(rng));
      const double want = testing::sampledReference(*grid, x, y, z);
      EXPECT_NEAR(fe.evaluate(x, y, z), want, 2e-7) << x << ", " << y << ", " << z;
      EXPECT_NEAR(testing::evaluateDouble(tape, x, y, z), want, 1e-12);
    }
  }
}

TEST(SampledGrid, LinearFunctionsAreReproducedExactlyInsideTheBox) {
  // Both interpolants reproduce linear functions (the B-spline too, away from the clamped edge
  // samples, whose support repeats the edge: one cell in from the edges).
  for (SampleInterpolation interpolation : kBoth) {
    const int n = 9;
    std::vector<float> v;
    const double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) v.push_back(static_cast<float>(0.5 * (-1 + 0.25 * i) - 0.25 * (-1 + 0.25 * j) + 0.125 * (-1 + 0.25 * k)));
    SampledGrid grid(n, n, n, lo, hi, interpolation, v);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-0.74, 0.74);
    for (int k = 0; k < 500; ++k) {
      const float x = static_cast<float>(u(rng)), y = static_cast<float>(u(rng)), z = static_cast<float>(u(rng));
      float g[4];
      grid.valueAndGradient(x, y, z, g);
      EXPECT_NEAR(g[0], 0.5 * x - 0.25 * y + 0.125 * z, 1e-6);
      EXPECT_NEAR(g[1], 0.5, 1e-5);
      EXPECT_NEAR(g[2], -0.25, 1e-5);
      EXPECT_NEAR(g[3], 0.125, 1e-5);
    }
  }
}

TEST(SampledGrid, GradientsMatchCentralDifferencesOfTheReference) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 6, 5, 7, 4);
    GradientEvaluator ge(sampledFieldTape(grid));
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> ux(-0.95, 0.95), uy(-0.45, 1.45), uz(-1.95, -0.05);
    for (int k = 0; k < 500; ++k) {
      const double p[3] = {ux(rng), uy(rng), uz(rng)};
      const FieldGradient g = ge.evaluate(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
      const float* got[3] = {&g.dx, &g.dy, &g.dz};
      for (int a = 0; a < 3; ++a) {
        const double h = 1e-6;
        double q0[3] = {p[0], p[1], p[2]}, q1[3] = {p[0], p[1], p[2]};
        q0[a] -= h;
        q1[a] += h;
        // (Trilinear is C0 across cell faces: skip points next to one.)
        const double cells = (p[a] - grid->boxMin(a)) / (grid->boxMax(a) - grid->boxMin(a)) * (grid->size(a) - 1);
        if (interpolation == SampleInterpolation::Trilinear && std::fabs(cells - std::round(cells)) < 1e-4) continue;
        const double want = (testing::sampledReference(*grid, q1[0], q1[1], q1[2]) -
                             testing::sampledReference(*grid, q0[0], q0[1], q0[2])) / (2 * h);
        EXPECT_NEAR(*got[a], want, 2e-4 * std::max(1.0, std::fabs(want))) << "axis " << a;
      }
    }
  }
}

// Random boxes: small, cell-sized, across the box's faces, outside it, the whole line's halves.
std::vector<std::array<float, 6>> randomBoxes(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> c(-2.5f, 2.5f);
  std::vector<std::array<float, 6>> boxes;
  for (int k = 0; k < 300; ++k) {
    const float w = k % 4 == 0 ? 1e-4f : k % 4 == 1 ? 0.1f : k % 4 == 2 ? 0.6f : 3.0f;
    std::array<float, 6> b;
    for (int a = 0; a < 3; ++a) {
      b[a] = c(rng);
      b[3 + a] = b[a] + w * (0.5f + static_cast<float>(k % 7) / 7.0f);
    }
    boxes.push_back(b);
  }
  boxes.push_back({-INFINITY, -INFINITY, -INFINITY, INFINITY, 0.0f, INFINITY});
  return boxes;
}

TEST(SampledGrid, IntervalFormsEncloseDenseSamplesOfValuesAndDerivatives) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 8, 6, 9, 5);
    const FieldTape tape = sampledFieldTape(grid);
    IntervalEvaluator ie(tape);
    IntervalSlopeEvaluator se(tape);
    FloatEvaluator fe(tape);
    GradientEvaluator ge(tape);
    for (const auto& b : randomBoxes(6)) {
      const Interval x{b[0], b[3]}, y{b[1], b[4]}, z{b[2], b[5]};
      const Interval r = ie.evaluate(x, y, z);
      // A direction box: the rate must hold every grad . d for d in it.
      const Interval dx{0.2f, 0.5f}, dy{-1.0f, -0.8f}, dz{-0.1f, 0.3f};
      const IntervalSlope s = se.evaluate(x, y, z, dx, dy, dz);
      EXPECT_EQ(s.value.lo, r.lo);
      EXPECT_EQ(s.value.hi, r.hi);
      const int steps = 12;
      auto along = [&](int a, int i) {
        const float lo = std::max(b[a], -3.0f), hi = std::min(b[3 + a], 3.0f);
        return lo + (hi - lo) * static_cast<float>(i) / steps;
      };
      for (int i = 0; i <= steps; ++i)
        for (int j = 0; j <= steps; ++j)
          for (int k = 0; k <= steps; ++k) {
            const float px = along(0, i), py = along(1, j), pz = along(2, k);
            const float v = fe.evaluate(px, py, pz);
            ASSERT_TRUE(r.contains(v)) << v << " outside [" << r.lo << ", " << r.hi << "] at " << px << ", " << py << ", " << pz;
            const FieldGradient g = ge.evaluate(px, py, pz);
            for (const float ddx : {dx.lo, dx.hi})
              for (const float ddy : {dy.lo, dy.hi})
                for (const float ddz : {dz.lo, dz.hi}) {
                  const double rate = static_cast<double>(g.dx) * ddx + static_cast<double>(g.dy) * ddy + static_cast<double>(g.dz) * ddz;
                  ASSERT_TRUE(s.rate.lo <= rate + 1e-6 && rate - 1e-6 <= s.rate.hi)
                      << rate << " outside [" << s.rate.lo << ", " << s.rate.hi << "]";
                }
          }
    }
  }
}

TEST(SampledGrid, BatchedIntervalFormsAreTheScalarOnesBitForBit) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 7, 7, 7, 8);
    FieldTapeBuilder builder;
    // The grid inside a little arithmetic, so that it is not only a leaf alone.
    const uint32_t s = builder.sample(grid);
    const FieldTape tape = builder.finish(builder.binary(FieldOp::Sub, builder.unary(FieldOp::Square, builder.x()), s));
    IntervalEvaluator ie(tape);
    IntervalSlopeEvaluator se(tape);
    IntervalBatchEvaluator ib;
    IntervalSlopeBatchEvaluator sb;
    ib.reset(tape);
    sb.reset(tape);
    const auto boxes = randomBoxes(12);
    IntervalBatchEvaluator::Boxes in{};
    IntervalSlopeBatchEvaluator::Boxes sin{};
    const int n = 40;
    for (int j = 0; j < n; ++j) {
      const auto& b = boxes[static_cast<size_t>(j)];
      in.x_lo[j] = sin.x_lo[j] = b[0], in.y_lo[j] = sin.y_lo[j] = b[1], in.z_lo[j] = sin.z_lo[j] = b[2];
      in.x_hi[j] = sin.x_hi[j] = b[3], in.y_hi[j] = sin.y_hi[j] = b[4], in.z_hi[j] = sin.z_hi[j] = b[5];
      sin.dx_lo[j] = 0.1f, sin.dx_hi[j] = 0.2f, sin.dy_lo[j] = -0.3f, sin.dy_hi[j] = 0.4f, sin.dz_lo[j] = 0.9f, sin.dz_hi[j] = 1.0f;
    }
    Interval out[n];
    IntervalSlope sout[n];
    ib.evaluate(in, n, out, false);
    sb.evaluate(sin, n, sout);
    for (int j = 0; j < n; ++j) {
      const Interval x{in.x_lo[j], in.x_hi[j]}, y{in.y_lo[j], in.y_hi[j]}, z{in.z_lo[j], in.z_hi[j]};
      const Interval want = ie.evaluate(x, y, z);
      EXPECT_TRUE(std::memcmp(&want, &out[j], sizeof want) == 0) << "box " << j;
      const IntervalSlope ws = se.evaluate(x, y, z, {0.1f, 0.2f}, {-0.3f, 0.4f}, {0.9f, 1.0f});
      EXPECT_TRUE(std::memcmp(&ws, &sout[j], sizeof ws) == 0) << "box " << j;
    }
  }
}

TEST(SampledGrid, EverySimdTargetGivesTheSameBits) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 6, 7, 5, 13);
    const FieldTape tape = sampledFieldTape(grid);
    float x[FloatEvaluator::kBatch], y[FloatEvaluator::kBatch], z[FloatEvaluator::kBatch];
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (int i = 0; i < FloatEvaluator::kBatch; ++i) x[i] = u(rng), y[i] = u(rng), z[i] = u(rng);
    std::vector<float> first;
    std::vector<FieldGradient> first_gradients;
    for (const std::string& target : floatSlotsTargets()) {
      ASSERT_TRUE(useFloatSlotsTarget(target));
      FloatEvaluator fe(tape);
      GradientEvaluator ge(tape);
      std::vector<float> v(FloatEvaluator::kBatch);
      std::vector<FieldGradient> g(FloatEvaluator::kBatch);
      fe.evaluate(x, y, z, FloatEvaluator::kBatch, v.data());
      ge.evaluate(x, y, z, FloatEvaluator::kBatch, g.data());
      if (first.empty()) {
        first = v;
        first_gradients = g;
        continue;
      }
      EXPECT_EQ(std::memcmp(first.data(), v.data(), v.size() * sizeof(float)), 0) << target;
      EXPECT_EQ(std::memcmp(first_gradients.data(), g.data(), g.size() * sizeof(FieldGradient)), 0) << target;
    }
    EXPECT_TRUE(useFloatSlotsTarget("best"));
  }
}

TEST(SampledGrid, LipschitzBoundsEveryGradient) {
  for (SampleInterpolation interpolation : kBoth) {
    const auto grid = randomGrid(interpolation, 6, 6, 6, 11);
    GradientEvaluator ge(sampledFieldTape(grid));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (int k = 0; k < 2000; ++k) {
      const FieldGradient g = ge.evaluate(u(rng), u(rng), u(rng));
      EXPECT_LE(std::sqrt(g.dx * g.dx + g.dy * g.dy + g.dz * g.dz), grid->lipschitz());
    }
  }
}

// A .pfgrid file: the header lines and the samples as little-endian float32.
std::string gridFile(const std::string& header, const std::vector<float>& samples) {
  std::string out = header;
  for (float f : samples) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    for (int b = 0; b < 4; ++b) out += static_cast<char>((bits >> (8 * b)) & 0xff);
  }
  return out;
}

std::string readError(const std::string& bytes) {
  DiagnosticLog log;
  EXPECT_FALSE(readSampledField("g.pfgrid", bytes, log)) << bytes.substr(0, 80);
  return log.format();
}

void expectHas(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected to find: " << part << "\nin:\n" << text;
}

TEST(SampledReader, ReadsTheHeaderAndTheSamples) {
  std::vector<float> v(2 * 3 * 2);
  for (size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(i) - 5.5f;
  DiagnosticLog log;
  const auto grid = readSampledField(
      "g.pfgrid", gridFile("pfgrid 1\n# a comment\nbox -1 -2 -3 1 2 3\nsize 2 3 2\ninterpolation tricubic\ndata\n", v), log);
  ASSERT_TRUE(grid) << log.format();
  EXPECT_EQ(grid->size(0), 2);
  EXPECT_EQ(grid->size(1), 3);
  EXPECT_EQ(grid->interpolation(), SampleInterpolation::CubicBSpline);
  EXPECT_EQ(grid->sample(1, 2, 1), v[1 + 2 * 2 + 1 * 6]);
  EXPECT_EQ(grid->boxMax(2), 3.0);
  // Through compileFieldSource, by the file's extension.
  ASSERT_EQ(fieldFormatOfPath("a/b.pfgrid"), FieldFormat::Sampled);
  const auto tape = compileFieldSource(FieldFormat::Sampled, "g.pfgrid",
                                       gridFile("pfgrid 1\nsize 2 3 2\nbox -1 -2 -3 1 2 3\ninterpolation trilinear\ndata\n", v),
                                       {}, 0.0, log);
  ASSERT_TRUE(tape) << log.format();
  EXPECT_EQ(tape->grids.size(), 1u);
  EXPECT_FLOAT_EQ(FloatEvaluator(*tape).evaluate(-1.0f, -2.0f, -3.0f), v[0]);
}

TEST(SampledReader, MalformedFilesNameTheLineOrTheByteOffset) {
  const std::string head = "pfgrid 1\nsize 2 2 2\nbox 0 0 0 1 1 1\ninterpolation trilinear\ndata\n";
  const std::vector<float> eight(8, 1.0f);
  expectHas(readError("grid 1\n"), "g.pfgrid:1:1: error: a sampled field file starts with 'pfgrid 1'");
  expectHas(readError("pfgrid 1\nsize 0 2 2\n"), "g.pfgrid:2:6: error: '0' is not a sample count");
  expectHas(readError("pfgrid 1\nsize 2 2\n"), "g.pfgrid:2:1: error: 'size' takes 3 whole numbers");
  expectHas(readError("pfgrid 1\nbox 0 0 0 1 nan 1\n"), "g.pfgrid:2:13: error: 'nan' is not a finite number");
  expectHas(readError("pfgrid 1\nbox 0 0 0 1 0 1\n"), "g.pfgrid:2:13: error: the box's second corner must be above");
  expectHas(readError("pfgrid 1\nsize 2 2 2\ncolour red\n"), "g.pfgrid:3:1: error: unknown header line 'colour'");
  expectHas(readError("pfgrid 1\ninterpolation cubic\n"), "g.pfgrid:2:15: error: unknown interpolation 'cubic'");
  expectHas(readError("pfgrid 1\nsize 2 2 2\n"), "g.pfgrid:2:1: error: the header does not end with a 'data' line");
  expectHas(readError("pfgrid 1\nsize 2 2 2\ndata\n"), "g.pfgrid:3:1: error: the header has no 'box' line");
  expectHas(readError(gridFile(head, std::vector<float>(7, 1.0f))),
            "g.pfgrid:5:1: error: the data ends at byte offset 28 of the 32 that 8 samples need (the file is truncated)");
  expectHas(readError(gridFile(head, std::vector<float>(9, 1.0f))), "g.pfgrid:5:1: error: the data has 4 bytes past its 8 samples");
  std::vector<float> nan = eight;
  nan[5] = NAN;
  expectHas(readError(gridFile(head, nan)), "g.pfgrid:5:1: error: sample 5 (at byte offset 20 of the data) is not a finite number");
  expectHas(readError("pfgrid 1\nsize 1000 1000 1000\nbox 0 0 0 1 1 1\ninterpolation trilinear\ndata\n"),
            "g.pfgrid:5:1: error: a sampled field of 1000 x 1000 x 1000 samples is larger than the 16777216 allowed");
}

}  // namespace
}  // namespace pf::field
