// The gradient form (forward-mode AD) against a double-precision central difference of the
// double evaluation of the same tape, at points where the field is smooth.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "compiler/field/fidget_reader.h"
#include "field/field_reference.h"
#include "raster/field/gradient_evaluator.h"

namespace pf::field {
namespace {

TEST(GradientEvaluator, MatchesCentralDifferencesOfTheDoubleField) {
  for (const char* name : {"fidget/tanglecube.vm", "fidget/bear.vm", "fidget/colonnade.vm"}) {
    SCOPED_TRACE(name);
    DiagnosticLog log;
    const FieldTape t = *readFidgetModel(name, testing::readModelText(name), log);
    GradientEvaluator ge(t);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int compared = 0;
    for (int k = 0; k < 400; ++k) {
      const double p[3] = {u(rng), u(rng), u(rng)};
      const FieldGradient g = ge.evaluate(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
      double want[3];
      bool smooth = true;
      for (int axis = 0; axis < 3; ++axis) {
        // Central differences at two step sizes; where they disagree the point is near a kink
        // (min, max, abs) and the derivative is not defined there: skip it.
        auto diff = [&](double h) {
          double a[3] = {p[0], p[1], p[2]}, b[3] = {p[0], p[1], p[2]};
          a[axis] += h;
          b[axis] -= h;
          return (testing::evaluateDouble(t, a[0], a[1], a[2]) - testing::evaluateDouble(t, b[0], b[1], b[2])) / (2 * h);
        };
        want[axis] = diff(1e-6);
        if (std::fabs(want[axis] - diff(1e-5)) > 1e-4 * std::max(1.0, std::fabs(want[axis]))) smooth = false;
      }
      if (!smooth) continue;
      // The float point is the double point rounded: compare at the float point's own gradient
      // scale, relative to the gradient's size.
      const double scale = std::max({1.0, std::fabs(want[0]), std::fabs(want[1]), std::fabs(want[2])});
      EXPECT_NEAR(g.dx, want[0], 2e-3 * scale);
      EXPECT_NEAR(g.dy, want[1], 2e-3 * scale);
      EXPECT_NEAR(g.dz, want[2], 2e-3 * scale);
      ++compared;
    }
    EXPECT_GT(compared, 200);
  }
}

TEST(GradientEvaluator, EveryOperationHasItsDerivative) {
  // f = sin(x) * exp(y) / (2 + cos(z)) + sqrt(x*x + 1) - ln(y + 3) + |z - 5| - (-x)
  FieldTapeBuilder b;
  const uint32_t x = b.x(), y = b.y(), z = b.z();
  uint32_t f = b.binary(FieldOp::Mul, b.unary(FieldOp::Sin, x), b.unary(FieldOp::Exp, y));
  f = b.binary(FieldOp::Div, f, b.binary(FieldOp::Add, b.constant(2.0f), b.unary(FieldOp::Cos, z)));
  f = b.binary(FieldOp::Add, f, b.unary(FieldOp::Sqrt, b.binary(FieldOp::Add, b.unary(FieldOp::Square, x), b.constant(1.0f))));
  f = b.binary(FieldOp::Sub, f, b.unary(FieldOp::Log, b.binary(FieldOp::Add, y, b.constant(3.0f))));
  f = b.binary(FieldOp::Add, f, b.unary(FieldOp::Abs, b.binary(FieldOp::Sub, z, b.constant(5.0f))));
  f = b.binary(FieldOp::Sub, f, b.unary(FieldOp::Neg, x));
  const FieldTape t = b.finish(f);
  GradientEvaluator ge(t);
  const double X = 0.3, Y = -0.4, Z = 0.7;
  const FieldGradient g = ge.evaluate(0.3f, -0.4f, 0.7f);
  const double dfdx = std::cos(X) * std::exp(Y) / (2 + std::cos(Z)) + X / std::sqrt(X * X + 1) + 1;
  const double dfdy = std::sin(X) * std::exp(Y) / (2 + std::cos(Z)) - 1 / (Y + 3);
  const double dfdz = std::sin(X) * std::exp(Y) * std::sin(Z) / ((2 + std::cos(Z)) * (2 + std::cos(Z))) - 1;
  EXPECT_NEAR(g.dx, dfdx, 1e-5);
  EXPECT_NEAR(g.dy, dfdy, 1e-5);
  EXPECT_NEAR(g.dz, dfdz, 1e-5);
  EXPECT_NEAR(g.value, testing::evaluateDouble(t, X, Y, Z), 1e-5);
}

// The pixel executor's scratch evaluator (PixelExecutor::fieldGradient) runs many tapes one after
// the other on the same storage, slots left as the last tape wrote them: every value equals a
// fresh evaluator's, bit for bit, for every batch size -- a big tape after a small one (slots
// grow), a small one after a big one (stale slots), and the same tape again.
TEST(GradientEvaluator, ResetMatchesAFreshEvaluatorBitForBit) {
  std::vector<FieldTape> tapes;
  for (const char* name : {"fidget/tanglecube.vm", "fidget/bear.vm", "fidget/colonnade.vm"}) {
    DiagnosticLog log;
    tapes.push_back(*readFidgetModel(name, testing::readModelText(name), log));
  }
  FieldTapeBuilder b;
  tapes.push_back(b.finish(b.binary(FieldOp::Mul, b.unary(FieldOp::Sin, b.x()), b.y())));
  GradientEvaluator scratch;
  float x[GradientEvaluator::kBatch], y[GradientEvaluator::kBatch], z[GradientEvaluator::kBatch];
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < GradientEvaluator::kBatch; ++i) x[i] = u(rng), y[i] = u(rng), z[i] = u(rng);
  EXPECT_EQ(scratch.evaluate(0.5f, 0.5f, 0.5f).dx, 0.0f);  // no field yet: zeros
  for (size_t order : {0, 1, 2, 3, 1, 3, 0, 2, 2}) {
    const FieldTape& t = tapes[order];
    GradientEvaluator fresh(t);
    scratch.reset(t);
    for (int n : {1, 3, 8, 13, 64}) {
      FieldGradient want[GradientEvaluator::kBatch], got[GradientEvaluator::kBatch];
      fresh.evaluate(x, y, z, n, want);
      scratch.evaluate(x, y, z, n, got);
      for (int i = 0; i < n; ++i)
        ASSERT_EQ(std::memcmp(&want[i], &got[i], sizeof(FieldGradient)), 0)
            << "tape " << order << ", n " << n << ", lane " << i;
    }
  }
}

}  // namespace
}  // namespace pf::field
