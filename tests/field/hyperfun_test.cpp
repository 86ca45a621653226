// The HyperFun front end: each operator and library function compiles to a tape whose value
// (evaluated in double) equals the formula written out here, independently, at many points;
// HyperFun's quirks (precedence, comments, numbers, case) behave as its C interpreter does;
// if/while resolve at compile time; what primflow cannot express is rejected with line:col.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "compiler/field/hyperfun_reader.h"
#include "compiler/sanitizers.h"
#include "field/field_reference.h"
#include "raster/field/float_evaluator.h"
#include "unit/on_stack.h"

namespace pf::field {
namespace {

using Fn = std::function<double(double, double, double)>;

FieldTape compileOk(const std::string& text, const std::vector<double>& params = {},
                    const std::string& object = "my_model") {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", text, log, params, object);
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

std::string compileError(const std::string& text, const std::vector<double>& params = {}) {
  DiagnosticLog log;
  auto tape = readHyperFunModel("m.hf", text, log, params);
  EXPECT_FALSE(tape) << text;
  return log.format();
}

// An object my_model(x[3], a[2]) with the given body lines (the body starts on line 2).
std::string model(const std::string& body) { return "my_model(x[3], a[2]) {\n" + body + "\n}\n"; }

void expectHas(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "expected to find: " << part << "\nin:\n" << text;
}

double at(const FieldTape& t, double x, double y, double z) { return testing::evaluateDouble(t, x, y, z); }

// The tape against `want` at random points of [lo, hi]^3 (float constants: a relative bound).
void expectField(const std::string& text, const Fn& want, const std::vector<double>& params = {}, double lo = -2.5,
                 double hi = 2.5, double tol = 2e-5) {
  SCOPED_TRACE(text);
  const FieldTape t = compileOk(text, params);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(lo, hi);
  int checked = 0;
  for (int k = 0; k < 300; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const double w = want(x, y, z);
    if (!std::isfinite(w)) continue;
    EXPECT_NEAR(at(t, x, y, z), w, tol * std::max(1.0, std::fabs(w))) << "at " << x << ", " << y << ", " << z;
    ++checked;
  }
  EXPECT_GT(checked, 250);
}

double sq(double v) { return v * v; }
double uni(double a, double b) { return a + b + std::sqrt(a * a + b * b); }
double inter(double a, double b) { return a + b - std::sqrt(a * a + b * b); }
double sphere(double x, double y, double z, double cx, double cy, double cz, double r) {
  return r * r - sq(x - cx) - sq(y - cy) - sq(z - cz);
}
double noiseG(double x, double y, double z, double amp, double freq, double phase) {
  const double sx = std::sin(freq * x), sy = std::sin(freq * y), sz = std::sin(freq * z);
  const double ex = amp * sx + amp / 1.17 * std::sin(freq * x / 1.35 + phase * sz);
  const double ey = amp * sy + amp / 1.17 * std::sin(freq * y / 1.35 + phase * sx);
  const double ez = amp * sz + amp / 1.17 * std::sin(freq * z / 1.35 + phase * sy);
  return ex * ey * ez;
}

// --- The real model ------------------------------------------------------------------------------

TEST(HyperFun, AddaExampleIsTheNoisyEllipsoid) {
  const std::string text = testing::readModelText("hyperfun/example.hf");
  ASSERT_FALSE(text.empty());
  const FieldTape t = compileOk(text);
  FloatEvaluator f(t);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int k = 0; k < 400; ++k) {
    const double x = u(rng), y = u(rng), z = u(rng);
    const double want = 1.0 - x * x - y * y - sq(z / 2.4) + noiseG(x, y, z, 0.5, 4.0, 1.4);
    EXPECT_NEAR(at(t, x, y, z), want, 1e-5 * std::max(1.0, std::fabs(want)));
    EXPECT_NEAR(f.evaluate(float(x), float(y), float(z)), want, 1e-4 * std::max(1.0, std::fabs(want)));
  }
  EXPECT_GT(at(t, 0, 0, 0), 0.0);    // the centre is inside
  EXPECT_LT(at(t, 0, 0, 3.5), 0.0);  // beyond the 2.4 half-axis (noise is at most (0.5*(1+1/1.17))^3)
}

// --- Operators and precedence ----------------------------------------------------------------

TEST(HyperFun, SetOperatorsAreTheAlphaZeroRFunctions) {
  const std::string two =
      "array c[3], d[3];\nc = [0.5, 0, 0];\nd = [-0.5, 0.25, 0];\n"
      "s1 = hfSphere(x, c, 1);\ns2 = hfSphere(x, d, 1.2);\n";
  auto f1 = [](double x, double y, double z) { return sphere(x, y, z, 0.5, 0, 0, 1); };
  auto f2 = [](double x, double y, double z) { return sphere(x, y, z, -0.5, 0.25, 0, 1.2); };
  expectField(model(two + "my_model = s1 | s2;"),
              [&](double x, double y, double z) { return uni(f1(x, y, z), f2(x, y, z)); });
  expectField(model(two + "my_model = s1 & s2;"),
              [&](double x, double y, double z) { return inter(f1(x, y, z), f2(x, y, z)); });
  expectField(model(two + "my_model = s1 @ s2;"),
              [&](double x, double y, double z) { return inter(f1(x, y, z), f2(x, y, z)); });
  expectField(model(two + "my_model = s1 \\ s2;"),
              [&](double x, double y, double z) { return inter(f1(x, y, z), -f2(x, y, z)); });
  expectField(model(two + "my_model = ~s1;"), [&](double x, double y, double z) { return -f1(x, y, z); });
}

TEST(HyperFun, PrecedenceFollowsTheCInterpreter) {
  // Set operators share the level of + and -: a | b + c = (a | b) + c.
  expectField(model("my_model = x[1] | x[2] + x[3];"), [](double x, double y, double z) { return uni(x, y) + z; });
  expectField(model("my_model = x[1] + x[2] & x[3];"), [](double x, double y, double z) { return inter(x + y, z); });
  expectField(model("my_model = x[1] * x[2] | x[3];"), [](double x, double y, double z) { return uni(x * y, z); });
  // A sign binds tighter than ^, and ^ is left-associative.
  EXPECT_NEAR(at(compileOk(model("my_model = -2^2;")), 0, 0, 0), 4.0, 0.0);
  EXPECT_NEAR(at(compileOk(model("my_model = 2^3^2;")), 0, 0, 0), 64.0, 0.0);
  expectField(model("my_model = -x[1]^2;"), [](double x, double, double) { return x * x; });
  expectField(model("my_model = 2*x[1]^3 - x[2]/x[3]/2;"),
              [](double x, double y, double z) { return 2 * x * x * x - y / z / 2; });
  // Parenthesised, the documented reading.
  expectField(model("my_model = x[1] | (x[2] + x[3]);"), [](double x, double y, double z) { return uni(x, y + z); });
}

TEST(HyperFun, MixingSetOperatorsWithPlusGetsANote) {
  DiagnosticLog log;
  ASSERT_TRUE(readHyperFunModel("m.hf", model("my_model = x[1] | x[2] + x[3];"), log));
  expectHas(log.format(), "m.hf:2:24: note: HyperFun gives the set operators");
  DiagnosticLog quiet;
  ASSERT_TRUE(readHyperFunModel("m.hf", model("my_model = (x[1] | x[2]) + x[3];"), quiet));
  EXPECT_TRUE(quiet.all().empty());
}

TEST(HyperFun, PowersMultiplyForWholeExponentsAndUseExpLogOtherwise) {
  expectField(model("my_model = x[1]^3;"), [](double x, double, double) { return x * x * x; });
  expectField(model("my_model = x[1]^(-2);"), [](double x, double, double) { return 1.0 / (x * x); });
  expectField(model("my_model = x[1]^2.0000004;"), [](double x, double, double) { return x * x; });  // within 1e-6
  expectField(model("my_model = x[1]^0;"), [](double, double, double) { return 1.0; });
  expectField(model("my_model = abs(x[1])^1.5;"), [](double x, double, double) { return std::pow(std::fabs(x), 1.5); });
  expectField(model("my_model = 2^x[1];"), [](double x, double, double) { return std::pow(2.0, x); });
  // A negative base with a non-integer exponent is NaN (HyperFun: a run-time error).
  const FieldTape t = compileOk(model("my_model = x[1]^1.5;"));
  EXPECT_TRUE(std::isnan(at(t, -1.0, 0, 0)));
}

TEST(HyperFun, BuiltInMaths) {
  expectField(model("my_model = sqrt(abs(x[1])) + exp(x[2]/2) - log(abs(x[3]) + 0.1);"),
              [](double x, double y, double z) {
                return std::sqrt(std::fabs(x)) + std::exp(y / 2) - std::log(std::fabs(z) + 0.1);
              });
  expectField(model("my_model = logd(abs(x[1]) + 0.5) * sin(x[2]) * cos(x[3]);"),
              [](double x, double y, double z) { return std::log10(std::fabs(x) + 0.5) * std::sin(y) * std::cos(z); });
  expectField(
      model("my_model = tan(x[1]/2) + sinh(x[2]) - cosh(x[3]/2);"),
      [](double x, double y, double z) { return std::tan(x / 2) + std::sinh(y) - std::cosh(z / 2); }, {}, -2.5, 2.5,
      1e-4);
  expectField(
      model("my_model = tanh(3*x[1]) + max(x[2], x[3]) - min(x[1], x[3]);"),
      [](double x, double y, double z) { return std::tanh(3 * x) + std::max(y, z) - std::min(x, z); }, {}, -2.5, 2.5,
      1e-4);
  // The functions without a tape operation fold when their arguments are known now.
  const FieldTape t = compileOk(
      model("v = asin(0.5) + acos(0.5) + atan(1) + atan2(1, 2) + mod(7.4, 3) + ceil(1.2) + floor(-1.2) + int(-1.7) "
            "+ frac(2.25) + sign(-3) + sign(0) + sign(2);\nmy_model = v;"));
  const double want = std::asin(0.5) + std::acos(0.5) + std::atan(1.0) + std::atan2(1.0, 2.0) + 1.0 + 2.0 - 2.0 - 1.0 +
                      0.25 - 1.0 + 1.0 + 1.0;
  EXPECT_NEAR(at(t, 0, 0, 0), want, 1e-6);
  EXPECT_EQ(t.size(), 1u);  // one constant
}

TEST(HyperFun, DivisionByZeroIsIeee) {
  const FieldTape t = compileOk(model("my_model = 1 / x[1];"));
  EXPECT_TRUE(std::isinf(at(t, 0.0, 1, 1)));
}

// --- Lexical rules -------------------------------------------------------------------------------

TEST(HyperFun, NamesAreCaseInsensitive) {
  expectField(
      "My_Model(X[3], A[1]) {\n ARRAY Ctr[3];\n CTR = [1, 0, 0];\n R = HFSPHERE(x, ctr, 2) | HfCylinderZ(X, cTr, "
      "0.5);\n"
      " MY_MODEL = r;\n}\n",
      [](double x, double y, double z) { return uni(sphere(x, y, z, 1, 0, 0, 2), 0.25 - sq(x - 1) - y * y); });
}

TEST(HyperFun, CommentsRunFromDoubleMinusToTheEndOfTheLine) {
  expectField(model("-- a comment line\nv = x[1]--x[2] is commented out, so v = x[1]\n;\nmy_model = v; -- trailing"),
              [](double x, double, double) { return x; });
  expectField(model("v = x[1]- -x[2];\nmy_model = v;"), [](double x, double y, double) { return x + y; });
}

TEST(HyperFun, NumberSyntaxAndItsQuirks) {
  EXPECT_NEAR(at(compileOk(model("my_model = 1. + .5 + 2.5e1 + 3E-1 + 0.25 + 4e+2;")), 0, 0, 0), 427.05, 1e-4);
  expectHas(compileError(model("my_model = 05;")),
            "m.hf:2:12: error: '05' is not a HyperFun number: a number with more than one digit before the point may "
            "not start with 0");
  expectHas(compileError(model("my_model = 1e05;")),
            "m.hf:2:12: error: '1e05' is not a HyperFun number: an exponent may not start with 0");
  expectHas(compileError(model("my_model = 2e;")), "m.hf:2:12: error: '2e' is not a HyperFun number");
  expectHas(compileError(model("my_model = 1 $ 2;")), "m.hf:2:14: error: unexpected character '$'");
}

// --- Statements ------------------------------------------------------------------------------

TEST(HyperFun, WholeArrayLiteralsNeedExactlyOneSignedNumberPerItem) {
  expectField(model("array c[3];\nc = [-1, +0.5, 2];\nmy_model = hfSphere(x, c, 1);"),
              [](double x, double y, double z) { return sphere(x, y, z, -1, 0.5, 2, 1); });
  expectHas(compileError(model("array c[3];\nc = [1, 2];\nmy_model = 1;")),
            "m.hf:3:5: error: array 'c' has 3 items, but the list gives 2");
  expectHas(compileError(model("array c[3];\nc = [1, 2, 3, 4];\nmy_model = 1;")),
            "m.hf:3:5: error: array 'c' has 3 items, but the list gives 4");
  expectHas(compileError(model("array c[3];\nr = 1;\nc = [0, r, 2];\nmy_model = 1;")),
            "m.hf:4:9: error: a whole-array assignment lists signed numbers only");
}

TEST(HyperFun, IfAndWhileResolveWhenTheModelCompiles) {
  const std::string body =
      "array c[3];\nc = [0, 0, 0];\nif a[1] > 0 and not (a[2] = 1) then\n  r = 2;\nelse\n  if a[2] /= 1 then r = 3; "
      "else r = 1; endif;\nendif;\nmy_model = hfSphere(x, c, r);";
  auto ball = [](double r) { return [r](double x, double y, double z) { return sphere(x, y, z, 0, 0, 0, r); }; };
  expectField(model(body), ball(2), {1, 0});
  expectField(model(body), ball(1), {0, 1});
  expectField(model(body), ball(3), {0, 0});
  expectField(model(body), ball(1), {1, 1.0000005});  // = compares within 1e-6
  // A loop unrolled: the union of three spheres along x.
  expectField(model("array c[3];\nc = [0, 0, 0];\nf = -100; i = 1;\nwhile i <= 3 loop\n  c[1] = 2*(i - 2);\n"
                    "  f = f | hfSphere(x, c, 0.75);\n  i = i + 1;\nendloop;\nmy_model = f;"),
              [](double x, double y, double z) {
                double f = -100;
                for (int i = 1; i <= 3; ++i) f = uni(f, sphere(x, y, z, 2.0 * (i - 2), 0, 0, 0.75));
                return f;
              });
  // Missing parameters are 0; too many is an error.
  expectField(model("my_model = a[1] + a[2] + x[1];"), [](double x, double, double) { return 5 + x; }, {5});
  expectHas(compileError(model("my_model = 1;"), {1, 2, 3}),
            "m.hf:1:16: error: 3 parameters given, but 'my_model' has a[2]");
}

// (An `if` on x compiles to the tape's Select: tests/field/point_choice_test.cpp.)
TEST(HyperFun, APointDependentLoopIsRejectedAtTheCondition) {
  expectHas(compileError(model("r = x[2];\nwhile r < 3 loop r = r + 1; endloop;\nmy_model = r;")),
            "m.hf:3:7: error: condition depends on the point x: a 'while'");
  expectHas(compileError(model("i = 0;\nwhile i < 1 loop i = i * 2; endloop;\nmy_model = i;")),
            "m.hf:3:1: error: loop does not end within 100000 iterations");
  expectHas(compileError(model("if (a[1]+1)*2 > 1 then r = 1; endif;\nmy_model = 1;")),
            "m.hf:2:12: error: in a condition, HyperFun reads a '(' that starts an operand as a boolean group");
}

TEST(HyperFun, StatementErrorsArePrecise) {
  expectHas(compileError(model("my_model = r;")), "m.hf:2:12: error: 'r' is not defined");
  expectHas(compileError(model("if a[1] > 0 then r = 1; endif;\nmy_model = r;")),
            "m.hf:3:12: error: 'r' is used before it is assigned");
  expectHas(compileError(model("array c[2];\nc[1] = 1;\nmy_model = c[2];")),
            "m.hf:4:12: error: 'c[2]' is used before it is assigned");
  expectHas(compileError(model("array c[2];\nc = [1, 2];\nmy_model = c[3];")),
            "m.hf:4:14: error: index 3 is out of range for 'c' (1 to 2)");
  expectHas(compileError(model("array c[2];\nc = [1, 2];\nmy_model = c[x[1]];")),
            "m.hf:4:14: error: the index of 'c' depends on the point x");
  expectHas(compileError(model("x[1] = 2;\nmy_model = 1;")), "m.hf:2:1: error: 'x' cannot be assigned");
  expectHas(compileError(model("r = 1;\narray c[2];\nmy_model = 1;")),
            "m.hf:3:1: error: array declarations must come before the statements");
  expectHas(compileError(model("if a[1] = 0 then my_model = 1; endif;\nmy_model = 2;")),
            "m.hf:2:18: error: 'my_model' can only be assigned by the object's last statement");
  expectHas(compileError(model("max = 2;\nmy_model = 1;")),
            "m.hf:2:1: error: 'max' is a library function's name and cannot be assigned");
}

// --- Objects -------------------------------------------------------------------------------------

const char* kTwoObjects =
    "ball(x[3], a[1]) {\n array c[3];\n c = [0, 0, 0];\n ball = hfSphere(x, c, a[1]);\n}\n"
    "my_model(x[3], a[1]) {\n array xt[3], r[1], big[4];\n xt[1] = x[1] - 1; xt[2] = x[2]; xt[3] = x[3];\n"
    " r = [1.5];\n my_model = ball(xt, r) | ball(x, a);\n}\n";

TEST(HyperFun, ObjectsCallEarlierObjectsWithArraysOfTheirSizes) {
  expectField(
      kTwoObjects,
      [](double x, double y, double z) { return uni(sphere(x, y, z, 1, 0, 0, 1.5), sphere(x, y, z, 0, 0, 0, 0.5)); },
      {0.5});
  // The object drawn: `object` when present, else the first.
  DiagnosticLog log;
  auto ball = readHyperFunModel("m.hf", kTwoObjects, log, {2}, "BALL");
  ASSERT_TRUE(ball) << log.format();
  EXPECT_NEAR(at(*ball, 1, 0, 0), 3.0, 1e-6);
  auto first = readHyperFunModel("m.hf", kTwoObjects, log, {2}, "no_such_object");
  ASSERT_TRUE(first) << log.format();
  EXPECT_NEAR(at(*first, 1, 0, 0), 3.0, 1e-6);
}

TEST(HyperFun, ObjectCallErrors) {
  std::string text = kTwoObjects;
  text.replace(text.find("ball(x, a)"), 10, "ball(x, big)");
  expectHas(compileError(text), "m.hf:10:35: error: object 'ball' takes a[1], but 'big' has 4 items");
  expectHas(compileError("first(x[3], a[1]) { first = later(x, a); }\nlater(x[3], a[1]) { later = 1; }\n"),
            "m.hf:1:29: error: object 'later' is defined after 'first'");
  expectHas(compileError(model("my_model = nothing(x, a);")), "m.hf:2:12: error: unknown function 'nothing'");
  expectHas(compileError("b(x[3], a[1]) { b = 1; }\nb(x[3], a[1]) { b = 2; }\n"),
            "m.hf:2:1: error: object 'b' is already defined on line 1");
}

// --- The library ---------------------------------------------------------------------------------

// A model with c = (0.3, -0.2, 0.1) and the given final expression.
std::string withCentre(const std::string& value) {
  return model("array c[3];\nc = [0.3, -0.2, 0.1];\nmy_model = " + value + ";");
}
const double cx = 0.3, cy = -0.2, cz = 0.1;

TEST(HyperFun, QuadricPrimitives) {
  expectField(withCentre("hfEllipsoid(x, c, 1, 2, 0.5)"), [](double x, double y, double z) {
    return 1 - sq((x - cx) / 1) - sq((y - cy) / 2) - sq((z - cz) / 0.5);
  });
  expectField(withCentre("hfCylinderX(x, c, 0.7)"),
              [](double, double y, double z) { return 0.49 - sq(y - cy) - sq(z - cz); });
  expectField(withCentre("hfCylinderY(x, c, 0.7)"),
              [](double x, double, double z) { return 0.49 - sq(x - cx) - sq(z - cz); });
  expectField(withCentre("hfCylinderZ(x, c, 0.7)"),
              [](double x, double y, double) { return 0.49 - sq(x - cx) - sq(y - cy); });
  expectField(withCentre("hfEllCylX(x, c, 0.5, 2)"),
              [](double, double y, double z) { return 1 - sq((y - cy) / 0.5) - sq((z - cz) / 2); });
  expectField(withCentre("hfEllCylY(x, c, 0.5, 2)"),
              [](double x, double, double z) { return 1 - sq((x - cx) / 0.5) - sq((z - cz) / 2); });
  expectField(withCentre("hfEllCylZ(x, c, 0.5, 2)"),
              [](double x, double y, double) { return 1 - sq((x - cx) / 0.5) - sq((y - cy) / 2); });
  expectField(withCentre("hfConeX(x, c, 0.5)"),
              [](double x, double y, double z) { return sq(x - cx) - sq((y - cy) / 0.5) - sq((z - cz) / 0.5); });
  expectField(withCentre("hfConeY(x, c, 0.5)"),
              [](double x, double y, double z) { return sq(y - cy) - sq((x - cx) / 0.5) - sq((z - cz) / 0.5); });
  expectField(withCentre("hfConeZ(x, c, 0.5)"),
              [](double x, double y, double z) { return sq(z - cz) - sq((x - cx) / 0.5) - sq((y - cy) / 0.5); });
  expectField(withCentre("hfEllConeX(x, c, 0.5, 3)"),
              [](double x, double y, double z) { return sq(x - cx) - sq((y - cy) / 0.5) - sq((z - cz) / 3); });
  expectField(withCentre("hfEllConeY(x, c, 0.5, 3)"),
              [](double x, double y, double z) { return sq(y - cy) - sq((x - cx) / 0.5) - sq((z - cz) / 3); });
  expectField(withCentre("hfEllConeZ(x, c, 0.5, 3)"),
              [](double x, double y, double z) { return sq(z - cz) - sq((x - cx) / 0.5) - sq((y - cy) / 3); });
}

TEST(HyperFun, ToriAndBlocks) {
  auto torus = [](double along, double u, double v, double R, double r0) {
    return r0 * r0 - (along * along + u * u + v * v) - R * R + 2 * R * std::sqrt(u * u + v * v);
  };
  expectField(withCentre("hfTorusX(x, c, 1.5, 0.5)"),
              [&](double x, double y, double z) { return torus(x - cx, y - cy, z - cz, 1.5, 0.5); });
  expectField(withCentre("hfTorusY(x, c, 1.5, 0.5)"),
              [&](double x, double y, double z) { return torus(y - cy, x - cx, z - cz, 1.5, 0.5); });
  expectField(withCentre("hfTorusZ(x, c, 1.5, 0.5)"),
              [&](double x, double y, double z) { return torus(z - cz, x - cx, y - cy, 1.5, 0.5); });
  expectField(withCentre("hfBlock(x, c, 1, 2, 0.5)"), [](double x, double y, double z) {
    const double sx = (x - cx) * (cx + 1 - x), sy = (y - cy) * (cy + 2 - y), sz = (z - cz) * (cz + 0.5 - z);
    return inter(inter(sx, sy), sz);
  });
  expectHas(compileError(withCentre("hfBlock(x, c, 1, -2, 0.5)")),
            "m.hf:4:29: error: 'dy' (argument 4 of 'hfBlock') is negative");
}

TEST(HyperFun, SuperEllipsoid) {
  auto superell = [](double x, double y, double z, double a, double b, double c, double s1, double s2) {
    const double X = (x - cx) / a, Y = (y - cy) / b, Z = (z - cz) / c;
    return 1 - std::pow(std::pow(std::fabs(X), 2 / s2) + std::pow(std::fabs(Y), 2 / s2), s2 / s1) -
           std::pow(std::fabs(Z), 2 / s1);
  };
  expectField(
      withCentre("hfSuperEll(x, c, 1, 1.5, 0.8, 0.3, 0.6)"),
      [&](double x, double y, double z) { return superell(x, y, z, 1, 1.5, 0.8, 0.3, 0.6); }, {}, -1.5, 1.5, 1e-4);
  expectField(withCentre("hfSuperEll(x, c, 1, 1.5, 0.8, 1, 2)"),
              [&](double x, double y, double z) { return superell(x, y, z, 1, 1.5, 0.8, 1, 2); });
  // The value at the centre, where |X|^p takes log(0).
  EXPECT_NEAR(at(compileOk(withCentre("hfSuperEll(x, c, 1, 1, 1, 0.5, 0.5)")), cx, cy, cz), 1.0, 1e-6);
}

TEST(HyperFun, BlobbyMetaballsAndSoftObjects) {
  const std::string centres =
      "array x0[2], y0[2], z0[2], p[2], q[2];\nx0 = [-0.5, 0.7];\ny0 = [0, 0.2];\nz0 = [0.1, -0.3];\n";
  const double X0[2] = {-0.5, 0.7}, Y0[2] = {0, 0.2}, Z0[2] = {0.1, -0.3};
  auto r2 = [&](int i, double x, double y, double z) { return sq(x - X0[i]) + sq(y - Y0[i]) + sq(z - Z0[i]); };
  expectField(model(centres + "p = [2, 3];\nq = [1, 0.5];\nmy_model = hfBlobby(x, x0, y0, z0, p, q, 0.3);"),
              [&](double x, double y, double z) {
                return std::exp(-2 * r2(0, x, y, z)) + 0.5 * std::exp(-3 * r2(1, x, y, z)) - 0.3;
              });
  // Nishimura's piecewise kernel, against the tape's min/max form; the second ball has d < 0
  // and is skipped, as HyperFun does.
  auto metaball = [](double r, double b, double d) {
    if (r <= d / 3) return b * (1 - 3 * sq(r / d));
    if (r < d) return 1.5 * b * sq(1 - r / d);
    return 0.0;
  };
  expectField(
      model(centres + "p = [1.2, 0.8];\nq = [2, 1.5];\nmy_model = hfMetaball(x, x0, y0, z0, p, q, 0.25);"),
      [&](double x, double y, double z) {
        return metaball(std::sqrt(r2(0, x, y, z)), 1.2, 2) + metaball(std::sqrt(r2(1, x, y, z)), 0.8, 1.5) - 0.25;
      },
      {}, -2, 2);
  expectField(
      model(centres + "p = [1.2, 0.8];\nq = [2, -1.5];\nmy_model = hfMetaball(x, x0, y0, z0, p, q, 0.25);"),
      [&](double x, double y, double z) { return metaball(std::sqrt(r2(0, x, y, z)), 1.2, 2) - 0.25; }, {}, -2, 2);
  auto soft = [](double rr, double d) {
    if (std::sqrt(rr) > d) return 0.0;
    const double d2 = d * d;
    return 1 - 22 * rr / (9 * d2) + 17 * rr * rr / (9 * d2 * d2) - 4 * rr * rr * rr / (9 * d2 * d2 * d2);
  };
  expectField(
      model(centres + "q = [2, 1.5];\nmy_model = hfSoft(x, x0, y0, z0, q, 0.2);"),
      [&](double x, double y, double z) { return soft(r2(0, x, y, z), 2) + soft(r2(1, x, y, z), 1.5) - 0.2; }, {}, -2,
      2);
  expectHas(compileError(model(centres + "q = [2, 1.5];\nq[2] = x[1];\nmy_model = hfSoft(x, x0, y0, z0, q, 0.2);")),
            "m.hf:8:34: error: item 2 of 'd' (argument 5 of 'hfSoft') depends on the point x");
}

TEST(HyperFun, ConvolutionPointsAndNoise) {
  expectField(model("array v[6], w[2];\nv = [0, 0, 0, 1, 1, 0];\nw = [1, 2];\nmy_model = hfConvPoint(x, v, w, 0.1);"),
              [](double x, double y, double z) {
                return 1 / sq(1 + 1 * (x * x + y * y + z * z)) + 1 / sq(1 + 4 * (sq(x - 1) + sq(y - 1) + z * z)) - 0.1;
              });
  expectField(model("my_model = hfNoiseG(x, 2.5, 0.7, 1.4);"),
              [](double x, double y, double z) { return noiseG(x, y, z, 2.5, 0.7, 1.4); });
  expectHas(compileError(
                model("array v[5], w[2];\nv = [0, 0, 0, 1, 1];\nw = [1, 2];\nmy_model = hfConvPoint(x, v, w, 0.1);")),
            "m.hf:5:27: error: 'vect' (argument 2 of 'hfConvPoint') must be an array of 6 items; 'v' has 5");
}

// hfConvLine and hfConvCurve: the Cauchy kernel integrated along segments, against Simpson's
// rule in double (4000 intervals per segment) -- not against the closed form the library uses.
double cauchyAlong(double x, double y, double z, const double b[3], const double e[3], double s) {
  const int n = 4000;
  double sum = 0;
  const double len = std::sqrt(sq(e[0] - b[0]) + sq(e[1] - b[1]) + sq(e[2] - b[2]));
  for (int i = 0; i <= n; ++i) {
    const double t = double(i) / n;
    const double r2 = sq(x - (b[0] + t * (e[0] - b[0]))) + sq(y - (b[1] + t * (e[1] - b[1]))) + sq(z - (b[2] + t * (e[2] - b[2])));
    const double w = i == 0 || i == n ? 1 : i % 2 ? 4 : 2;
    sum += w / sq(1 + s * s * r2);
  }
  return sum * len / (3.0 * n);
}

TEST(HyperFun, ConvolutionLinesAndCurves) {
  const double b0[3] = {-1, 0, 0}, e0[3] = {1, 0.5, 0}, b1[3] = {0, -1, 0.5}, e1[3] = {0, 1, -0.5};
  expectField(model("array b[6], e[6], w[2];\nb = [-1, 0, 0, 0, -1, 0.5];\ne = [1, 0.5, 0, 0, 1, -0.5];\n"
                    "w = [1.5, 0.8];\nmy_model = hfConvLine(x, b, e, w, 0.3);"),
              [&](double x, double y, double z) {
                return cauchyAlong(x, y, z, b0, e0, 1.5) + cauchyAlong(x, y, z, b1, e1, 0.8) - 0.3;
              },
              {}, -2.5, 2.5, 1e-5);
  // A curve through three points: two segments, one S each.
  const double p0[3] = {-1, -1, 0}, p1[3] = {0, 1, 0.3}, p2[3] = {1.2, -0.5, -0.2};
  expectField(model("array v[9], w[2];\nv = [-1, -1, 0, 0, 1, 0.3, 1.2, -0.5, -0.2];\nw = [2, 1];\n"
                    "my_model = hfConvCurve(x, v, w, 0.2);"),
              [&](double x, double y, double z) {
                return cauchyAlong(x, y, z, p0, p1, 2) + cauchyAlong(x, y, z, p1, p2, 1) - 0.2;
              },
              {}, -2.5, 2.5, 1e-5);
  // A segment of length 0 adds nothing.
  expectField(model("array b[3], e[3], w[1];\nb = [0.5, 0.5, 0.5];\ne = [0.5, 0.5, 0.5];\nw = [2];\n"
                    "my_model = hfConvLine(x, b, e, w, 0.25);"),
              [](double, double, double) { return -0.25; });
  expectHas(compileError(model("array v[8], w[2];\nv = [0, 0, 0, 1, 1, 1, 2, 2];\nw = [1, 1];\n"
                               "my_model = hfConvCurve(x, v, w, 0.2);")),
            "'vect' (argument 2 of 'hfConvCurve') must be an array of 9 items; 'v' has 8");
}

TEST(HyperFun, Blends) {
  auto blend = [](double set, double f1, double f2, double a0, double a1, double a2) {
    return set + a0 / (1 + sq(f1 / a1) + sq(f2 / a2));
  };
  expectField(model("my_model = hfBlendUni(x[1], x[2], 0.5, 1, 2);"),
              [&](double x, double y, double) { return blend(uni(x, y), x, y, 0.5, 1, 2); });
  expectField(model("my_model = hfBlendInt(x[1], x[2], -0.5, 1, 2);"),
              [&](double x, double y, double) { return blend(inter(x, y), x, y, -0.5, 1, 2); });
}

// The value of x after a mapping, read back as a weighted sum so that one field shows all three.
const char* kReadBack = "my_model = xt[1] + 10*xt[2] + 100*xt[3];";
double readBack(double x, double y, double z) { return x + 10 * y + 100 * z; }
std::string mapped(const std::string& call) {
  return model("array xt[3], v[3];\nxt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3];\nv = [0.5, -1, 2];\nd = " + call + ";\n" +
               kReadBack);
}

TEST(HyperFun, AffineSpaceMappings) {
  expectField(mapped("hfShift3D(xt, 1, 2, 3)"),
              [](double x, double y, double z) { return readBack(x - 1, y - 2, z - 3); });
  expectField(mapped("hfScale3D(xt, 2, 4, 0.5)"),
              [](double x, double y, double z) { return readBack(x / 2, y / 4, z / 0.5); });
  expectField(mapped("hfStretch3D(xt, v, 2, 4, 0.5)"), [](double x, double y, double z) {
    return readBack(0.5 + (x - 0.5) / 2, -1 + (y + 1) / 4, 2 + (z - 2) / 0.5);
  });
  const double t = 0.7, c = std::cos(t), s = std::sin(t);
  expectField(mapped("hfRotate3DX(xt, 0.7)"),
              [&](double x, double y, double z) { return readBack(x, y * c + z * s, -y * s + z * c); });
  expectField(mapped("hfRotate3DY(xt, 0.7)"),
              [&](double x, double y, double z) { return readBack(-z * s + x * c, y, z * c + x * s); });
  expectField(mapped("hfRotate3DZ(xt, 0.7)"),
              [&](double x, double y, double z) { return readBack(x * c + y * s, -x * s + y * c, z); });
  // A mapping applied to x itself changes every later use of x (HyperFun's aliasing).
  expectField(model("d = hfShift3D(x, 1, 0, 0);\nmy_model = x[1];"), [](double x, double, double) { return x - 1; });
}

TEST(HyperFun, TwistsAndTapers) {
  auto angle = [](double p) {
    const double t = (p - (-1)) / (2 - (-1));
    return (1 - t) * 0.2 + t * 1.1;
  };
  expectField(mapped("hfTwistZ(xt, -1, 2, 0.2, 1.1)"), [&](double x, double y, double z) {
    const double a = angle(z), c = std::cos(a), s = std::sin(a);
    return readBack(x * c + y * s, -x * s + y * c, z);
  });
  expectField(mapped("hfTwistX(xt, -1, 2, 0.2, 1.1)"), [&](double x, double y, double z) {
    const double a = angle(x), c = std::cos(a), s = std::sin(a);
    return readBack(x, y * c + z * s, -y * s + z * c);
  });
  expectField(mapped("hfTwistY(xt, -1, 2, 0.2, 1.1)"), [&](double x, double y, double z) {
    const double a = angle(y), c = std::cos(a), s = std::sin(a);
    return readBack(-z * s + x * c, y, z * c + x * s);
  });
  // HyperFun's piecewise scale: s1 below, s2 above, linear between.
  auto scale = [](double p) {
    if (p < -1) return 0.5;
    if (p > 2) return 2.0;
    const double t = (p + 1) / 3;
    return (1 - t) * 0.5 + t * 2.0;
  };
  expectField(mapped("hfTaperZ(xt, -1, 2, 0.5, 2)"),
              [&](double x, double y, double z) { return readBack(x / scale(z), y / scale(z), z); });
  expectField(mapped("hfTaperX(xt, -1, 2, 0.5, 2)"),
              [&](double x, double y, double z) { return readBack(x, y / scale(x), z / scale(x)); });
  expectField(mapped("hfTaperY(xt, -1, 2, 0.5, 2)"),
              [&](double x, double y, double z) { return readBack(x / scale(y), y, z / scale(y)); });
  expectHas(compileError(mapped("hfTaperZ(xt, 2, -1, 0.5, 2)")),
            "m.hf:5:21: error: 'z2' (argument 3 of 'hfTaperZ') must be greater than 'z1'");
  expectHas(compileError(mapped("hfTaperZ(xt, -1, 2, -0.5, 2)")), "m.hf:5:25: error: the scales must have one sign");
  expectHas(compileError(mapped("hfTaperZ(xt, x[1], 2, 0.5, 2)")),
            "m.hf:5:18: error: 'z1' (argument 2 of 'hfTaperZ') depends on the point x");
}

TEST(HyperFun, ControlPointSpaceMappings) {
  const std::string body =
      "array xt[3], src[6], dst[6], b[6];\nxt[1] = x[1]; xt[2] = x[2]; xt[3] = x[3];\n"
      "src = [0, 0, 0, 1, 1, 1];\ndst = [0.5, 0, 0, 1, 1.5, 1];\nb = [1, 1, 1, 0.5, 0.8, 1.2];\n";
  const double S[6] = {0, 0, 0, 1, 1, 1}, T[6] = {0.5, 0, 0, 1, 1.5, 1}, B[6] = {1, 1, 1, 0.5, 0.8, 1.2};
  auto apply = [&](double p[3], bool cubic) {
    for (int i = 0; i < 6; i += 3) {
      double d[3], s = 0;
      for (int k = 0; k < 3; ++k) {
        d[k] = T[i + k] - S[i + k];
        s += sq((p[k] - T[i + k]) / (B[i + k] * (1 + std::fabs(d[k]))));
      }
      double w = std::exp(-s);
      if (cubic) {
        const double rho = std::sqrt(s);
        w = rho <= 1 ? std::pow(1 - rho, 3) / (1 + rho) : 0.0;
      }
      for (int k = 0; k < 3; ++k) p[k] -= w * d[k];
    }
    return readBack(p[0], p[1], p[2]);
  };
  expectField(model(body + "d = hfSpaceMapExp(xt, src, dst, b);\n" + kReadBack), [&](double x, double y, double z) {
    double p[3] = {x, y, z};
    return apply(p, false);
  });
  expectField(model(body + "d = hfSpaceMapCubic(xt, src, dst, b);\n" + kReadBack), [&](double x, double y, double z) {
    double p[3] = {x, y, z};
    return apply(p, true);
  });
}

TEST(HyperFun, LibraryCallErrorsArePrecise) {
  expectHas(compileError(withCentre("hfSphere(x, c)")),
            "m.hf:4:12: error: 'hfSphere' takes 3 arguments (x, center, R), found 2");
  expectHas(compileError(withCentre("hfSphere(x, 1, 2)")),
            "m.hf:4:24: error: argument 2 of 'hfSphere' must be the name of an array");
  expectHas(compileError(withCentre("hfSphere(x, c, c)")), "m.hf:4:27: error: 'c' is an array");
  expectHas(compileError(model("array c[2];\nc = [1, 2];\nmy_model = hfSphere(x, c, 1);")),
            "m.hf:4:24: error: 'center' (argument 2 of 'hfSphere') must be an array of 3 items; 'c' has 2");
  expectHas(compileError(model("array c[3];\nc[1] = 1;\nmy_model = hfSphere(x, c, 1);")),
            "m.hf:4:24: error: 'c[2]' is not assigned");
  // atan and what is built from it work on the point (the tape has atan).
  expectField(model("my_model = atan2(x[2], x[1]) + atan(x[3]) - asin(x[1] * 0.3) + acos(x[2] * 0.3);"),
              [](double x, double y, double z) {
                return std::atan2(y, x) + std::atan(z) - std::asin(x * 0.3) + std::acos(y * 0.3);
              });
  // mod: fmod of HyperFun's rounded arguments (ceil - 1 where that is more than 0.5 below).
  auto hfRound = [](double v) { return std::ceil(v) - v > 0.5 ? std::ceil(v) - 1 : std::ceil(v); };
  expectField(model("my_model = mod(3*x[1], 2*x[2] + 7) + mod(x[3]*4, -3);"),
              [&](double x, double y, double z) {
                auto half = [](double v) { return std::fabs(v - std::floor(v) - 0.5) < 1e-6; };
                if (half(3 * x) || half(2 * y + 7) || half(4 * z)) return std::nan("");  // skipped
                return std::fmod(hfRound(3 * x), hfRound(2 * y + 7)) + std::fmod(hfRound(4 * z), -3.0);
              });
  // floor, ceil, int and frac work on the point (the tape has floor); int truncates towards 0.
  expectField(model("my_model = floor(x[1]) + 2*ceil(x[2]) + 4*int(x[3]) + 8*frac(x[1] - x[3]);"),
              [](double x, double y, double z) {
                return std::floor(x) + 2 * std::ceil(y) + 4 * std::trunc(z) + 8 * ((x - z) - std::trunc(x - z));
              });
  expectHas(compileError(model("array e[3];\ne = [0, 0, 0];\nmy_model = hfDEllipsoid(x, e, 1, 0, 1);")),
            "m.hf:4:34: error: 'b' (argument 4 of 'hfDEllipsoid') is within 1e-6 of 0");
  expectHas(compileError(model("my_model = hfDUni(x[1], x[2], 1);")),
            "m.hf:2:12: error: 'hfDUni' takes 4 arguments (f1, f2, r, alpha), found 3");
  expectHas(compileError(model("my_model = hfNoSuchThing(x, a);")),
            "m.hf:2:12: error: unknown function 'hfnosuchthing'");
}

TEST(HyperFun, AttributeArraysAreAcceptedAndIgnored) {
  expectField("my_model(x[3], a[1], s[2]) {\n s = [0.5, 1];\n s[2] = x[1];\n my_model = x[2] + s[1];\n}\n",
              [](double, double y, double) { return y + 0.5; });
}

TEST(HyperFun, ElseIfChainsExtraCoordinatesAndCrLf) {
  const std::string chain =
      "if a[1] < 1 then\r\n r = 1;\r\nelse\r\n if a[1] < 2 then r = 2; else r = 3; endif;\r\nendif;\r\nmy_model = r + "
      "x[1];";
  expectField(model(chain), [](double x, double, double) { return 2 + x; }, {1.5});
  expectField(model(chain), [](double x, double, double) { return 3 + x; }, {7});
  // x[4] and beyond (time, say) are fixed at 0.
  expectField("my_model(x[4], a[1]) {\n my_model = x[1] + x[4] + 1;\n}\n",
              [](double x, double, double) { return x + 1; });
}

TEST(HyperFun, ObjectCallsCopyTheSArrayBack) {
  const char* text =
      "colour(x[3], a[1], s[2]) {\n s[2] = 7;\n colour = x[1];\n}\n"
      "my_model(x[3], a[1], s[2]) {\n s = [1, 2];\n v = colour(x, a, s);\n my_model = v + s[2];\n}\n";
  expectField(text, [](double x, double, double) { return x + 7; });
  std::string wrong = text;
  wrong.replace(wrong.find("colour(x, a, s)"), 15, "colour(x, a)");
  expectHas(compileError(wrong),
            "m.hf:7:6: error: object 'colour' has s[2]: pass an array of that size as a third argument");
}

TEST(HyperFun, NestingAndWorkAreBounded) {
  std::string sum = "my_model = x[1]";
  for (int i = 0; i < 3000; ++i) sum += " + 1";
#if defined(PF_SANITIZED)
  // 3000 levels fit the main thread's 8 MB; clang's ASan frames do not (the reader's stack
  // guard says so, as it should): the legal depth is checked on a stack with room for them.
  test::onStack(size_t{64} << 20, [&] {
    expectField(model(sum + ";"), [](double x, double, double) { return x + 3000; });
  });
#else
  expectField(model(sum + ";"), [](double x, double, double) { return x + 3000; });
#endif
  for (int i = 0; i < 2000; ++i) sum += " + 1";
  expectHas(compileError(model(sum + ";")), "error: expression nested more than 4000 levels deep");
  const std::string parens = std::string(1200, '(') + "1" + std::string(1200, ')');
  expectHas(compileError(model("my_model = " + parens + ";")), "error: nested more than 1000 levels deep");
  expectHas(compileError(model("i = 0;\nwhile i < 3000 loop\n j = 0;\n while j < 3000 loop j = j + 1; endloop;\n"
                               " i = i + 1;\nendloop;\nmy_model = 1;")),
            "m.hf:4:2: error: the model needs more than 2000000 statements to compile");
  // A loop that never ends but grows the tape each time stops at the tape's limit, long before
  // the iteration limit (found by fuzz_field: it took seconds and ~1 GB before).
  expectHas(compileError(model("n = 1;\np = x[1];\nwhile n < 6 loop\n p = 2 * p - x[2];\n q = p * p + x[3];\n p = q - p * x[1];\n n = n + 0;\nendloop;\nmy_model = p;")),
            "error: the model unrolls to more than 262144 tape operations (loops and object calls are unrolled)");
}

}  // namespace
}  // namespace pf::field
