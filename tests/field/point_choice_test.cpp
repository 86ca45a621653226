// Point-dependent choices on field tapes (FieldOp::Less, LessEq, Select): what each evaluator
// computes -- the SIMD float and gradient forms against the scalar meaning (field_scalar.h),
// the interval form enclosing dense samples and deciding selects whose simplified tapes agree
// bit for bit, the gradient against central differences in double -- and the HyperFun front
// end's `if` on x, against the same branches written in C++ and by rendering against the
// double-precision reference hit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "compiler/field/field_scalar.h"
#include "compiler/field/hyperfun_reader.h"
#include "field/cast_comparison.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/interval_evaluator.h"

namespace pf::field {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// select(less(x, y), x * z, y - z) and select(lessEq(y, x), ...): operands from all three axes.
FieldTape choiceTape(FieldOp compare) {
  FieldTapeBuilder b;
  const uint32_t cond = b.binary(compare, b.x(), b.y());
  return b.finish(b.select(cond, b.binary(FieldOp::Mul, b.x(), b.z()), b.binary(FieldOp::Sub, b.y(), b.z())));
}

bool sameFloat(float a, float b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// Every value the SIMD loops can meet, on every instruction set this machine runs: the float
// form lane for lane equal to the scalar meaning, NaN and infinities included.
TEST(PointChoice, FloatFormIsTheScalarMeaningOnEveryTarget) {
  const float special[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 2.0f, kInf, -kInf, kNaN, 1e-38f, 3.0f};
  std::vector<float> xs, ys, zs;
  for (float x : special)
    for (float y : special) {
      xs.push_back(x);
      ys.push_back(y);
      zs.push_back(static_cast<float>(xs.size() % 5) - 2.0f);
    }
  for (const std::string& target : floatSlotsTargets()) {
    ASSERT_TRUE(useFloatSlotsTarget(target));
    SCOPED_TRACE(target);
    for (FieldOp compare : {FieldOp::Less, FieldOp::LessEq}) {
      const FieldTape t = choiceTape(compare);
      FloatEvaluator fe(t);
      GradientEvaluator ge(t);
      for (size_t start = 0; start < xs.size(); start += FloatEvaluator::kBatch) {
        const int n = static_cast<int>(std::min<size_t>(FloatEvaluator::kBatch, xs.size() - start));
        float out[FloatEvaluator::kBatch];
        FieldGradient grad[FloatEvaluator::kBatch];
        fe.evaluate(&xs[start], &ys[start], &zs[start], n, out);
        ge.evaluate(&xs[start], &ys[start], &zs[start], n, grad);
        for (int i = 0; i < n; ++i) {
          const float x = xs[start + i], y = ys[start + i], z = zs[start + i];
          const float cond = applyFieldOp(compare, x, y);
          EXPECT_EQ(cond, compare == FieldOp::Less ? (x < y ? 1.0f : 0.0f) : (x <= y ? 1.0f : 0.0f));
          const float want = applySelect(cond, x * z, y - z);
          EXPECT_TRUE(sameFloat(out[i], want)) << x << ", " << y << ", " << z << ": " << out[i] << " vs " << want;
          EXPECT_TRUE(sameFloat(grad[i].value, want)) << x << ", " << y << ", " << z;
          // The chosen side's derivatives: (z, 0, x) or (0, 1, -1) (at finite points: the chain
          // rule's inf * 0 is NaN elsewhere).
          if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) continue;
          EXPECT_TRUE(sameFloat(grad[i].dx, cond != 0.0f ? z : 0.0f));
          EXPECT_TRUE(sameFloat(grad[i].dy, cond != 0.0f ? 0.0f : 1.0f));
          EXPECT_TRUE(sameFloat(grad[i].dz, cond != 0.0f ? x : -1.0f));
        }
      }
    }
  }
  useFloatSlotsTarget("best");
}

// The unchosen side's NaN or inf never reaches the value: 1/x where x != 0, else 0.
TEST(PointChoice, TheUnchosenSideDoesNotLeak) {
  FieldTapeBuilder b;
  const uint32_t zero = b.constant(0.0f);
  const uint32_t nonzero = b.binary(FieldOp::Sub, b.constant(1.0f),
                                    b.binary(FieldOp::Min, b.binary(FieldOp::LessEq, b.x(), zero),
                                             b.binary(FieldOp::LessEq, zero, b.x())));
  const FieldTape t = b.finish(b.select(nonzero, b.binary(FieldOp::Div, b.constant(1.0f), b.x()), zero));
  FloatEvaluator fe(t);
  EXPECT_EQ(fe.evaluate(0.0f, 0.0f, 0.0f), 0.0f);
  EXPECT_EQ(fe.evaluate(-0.0f, 0.0f, 0.0f), 0.0f);
  EXPECT_EQ(fe.evaluate(0.25f, 0.0f, 0.0f), 4.0f);
  IntervalEvaluator ie(t);
  const Interval at_zero = ie.evaluate(Interval::point(0.0f), {0, 0}, {0, 0});
  EXPECT_EQ(at_zero.lo, 0.0f);
  EXPECT_EQ(at_zero.hi, 0.0f);
  // Over a box holding 0 the interval form cannot decide, so it allows both sides (1/x there
  // is the whole line): sound, not tight.
  EXPECT_TRUE(ie.evaluate({-1.0f, 1.0f}, {0, 0}, {0, 0}).isWhole());
}

// Over random boxes: the interval encloses dense float samples; where the condition is decided,
// the choice names the side, and the simplified tape gives the same floats bit for bit.
TEST(PointChoice, IntervalsEncloseSamplesAndDecideSelects) {
  FieldTapeBuilder b;
  // select(x^2 + y < 0.5, sqrt(z + 2) - x, select(y <= z, y * z, -x))
  const uint32_t c1 = b.binary(FieldOp::Less, b.binary(FieldOp::Add, b.unary(FieldOp::Square, b.x()), b.y()), b.constant(0.5f));
  const uint32_t c2 = b.binary(FieldOp::LessEq, b.y(), b.z());
  const uint32_t inner = b.select(c2, b.binary(FieldOp::Mul, b.y(), b.z()), b.unary(FieldOp::Neg, b.x()));
  const uint32_t near = b.binary(FieldOp::Sub, b.unary(FieldOp::Sqrt, b.binary(FieldOp::Add, b.z(), b.constant(2.0f))), b.x());
  const FieldTape t = b.finish(b.select(c1, near, inner));
  IntervalEvaluator ie(t);
  FloatEvaluator fe(t);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> centre(-2.0f, 2.0f), half(0.001f, 0.8f);
  int decided = 0, undecided = 0;
  std::vector<Choice> choices;
  for (int box = 0; box < 400; ++box) {
    Interval r[3];
    for (Interval& i : r) {
      const float c = centre(rng), h = half(rng);
      i = {c - h, c + h};
    }
    const Interval value = ie.evaluate(r[0], r[1], r[2], &choices);
    bool any = false;
    for (size_t i = 0; i < t.instrs.size(); ++i)
      if (t.instrs[i].op == FieldOp::Select && choices[i] != Choice::Both) any = true;
    (any ? decided : undecided) += 1;
    const FieldTape simpler = simplify(t, choices);
    FloatEvaluator fs(simpler);
    for (int k = 0; k < 64; ++k) {
      float p[3];
      for (int a = 0; a < 3; ++a) p[a] = r[a].lo + (r[a].hi - r[a].lo) * std::uniform_real_distribution<float>(0, 1)(rng);
      const float v = fe.evaluate(p[0], p[1], p[2]);
      ASSERT_TRUE(std::isnan(v) ? value.isWhole() : value.contains(v)) << v << " outside [" << value.lo << ", " << value.hi << "]";
      const float s = fs.evaluate(p[0], p[1], p[2]);
      ASSERT_TRUE(sameFloat(v, s)) << "simplified " << s << " vs " << v;
    }
  }
  EXPECT_GT(decided, 100);  // the test exercises both
  EXPECT_GT(undecided, 20);
}

// Away from the condition's boundary, the derived gradient is the chosen side's: against
// central differences of the tape in double.
TEST(PointChoice, GradientAgreesWithCentralDifferences) {
  FieldTapeBuilder b;
  const uint32_t cond = b.binary(FieldOp::Less, b.x(), b.constant(0.0f));
  const FieldTape t = b.finish(b.select(cond, b.binary(FieldOp::Mul, b.unary(FieldOp::Square, b.x()), b.y()),
                                        b.binary(FieldOp::Add, b.unary(FieldOp::Sin, b.y()), b.unary(FieldOp::Square, b.z()))));
  GradientEvaluator ge(t);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 500; ++k) {
    const double p[3] = {static_cast<float>(u(rng)), static_cast<float>(u(rng)), static_cast<float>(u(rng))};
    if (std::fabs(p[0]) < 1e-3) continue;
    const FieldGradient g = ge.evaluate(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    const double h = 1e-6;
    double want[3];
    for (int a = 0; a < 3; ++a) {
      double hi[3] = {p[0], p[1], p[2]}, lo[3] = {p[0], p[1], p[2]};
      hi[a] += h;
      lo[a] -= h;
      want[a] = (testing::evaluateDouble(t, hi[0], hi[1], hi[2]) - testing::evaluateDouble(t, lo[0], lo[1], lo[2])) / (2 * h);
    }
    EXPECT_NEAR(g.dx, want[0], 1e-4 * (1 + std::fabs(want[0])));
    EXPECT_NEAR(g.dy, want[1], 1e-4 * (1 + std::fabs(want[1])));
    EXPECT_NEAR(g.dz, want[2], 1e-4 * (1 + std::fabs(want[2])));
  }
}

// --- HyperFun's `if` on x -------------------------------------------------------------------------

FieldTape hyperFun(const std::string& body, std::string* errors = nullptr) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", "my_model(x[3], a[1]) {\n" + body + "\n}\n", log, {}, "my_model");
  if (errors) *errors = log.format();
  else EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

template <class Want>
void expectModel(const std::string& body, Want want, double tol = 1e-6) {
  SCOPED_TRACE(body);
  const FieldTape t = hyperFun(body);
  ASSERT_FALSE(t.instrs.empty());
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 1000; ++k) {
    const double x = static_cast<float>(u(rng)), y = static_cast<float>(u(rng)), z = static_cast<float>(u(rng));
    const double w = want(x, y, z);
    ASSERT_NEAR(testing::evaluateDouble(t, x, y, z), w, tol * (1 + std::fabs(w))) << "at " << x << ", " << y << ", " << z;
  }
}

TEST(PointChoice, HyperFunIfOnThePointRunsBothBranches) {
  expectModel("r = 1;\nif x[1] > 0 then r = 2; endif;\nmy_model = r;",
              [](double x, double, double) { return x > 0 ? 2.0 : 1.0; });
  // and / or / not, as HyperFun reads them (same precedence, left to right); = within EPS.
  expectModel("if x[1] > 0 and not (x[2] > 0.5) or x[3] <= -1 then t = x[1]*x[2]; else t = x[3]; endif;\nmy_model = t;",
              [](double x, double y, double z) { return ((x > 0 && !(y > 0.5)) || z <= -1) ? x * y : z; });
  // Nested, with a space mapping in one branch: the mapped array is chosen item by item.
  expectModel("array xt[3], c[3];\nc = [0, 0, 0];\nxt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3];\n"
              "if x[3] > 0 then\n  if x[1] < x[2] then d = hfShift3D(xt, 0, 0, 1); else d = hfScale3D(xt, 2, 2, 2); endif;\n"
              "endif;\nmy_model = hfSphere(xt, c, 1);",
              [](double x, double y, double z) {
                if (z > 0) {
                  if (x < y) z -= 1;
                  else x /= 2, y /= 2, z /= 2;
                }
                return 1 - x * x - y * y - z * z;
              });
  // A truth test of a plain number (|v| >= EPS) and = / /= within EPS.
  expectModel("if x[1]*x[2] then r = 1; else r = 0; endif;\nif x[3] /= x[3] + 0.0000001 then r = r + 10; endif;\nmy_model = r;",
              [](double x, double y, double) { return std::fabs(x * y) >= 1e-6 ? 1.0 : 0.0; });
  // The guard keeps the unchosen division out.
  const FieldTape guard = hyperFun("if x[1] = 0 then r = 0; else r = 1/x[1]; endif;\nmy_model = r;");
  EXPECT_EQ(testing::evaluateDouble(guard, 0.0, 0.0, 0.0), 0.0);
  EXPECT_EQ(testing::evaluateDouble(guard, 0.5, 0.0, 0.0), 2.0);
}

TEST(PointChoice, HyperFunValuesAssignedInOneBranchOnly) {
  std::string errors;
  hyperFun("if x[1] > 0 then t = 1; endif;\nmy_model = t;", &errors);
  EXPECT_NE(errors.find("m.hf:3:12: error: 't' is assigned in only one branch of the 'if' at line 2, whose condition "
                        "depends on the point x"),
            std::string::npos)
      << errors;
  // Assigned before the if, it keeps that value where the branch does not run.
  expectModel("t = 3;\nif x[1] > 0 then t = 1; endif;\nmy_model = t;", [](double x, double, double) { return x > 0 ? 1.0 : 3.0; });
  // A known condition still runs one branch only (its other branch may hold anything).
  expectModel("if 1 > 0 then t = x[2]; else t = q; endif;\nmy_model = t;", [](double, double y, double) { return y; });
}

// A surface that jumps where the condition changes: left of x = 0 a ball of radius 0.7, right
// of it one of radius 0.4, rendered by every method against the double reference.
TEST(PointChoice, RendersAgainstTheReference) {
  const FieldTape t = hyperFun("array c[3];\nc = [0, 0, 0];\n"
                               "if x[1] < 0 then r = hfSphere(x, c, 0.7); else r = hfSphere(x, c, 0.4); endif;\nmy_model = r;");
  const ImplicitField field("half balls", t);
  const FieldRays rays = orthoRays(32, 32, {-1, -1, -1}, {1, 1, 1});
  for (RootMethod m : {RootMethod::Auto, RootMethod::Interval, RootMethod::March}) {
    const Comparison c = compare(field, rays, 32, 32, m, m == RootMethod::March ? 64.0f : 0.0f, 2000);
    SCOPED_TRACE(static_cast<int>(m));
    EXPECT_EQ(c.coverage_mismatches, 0);
    EXPECT_LT(c.max_depth_error, 1e-5);
    if (m == RootMethod::Interval) {
      EXPECT_GT(c.counters.slabs_culled, 0u);
    }
  }
  // Where the condition is decided over a block, tape simplification drops the other ball.
  std::vector<Choice> choices;
  IntervalEvaluator ie(t);
  ie.evaluate({0.1f, 0.9f}, {-1.0f, 1.0f}, {-1.0f, 1.0f}, &choices);
  const FieldTape right = simplify(t, choices);
  EXPECT_LT(right.size(), t.size());
  for (const FieldInstr& in : right.instrs) EXPECT_NE(in.op, FieldOp::Select);
}

}  // namespace
}  // namespace pf::field
