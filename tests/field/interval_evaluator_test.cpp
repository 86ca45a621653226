// The interval form encloses dense float samples: per operation on awkward intervals, and over
// boxes of the shipped models; min/max choices give simplified tapes with bit-identical values.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/interval_evaluator.h"

namespace pf::field {
namespace {

// Whether the float value v at a point is allowed by interval r: inside it, or NaN where r is
// the whole line (which stands for "any value or NaN").
::testing::AssertionResult encloses(Interval r, float v) {
  if (std::isnan(v) ? r.isWhole() : r.contains(v)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << v << " outside [" << r.lo << ", " << r.hi << "]";
}

FieldTape unaryTape(FieldOp op) {
  FieldTapeBuilder b;
  return b.finish(b.unary(op, b.x()));
}
FieldTape binaryTape(FieldOp op) {
  FieldTapeBuilder b;
  return b.finish(b.binary(op, b.x(), b.y()));
}

// Samples every interval in a list densely (endpoints included) for each operation.
TEST(IntervalEvaluator, EveryOperationEnclosesDenseSamples) {
  const std::vector<Interval> boxes = {
      {0.0f, 0.0f},    {0.0f, 1.0f},      {-1.0f, 0.0f},   {-2.5f, 3.0f},     {1e-30f, 1e-20f},
      {-7.0f, -3.0f},  {0.1f, 0.1000001f}, {1e6f, 1e7f},   {-40.0f, 40.0f},   {1.5f, 1.6f},
      {3.1f, 3.2f},    {-1e-7f, 1e-7f},   {80.0f, 90.0f},  {0.333f, 0.334f},
      // (index ranges of the Perlin tables: one entry, a few, past 64, past the end)
      {17.0f, 17.9f},  {200.5f, 203.0f},  {100.0f, 300.0f}, {500.0f, 600.0f}};
  const FieldOp unary[] = {FieldOp::Neg, FieldOp::Abs, FieldOp::Square, FieldOp::Sqrt,
                           FieldOp::Exp, FieldOp::Log, FieldOp::Sin,    FieldOp::Cos, FieldOp::Atan,
                           FieldOp::Floor, FieldOp::NoisePerm, FieldOp::NoiseGradX, FieldOp::NoiseGradY,
                           FieldOp::NoiseGradZ};
  const FieldOp binary[] = {FieldOp::Add, FieldOp::Sub, FieldOp::Mul, FieldOp::Div, FieldOp::Min, FieldOp::Max};
  auto samples = [](Interval r) {
    std::vector<float> s;
    for (int k = 0; k <= 64; ++k) s.push_back(r.lo + (r.hi - r.lo) * (k / 64.0f));
    s.push_back(r.lo);
    s.push_back(r.hi);
    return s;
  };
  for (FieldOp op : unary) {
    SCOPED_TRACE(std::string(fieldOpName(op)));
    const FieldTape t = unaryTape(op);
    IntervalEvaluator ie(t);
    FloatEvaluator fe(t);
    for (Interval x : boxes) {
      const Interval r = ie.evaluate(x, {0, 0}, {0, 0});
      for (float v : samples(x)) {
        if (!x.contains(v)) continue;
        EXPECT_TRUE(encloses(r, fe.evaluate(v, 0.0f, 0.0f))) << "x = " << v;
      }
    }
  }
  for (FieldOp op : binary) {
    SCOPED_TRACE(std::string(fieldOpName(op)));
    const FieldTape t = binaryTape(op);
    IntervalEvaluator ie(t);
    FloatEvaluator fe(t);
    for (Interval x : boxes) {
      for (Interval y : boxes) {
        const Interval r = ie.evaluate(x, y, {0, 0});
        for (float u : samples(x))
          for (float v : samples(y)) {
            if (!x.contains(u) || !y.contains(v)) continue;
            EXPECT_TRUE(encloses(r, fe.evaluate(u, v, 0.0f))) << u << ", " << v;
          }
      }
    }
  }
}

TEST(IntervalEvaluator, RoundsOutwardWhereFloatRoundingCouldLeaveTheRange) {
  // 1 + 2^-40 is not a float: the sum's lower end must not be rounded up past the true value.
  const Interval s = intervalAdd({1.0f, 1.0f}, {-0x1p-40f, -0x1p-40f});
  EXPECT_LT(s.lo, 1.0f);
  EXPECT_GE(s.hi, 1.0f);
  // Exact results stay tight: no widening of a square root of a square, or of 2 + 2.
  EXPECT_EQ(intervalSqrt({4.0f, 9.0f}).lo, 2.0f);
  EXPECT_EQ(intervalSqrt({4.0f, 9.0f}).hi, 3.0f);
  EXPECT_EQ(intervalAdd({2.0f, 2.0f}, {2.0f, 2.0f}).lo, 4.0f);
  EXPECT_EQ(intervalSquare({-2.0f, 1.0f}).lo, 0.0f);
  // NaN-producing inputs give the whole line.
  EXPECT_TRUE(intervalSqrt({-1.0f, 4.0f}).isWhole());
  EXPECT_TRUE(intervalLog({-1.0f, 4.0f}).isWhole());
  EXPECT_TRUE(intervalDiv({1.0f, 2.0f}, {-1.0f, 1.0f}).isWhole());
  EXPECT_TRUE(intervalMul({0.0f, 0.0f}, Interval::whole()).isWhole());
  EXPECT_TRUE(intervalSin({0.0f, std::numeric_limits<float>::infinity()}).isWhole());
}

TEST(IntervalEvaluator, FloatStepsMatchNextafter) {
  const float inf = std::numeric_limits<float>::infinity();
  for (float v : {0.0f, -0.0f, 1.0f, -1.0f, 1e-45f, -1e-45f, 3.4028235e38f, -3.4028235e38f, inf, -inf, 0.1f, -7.5f}) {
    EXPECT_EQ(floatBelow(v), std::nextafter(v, -inf)) << v;
    EXPECT_EQ(floatAbove(v), std::nextafter(v, inf)) << v;
  }
  EXPECT_TRUE(std::isnan(floatBelow(std::nanf(""))));
}

FieldTape model(const std::string& name) {
  DiagnosticLog log;
  auto t = readFidgetModel(name, testing::readModelText(name), log);
  EXPECT_TRUE(t) << log.format();
  return *t;
}

// Random boxes of three sizes over [-1, 1]^3; a 5x5x5 grid of float samples in each.
TEST(IntervalEvaluator, ModelsEncloseSamplesAndSimplifiedTapesAgreeBitForBit) {
  for (const char* name : {"fidget/bear.vm", "fidget/colonnade.vm", "fidget/prospero.vm", "fidget/tanglecube.vm"}) {
    SCOPED_TRACE(name);
    const FieldTape t = model(name);
    IntervalEvaluator ie(t);
    FloatEvaluator fe(t);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    size_t shortest = t.size();
    for (float size : {0.5f, 0.05f, 0.005f}) {
      for (int k = 0; k < 12; ++k) {
        const float x0 = u(rng), y0 = u(rng), z0 = u(rng);
        const Interval bx{x0, x0 + size}, by{y0, y0 + size}, bz{z0, z0 + size};
        std::vector<Choice> choices;
        const Interval r = ie.evaluate(bx, by, bz, &choices);
        const FieldTape s = simplify(t, choices);
        shortest = std::min(shortest, s.size());
        FloatEvaluator se(s);
        for (int i = 0; i < 5; ++i)
          for (int j = 0; j < 5; ++j)
            for (int l = 0; l < 5; ++l) {
              const float x = x0 + size * i / 4, y = y0 + size * j / 4, z = z0 + size * l / 4;
              if (!bx.contains(x) || !by.contains(y) || !bz.contains(z)) continue;
              const float v = fe.evaluate(x, y, z);
              ASSERT_TRUE(encloses(r, v)) << x << ", " << y << ", " << z;
              ASSERT_EQ(v, se.evaluate(x, y, z)) << x << ", " << y << ", " << z;
            }
      }
    }
    // Inside a small box most of a CSG model is decided (tanglecube has no min/max at all).
    // Inside a small box much of a CSG model is decided: Prospero (a union of thousands of
    // glyph pieces) drops to a small fraction; tanglecube has no min/max at all.
    std::printf("%s: %zu instructions, shortest simplified tape %zu\n", name, t.size(), shortest);
    if (std::string(name) == "fidget/prospero.vm") {
      EXPECT_LT(shortest * 10, t.size());
    } else if (std::string(name) != "fidget/tanglecube.vm") {
      EXPECT_LT(shortest, t.size());
    }
  }
}

}  // namespace
}  // namespace pf::field
