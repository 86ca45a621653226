// The float form's SIMD loops (raster/field/slot_loops_simd.cpp) on every instruction set
// this machine offers: each operation over 64 lanes against the C library in double -- within
// Highway's documented ULP bounds for exp/log/sin/cos, exactly for the rest -- including the
// inputs outside Highway's valid ranges (NaN, inf, log of negatives, exp overflow, huge sines),
// which must keep C's meaning; and min/max ignoring NaN as the scalar definition does.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "compiler/field/field_scalar.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"

namespace pf::field {
namespace {

std::vector<float> inputs() {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> v = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 3.14159f, -2.5f, 1e-30f, 80.0f, 88.0f, 89.0f, 103.0f,
                          105.0f, 1e6f, -1e6f, 38999.0f, 39001.0f, -40000.0f, 1e30f, -1e30f, inf, -inf, nan, 7.25f};
  while (v.size() < FloatEvaluator::kBatch) v.push_back(std::ldexp(1.37f * static_cast<float>(v.size() % 7) - 4.0f, static_cast<int>(v.size() % 9) - 3));
  return v;
}

// Units in the last place between two floats (0 when equal or both NaN).
double ulps(float got, float want) {
  if (std::isnan(got) && std::isnan(want)) return 0;
  if (got == want) return 0;
  if (std::isinf(got) || std::isinf(want) || std::isnan(got) || std::isnan(want)) return 1e30;
  const float spacing = std::nextafter(std::fabs(want), std::numeric_limits<float>::infinity()) - std::fabs(want);
  return std::fabs(static_cast<double>(got) - want) / spacing;
}

void checkEveryOperation() {
  const std::vector<float> x = inputs();
  std::vector<float> y(x.rbegin(), x.rend());
  struct Case {
    FieldOp op;
    double max_ulps;
  };
  // Highway's bounds (hwy/contrib/math/math-inl.h): exp 1, log 4, sin and cos 3 ULP; the C
  // library's own results (the comparison) are within 1 ULP of the true value.
  const Case cases[] = {{FieldOp::Neg, 0}, {FieldOp::Abs, 0}, {FieldOp::Square, 0}, {FieldOp::Sqrt, 0},
                        {FieldOp::Exp, 2}, {FieldOp::Log, 5}, {FieldOp::Sin, 4}, {FieldOp::Cos, 4}, {FieldOp::Atan, 4},
                        {FieldOp::Floor, 0}, {FieldOp::NoisePerm, 0}, {FieldOp::NoiseGradX, 0},
                        {FieldOp::NoiseGradY, 0}, {FieldOp::NoiseGradZ, 0},
                        {FieldOp::Add, 0}, {FieldOp::Sub, 0}, {FieldOp::Mul, 0}, {FieldOp::Div, 0},
                        {FieldOp::Min, 0}, {FieldOp::Max, 0}};
  for (const Case& c : cases) {
    FieldTapeBuilder b;
    const uint32_t r = fieldOpArity(c.op) == 1 ? b.unary(c.op, b.x()) : b.binary(c.op, b.x(), b.y());
    FloatEvaluator e(b.finish(r));
    std::vector<float> out(x.size());
    e.evaluate(x.data(), y.data(), nullptr, static_cast<int>(x.size()), out.data());
    for (size_t i = 0; i < x.size(); ++i) {
      const float want = applyFieldOp(c.op, x[i], y[i]);
      EXPECT_LE(ulps(out[i], want), c.max_ulps)
          << fieldOpName(c.op) << "(" << x[i] << ", " << y[i] << "): " << out[i] << ", C says " << want;
    }
  }
}

// The gradient form's loops: d/dx of each operation applied to x (and y = 2x + 1 for binary
// ones, so both operands' derivatives count), against the derivative written here in double.
void checkEveryDerivative() {
  std::vector<float> x;
  for (int i = 0; i < FloatEvaluator::kBatch; ++i) x.push_back(0.3f + 0.11f * static_cast<float>(i));
  const FieldOp ops[] = {FieldOp::Neg, FieldOp::Abs, FieldOp::Square, FieldOp::Sqrt, FieldOp::Exp, FieldOp::Log,
                         FieldOp::Sin, FieldOp::Cos, FieldOp::Atan, FieldOp::Floor, FieldOp::NoisePerm,
                         FieldOp::NoiseGradY, FieldOp::Add, FieldOp::Sub, FieldOp::Mul, FieldOp::Div, FieldOp::Min,
                         FieldOp::Max};
  for (FieldOp op : ops) {
    FieldTapeBuilder b;
    const uint32_t y = b.binary(FieldOp::Add, b.binary(FieldOp::Mul, b.constant(2.0f), b.x()), b.constant(1.0f));
    const uint32_t r = fieldOpArity(op) == 1 ? b.unary(op, b.x()) : b.binary(op, b.x(), y);
    GradientEvaluator e(b.finish(r));
    std::vector<FieldGradient> g(x.size());
    const std::vector<float> zeros(x.size(), 0.0f);
    e.evaluate(x.data(), zeros.data(), zeros.data(), static_cast<int>(x.size()), g.data());
    for (size_t i = 0; i < x.size(); ++i) {
      const double a = x[i], yv = 2 * a + 1;
      double want = 0;
      switch (op) {
        case FieldOp::Neg: want = -1; break;
        case FieldOp::Abs: want = 1; break;
        case FieldOp::Square: want = 2 * a; break;
        case FieldOp::Sqrt: want = 0.5 / std::sqrt(a); break;
        case FieldOp::Exp: want = std::exp(a); break;
        case FieldOp::Log: want = 1 / a; break;
        case FieldOp::Sin: want = std::cos(a); break;
        case FieldOp::Cos: want = -std::sin(a); break;
        case FieldOp::Atan: want = 1 / (1 + a * a); break;
        case FieldOp::Floor: want = 0; break;  // a step: 0 off the integers (x is never one here)
        case FieldOp::NoisePerm: case FieldOp::NoiseGradY: want = 0; break;  // table steps, likewise
        case FieldOp::Add: want = 3; break;
        case FieldOp::Sub: want = -1; break;
        case FieldOp::Mul: want = yv + 2 * a; break;
        case FieldOp::Div: want = (yv - 2 * a) / (yv * yv); break;
        case FieldOp::Min: want = 1; break;  // x < 2x + 1 for x > -1
        case FieldOp::Max: want = 2; break;
        default: break;
      }
      EXPECT_NEAR(g[i].dx, want, 2e-6 * std::max(1.0, std::fabs(want))) << fieldOpName(op) << " at " << a;
      EXPECT_EQ(g[i].dy, 0.0f);
      EXPECT_EQ(e.evaluate(x[i], 0.0f, 0.0f).dx, g[i].dx) << "a batch of one differs from the batch";
    }
  }
}

TEST(FloatSimd, EveryTargetComputesEveryOperationAsC) {
  const std::vector<std::string> targets = floatSlotsTargets();
  ASSERT_FALSE(targets.empty());
  for (const std::string& t : targets) {
    SCOPED_TRACE(t);
    ASSERT_TRUE(useFloatSlotsTarget(t));
    EXPECT_EQ(std::string(floatSlotsTarget()), t);
    checkEveryOperation();
    checkEveryDerivative();
  }
  EXPECT_TRUE(useFloatSlotsTarget("best"));
  EXPECT_EQ(std::string(floatSlotsTarget()), targets.front());
  EXPECT_FALSE(useFloatSlotsTarget("no such target"));
  std::printf("float loops: %s (of", floatSlotsTarget());
  for (const std::string& t : targets) std::printf(" %s", t.c_str());
  std::printf(")\n");
}

}  // namespace
}  // namespace pf::field
