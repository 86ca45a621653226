// IntervalBatchEvaluator against the scalar IntervalEvaluator, bit for bit -- results and the
// choices of every min, max and select -- and IntervalSlopeBatchEvaluator against
// IntervalSlopeEvaluator, over the shipped models and a tape of every
// operation, on boxes of every size, degenerate, infinite and NaN-bearing ones included.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>

#include "compiler/diagnostics.h"
#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/interval_batch.h"
#include "raster/field/interval_evaluator.h"
#include "raster/field/interval_slope_batch.h"
#include "raster/field/interval_slope_evaluator.h"

namespace pf::field {
namespace {

using B = FieldTapeBuilder;

// Every operation, with constants that make NaN, infinity and exact ties reachable.
FieldTape everyOperation() {
  B b;
  const uint32_t x = b.x(), y = b.y(), z = b.z();
  const uint32_t s = b.binary(FieldOp::Add, b.unary(FieldOp::Sin, x), b.unary(FieldOp::Cos, y));
  const uint32_t e = b.unary(FieldOp::Exp, b.binary(FieldOp::Mul, z, b.constant(30.0f)));
  const uint32_t l = b.unary(FieldOp::Log, b.binary(FieldOp::Sub, x, b.constant(0.25f)));
  const uint32_t q = b.binary(FieldOp::Div, y, b.binary(FieldOp::Sub, z, b.constant(0.5f)));
  const uint32_t r = b.unary(FieldOp::Sqrt, b.binary(FieldOp::Sub, b.unary(FieldOp::Square, x), b.constant(0.1f)));
  const uint32_t a = b.unary(FieldOp::Atan, b.unary(FieldOp::Neg, b.unary(FieldOp::Abs, q)));
  const uint32_t big = b.binary(FieldOp::Mul, b.constant(3e38f), b.binary(FieldOp::Add, x, y));
  const uint32_t steps = b.unary(FieldOp::Floor, b.binary(FieldOp::Mul, b.constant(4.0f), b.binary(FieldOp::Add, x, z)));
  // HyperFun's Perlin tables, indexed by a point-dependent whole number (a table of a table).
  const uint32_t index = b.unary(FieldOp::Floor, b.binary(FieldOp::Mul, b.constant(100.0f), b.binary(FieldOp::Add, y, b.constant(1.0f))));
  const uint32_t table = b.unary(FieldOp::NoiseGradX, b.unary(FieldOp::NoisePerm, index));
  const uint32_t cond = b.binary(FieldOp::Less, x, y);
  const uint32_t cond2 = b.binary(FieldOp::LessEq, z, b.constant(0.0f));
  const uint32_t pick = b.select(cond, b.binary(FieldOp::Min, s, e), b.binary(FieldOp::Max, l, r));
  const uint32_t pick2 = b.select(cond2, b.binary(FieldOp::Add, a, b.binary(FieldOp::Add, steps, table)), big);
  const uint32_t sum = b.binary(FieldOp::Add, b.binary(FieldOp::Add, pick, pick2), b.binary(FieldOp::Mul, x, b.constant(1e-30f)));
  return b.finish(b.binary(FieldOp::Max, b.binary(FieldOp::Min, sum, b.constant(5.0f)), b.unary(FieldOp::Neg, q)));
}

bool same(Interval a, Interval b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectBatchIsScalar(const FieldTape& t, const char* name) {
  IntervalEvaluator scalar(t);
  IntervalBatchEvaluator batch;
  batch.reset(t);
  std::mt19937 rng(21);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float inf = std::numeric_limits<float>::infinity();
  int checked = 0, decided = 0;
  for (int round = 0; round < 40; ++round) {
    IntervalBatchEvaluator::Boxes boxes;
    Interval want[64];
    std::vector<Choice> want_choices[64];
    const int n = round % 5 == 4 ? 1 + round % 64 : 64;
    for (int j = 0; j < n; ++j) {
      Interval axes[3];
      for (Interval& a : axes) {
        const float size = std::pow(10.0f, -4.0f * (u(rng) + 1.0f));
        const float c = u(rng);
        a = {c, c + size};
        if (rng() % 20 == 0) a = {c, c};                 // a point
        if (rng() % 40 == 0) a = {-inf, c};              // half-infinite
        if (rng() % 40 == 0) a = Interval::whole();      // the whole line
        if (rng() % 60 == 0) a = {0.0f, 0.0f};           // ties with constants
        if (rng() % 80 == 0) a = {std::nanf(""), 1.0f};  // a NaN end
      }
      boxes.x_lo[j] = axes[0].lo, boxes.x_hi[j] = axes[0].hi;
      boxes.y_lo[j] = axes[1].lo, boxes.y_hi[j] = axes[1].hi;
      boxes.z_lo[j] = axes[2].lo, boxes.z_hi[j] = axes[2].hi;
      want[j] = scalar.evaluate(axes[0], axes[1], axes[2], &want_choices[j]);
    }
    const bool with_choices = round % 3 != 2;
    Interval got[64];
    batch.evaluate(boxes, n, got, with_choices);
    std::vector<Choice> got_choices;
    for (int j = 0; j < n; ++j) {
      ASSERT_TRUE(same(want[j], got[j])) << name << " round " << round << " box " << j << ": [" << want[j].lo << ", "
                                         << want[j].hi << "] against [" << got[j].lo << ", " << got[j].hi << "]";
      if (!with_choices) continue;
      batch.choicesOf(j, got_choices);
      ASSERT_EQ(want_choices[j], got_choices) << name << " round " << round << " box " << j;
      for (Choice c : got_choices) decided += c != Choice::Both;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000) << name;
  if (std::string(name) != "fidget/tanglecube.vm") {  // (no min/max in it)
    EXPECT_GT(decided, 0) << name;
  }
}

TEST(IntervalBatch, IsTheScalarIntervalFormBitForBit) {
  for (const char* name : {"fidget/prospero.vm", "fidget/bear.vm", "fidget/colonnade.vm", "fidget/tanglecube.vm"}) {
    DiagnosticLog log;
    expectBatchIsScalar(*readFidgetModel(name, testing::readModelText(name), log), name);
  }
  expectBatchIsScalar(everyOperation(), "every operation");
}

void expectSlopeBatchIsScalar(const FieldTape& t, const char* name) {
  IntervalSlopeEvaluator scalar(t);
  IntervalSlopeBatchEvaluator batch;
  batch.reset(t);
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const float inf = std::numeric_limits<float>::infinity();
  int checked = 0, monotone = 0;
  for (int round = 0; round < 40; ++round) {
    IntervalSlopeBatchEvaluator::Boxes pairs;
    IntervalSlope want[64];
    const int n = round % 5 == 4 ? 1 + round % 64 : (round % 2 ? 16 : 64);
    for (int j = 0; j < n; ++j) {
      Interval axes[6];
      for (int k = 0; k < 6; ++k) {
        Interval& a = axes[k];
        const float size = std::pow(10.0f, -4.0f * (u(rng) + 1.0f)) * (k >= 3 ? 0.01f : 1.0f);
        const float c = u(rng);
        a = {c, c + size};
        if (rng() % 20 == 0) a = {c, c};
        if (rng() % 40 == 0) a = {-inf, c};
        if (rng() % 40 == 0) a = Interval::whole();
        if (rng() % 60 == 0) a = {0.0f, 0.0f};
        if (rng() % 80 == 0) a = {std::nanf(""), 1.0f};
      }
      float* const lo[6] = {pairs.x_lo, pairs.y_lo, pairs.z_lo, pairs.dx_lo, pairs.dy_lo, pairs.dz_lo};
      float* const hi[6] = {pairs.x_hi, pairs.y_hi, pairs.z_hi, pairs.dx_hi, pairs.dy_hi, pairs.dz_hi};
      for (int k = 0; k < 6; ++k) lo[k][j] = axes[k].lo, hi[k][j] = axes[k].hi;
      want[j] = scalar.evaluate(axes[0], axes[1], axes[2], axes[3], axes[4], axes[5]);
    }
    IntervalSlope got[64];
    batch.evaluate(pairs, n, got);
    for (int j = 0; j < n; ++j) {
      ASSERT_TRUE(same(want[j].value, got[j].value) && same(want[j].rate, got[j].rate))
          << name << " round " << round << " pair " << j << ": value [" << want[j].value.lo << ", " << want[j].value.hi
          << "] / [" << got[j].value.lo << ", " << got[j].value.hi << "], rate [" << want[j].rate.lo << ", "
          << want[j].rate.hi << "] / [" << got[j].rate.lo << ", " << got[j].rate.hi << "]";
      monotone += got[j].monotone();
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000) << name;
  EXPECT_GT(monotone, 0) << name;  // the small boxes do prove monotonicity
}

TEST(IntervalSlopeBatch, IsTheScalarSlopeFormBitForBit) {
  for (const char* name : {"fidget/prospero.vm", "fidget/bear.vm", "fidget/colonnade.vm", "fidget/tanglecube.vm"}) {
    DiagnosticLog log;
    expectSlopeBatchIsScalar(*readFidgetModel(name, testing::readModelText(name), log), name);
  }
  expectSlopeBatchIsScalar(everyOperation(), "every operation");
}

TEST(IntervalBatch, NoTapeIsTheWholeLine) {
  IntervalBatchEvaluator batch;
  IntervalBatchEvaluator::Boxes boxes{};
  Interval out[2];
  batch.evaluate(boxes, 2, out, true);
  EXPECT_TRUE(out[0].isWhole() && out[1].isWhole());
}

}  // namespace
}  // namespace pf::field
