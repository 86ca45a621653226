// IntervalSlopeEvaluator against the double-precision meaning of the tape: over random small
// boxes of the shipped models and a gyroid, the value enclosure holds f at sampled points and the
// rate enclosure holds central differences of f along sampled directions; monotone() is claimed
// only where it holds, and never across a step.
#include <gtest/gtest.h>

#include <random>

#include "field/cast_comparison.h"
#include "raster/field/interval_slope_evaluator.h"

namespace pf::field {
namespace {

using B = FieldTapeBuilder;

Interval around(double lo, double hi) { return {floatBelow(static_cast<float>(lo)), floatAbove(static_cast<float>(hi))}; }

void checkEnclosures(const FieldTape& tape, const char* name) {
  IntervalSlopeEvaluator se(tape);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double size = std::pow(10.0, -3.0 + 2.5 * (unit(rng) + 1.0) / 2.0);
    double lo[3], hi[3], dlo[3], dhi[3];
    for (int k = 0; k < 3; ++k) {
      const double c = unit(rng);
      lo[k] = c - size * (1.0 + unit(rng)) / 2.0;
      hi[k] = c + size * (1.0 + unit(rng)) / 2.0;
      const double d = unit(rng);
      dlo[k] = d - 0.05 * (1.0 + unit(rng));
      dhi[k] = d + 0.05 * (1.0 + unit(rng));
    }
    const IntervalSlope s = se.evaluate(around(lo[0], hi[0]), around(lo[1], hi[1]), around(lo[2], hi[2]),
                                        around(dlo[0], dhi[0]), around(dlo[1], dhi[1]), around(dlo[2], dhi[2]));
    for (int sample = 0; sample < 20; ++sample) {
      double p[3], d[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = lo[k] + (hi[k] - lo[k]) * (unit(rng) + 1.0) / 2.0;
        d[k] = dlo[k] + (dhi[k] - dlo[k]) * (unit(rng) + 1.0) / 2.0;
      }
      const double f = testing::evaluateDouble(tape, p[0], p[1], p[2]);
      const double h = 1e-7;
      const double fp = testing::evaluateDouble(tape, p[0] + h * d[0], p[1] + h * d[1], p[2] + h * d[2]);
      const double fm = testing::evaluateDouble(tape, p[0] - h * d[0], p[1] - h * d[1], p[2] - h * d[2]);
      const double rate = (fp - fm) / (2.0 * h);
      if (!std::isfinite(f) || !std::isfinite(rate)) continue;
      const double tol = 1e-5 * (1.0 + std::fabs(f));
      EXPECT_LE(s.value.lo - tol, f) << name << " value at trial " << trial;
      EXPECT_GE(s.value.hi + tol, f) << name << " value at trial " << trial;
      const double rate_tol = 1e-3 * (1.0 + std::fabs(rate));  // the difference's own error
      EXPECT_LE(s.rate.lo - rate_tol, rate) << name << " rate at trial " << trial;
      EXPECT_GE(s.rate.hi + rate_tol, rate) << name << " rate at trial " << trial;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000) << name;
}

TEST(IntervalSlope, EnclosesValueAndRateOfTheShippedModels) {
  for (const char* name : {"fidget/tanglecube.vm", "fidget/bear.vm", "fidget/colonnade.vm"}) checkEnclosures(model(name), name);
}

TEST(IntervalSlope, EnclosesTranscendentalsAndDivisions) {
  B b;
  const uint32_t s = b.unary(FieldOp::Sin, b.binary(FieldOp::Mul, b.constant(3.0f), b.x()));
  const uint32_t e = b.unary(FieldOp::Exp, b.binary(FieldOp::Mul, b.y(), b.z()));
  const uint32_t q = b.binary(FieldOp::Div, s, b.binary(FieldOp::Add, b.constant(2.0f), b.unary(FieldOp::Cos, b.z())));
  const uint32_t a = b.unary(FieldOp::Atan, b.binary(FieldOp::Sub, e, q));
  const uint32_t l = b.unary(FieldOp::Log, b.binary(FieldOp::Add, b.constant(1.5f), b.unary(FieldOp::Abs, b.x())));
  checkEnclosures(b.finish(b.binary(FieldOp::Max, a, b.binary(FieldOp::Mul, l, b.unary(FieldOp::Sqrt, e)))), "mixed");
}

TEST(IntervalSlope, FloorIsFlatBetweenItsStepsAndUnboundedAcrossThem) {
  B b;
  const uint32_t steps = b.unary(FieldOp::Floor, b.binary(FieldOp::Mul, b.constant(3.0f), b.x()));
  const uint32_t wave = b.unary(FieldOp::Sin, b.binary(FieldOp::Add, b.y(), b.unary(FieldOp::Floor, b.z())));
  checkEnclosures(b.finish(b.binary(FieldOp::Add, b.binary(FieldOp::Mul, b.constant(0.01f), b.x()),
                                    b.binary(FieldOp::Add, steps, wave))), "floor");
  // 0.01 x + floor(3x): rises between the steps (rate 0.01), jumps across one.
  B c;
  const FieldTape stair = c.finish(c.binary(FieldOp::Add, c.binary(FieldOp::Mul, c.constant(0.01f), c.x()),
                                            c.unary(FieldOp::Floor, c.binary(FieldOp::Mul, c.constant(3.0f), c.x()))));
  const Interval box{0.2f, 0.3f}, one{1.0f, 1.0f}, zero{0.0f, 0.0f};
  IntervalSlopeEvaluator se(stair);
  const IntervalSlope flat = se.evaluate({0.1f, 0.3f}, box, box, one, zero, zero);
  EXPECT_TRUE(flat.monotone());
  EXPECT_LT(flat.value.hi, 0.01f);  // 0.01 x + 0 over the box
  EXPECT_FALSE(se.evaluate({0.2f, 0.4f}, box, box, one, zero, zero).monotone());
}

TEST(IntervalSlope, MonotoneOnlyWhereItHolds) {
  const Interval along_x[3] = {{1.0f, 1.0f}, {0.0f, 0.0f}, {0.0f, 0.0f}};
  const Interval box_x{-0.5f, 0.5f}, box{0.2f, 0.3f};
  // x - 0.1: strictly increasing along +x.
  B a;
  const FieldTape linear = a.finish(a.binary(FieldOp::Sub, a.x(), a.constant(0.1f)));
  EXPECT_TRUE(IntervalSlopeEvaluator(linear).evaluate(box_x, box, box, along_x[0], along_x[1], along_x[2]).monotone());
  // |x| - 0.1 across x = 0: down then up.
  B b;
  const FieldTape vee = b.finish(b.binary(FieldOp::Sub, b.unary(FieldOp::Abs, b.x()), b.constant(0.1f)));
  EXPECT_FALSE(IntervalSlopeEvaluator(vee).evaluate(box_x, box, box, along_x[0], along_x[1], along_x[2]).monotone());
  // A step up at x = 0 plus a slope: 0.01 x + (x < 0 ? -1 : 1) rises, but jumps -- a sliver's
  // shape (in and out) is possible with such jumps, so no monotone claim across the step.
  B c;
  const uint32_t step = c.select(c.binary(FieldOp::Less, c.x(), c.constant(0.0f)), c.constant(-1.0f), c.constant(1.0f));
  const FieldTape jump = c.finish(c.binary(FieldOp::Add, c.binary(FieldOp::Mul, c.constant(0.01f), c.x()), step));
  IntervalSlopeEvaluator se(jump);
  EXPECT_FALSE(se.evaluate(box_x, box, box, along_x[0], along_x[1], along_x[2]).monotone());
  // ... and on one side of the step it is monotone.
  EXPECT_TRUE(se.evaluate({0.1f, 0.4f}, box, box, along_x[0], along_x[1], along_x[2]).monotone());
  // sqrt at 0 has an unbounded rate: no claim.
  B d;
  const FieldTape root = d.finish(d.unary(FieldOp::Sqrt, d.x()));
  EXPECT_FALSE(IntervalSlopeEvaluator(root).evaluate({0.0f, 0.5f}, box, box, along_x[0], along_x[1], along_x[2]).monotone());
}

}  // namespace
}  // namespace pf::field
