// Field units of the language (compiler/field/field_unit.h): fields written in the language
// compile to tapes whose values are the formulas' (checked in double at random points against
// the formulas written here in C++), compile-time control flow unrolls, and everything a tape
// cannot hold is an error that names the line.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "compiler/field/field_unit.h"
#include "field/field_reference.h"

namespace pf::field {
namespace {

FieldTape compileOk(const std::string& source, const std::vector<float>& params = {}, const std::string& name = "") {
  DiagnosticLog log;
  auto tape = compileFieldUnit("f.pfl", source, name, params, log);
  EXPECT_TRUE(tape) << log.format();
  return tape ? *tape : FieldTape{};
}

std::string compileError(const std::string& source, const std::vector<float>& params = {}, const std::string& name = "") {
  DiagnosticLog log;
  auto tape = compileFieldUnit("f.pfl", source, name, params, log);
  EXPECT_FALSE(tape);
  return log.format();
}

size_t countOps(const FieldTape& t, FieldOp op) {
  size_t n = 0;
  for (const FieldInstr& in : t.instrs) n += in.op == op;
  return n;
}

// Compares a tape with a double formula at random points of [-2, 2]^3.
template <class Formula>
void expectMatches(const FieldTape& tape, Formula formula, double tolerance = 1e-5) {
  ASSERT_FALSE(tape.instrs.empty());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 2000; ++i) {
    const double x = static_cast<float>(u(rng)), y = static_cast<float>(u(rng)), z = static_cast<float>(u(rng));
    const double want = formula(x, y, z);
    const double got = testing::evaluateDouble(tape, x, y, z);
    ASSERT_NEAR(got, want, tolerance * (1.0 + std::fabs(want))) << "at (" << x << ", " << y << ", " << z << ")";
  }
}

TEST(FieldUnit, LoopsAndCallsUnrollIntoTheFormula) {
  // Three spheres of radius r along x, unioned with max; a function and a loop on constants.
  const FieldTape t = compileOk(R"(
float sphere_at(point p, point c, float r) {
    vector d = vector(p.x - c.x, p.y - c.y, p.z - c.z);
    return r * r - dot(d, d);
}
field float beads(point p, float r) {
    float f = -1.0e9;
    for (float i = -1.0; i <= 1.0; i += 1.0) {
        f = max(f, sphere_at(p, point(i, 0.0, 0.0), r));
    }
    return f;
}
)", {0.6f});
  expectMatches(t, [](double x, double y, double z) {
    double f = -1e9;
    for (double c = -1; c <= 1; c += 1) f = std::max(f, 0.36 - ((x - c) * (x - c) + y * y + z * z));
    return f;
  }, 1e-6);
  EXPECT_EQ(countOps(t, FieldOp::Max), 3u);  // unrolled: max(max(max(-1e9, s0), s1), s2)
}

// A matrix built from the parameters is computed when the field is compiled: only its product
// with the point reaches the tape (an ellipsoid, turned by `angle` about z and moved).
TEST(FieldUnit, MatricesOfParametersFoldIntoTheFormula) {
  const FieldTape t = compileOk(R"(
field float turned(point p, float angle, float sx) {
    matrix to_world = matrix(cos(angle), -sin(angle), 0.0, 0.5,
                             sin(angle), cos(angle), 0.0, -0.25,
                             0.0, 0.0, 1.0, 0.1,
                             0.0, 0.0, 0.0, 1.0) * matrix(sx, 0.0, 0.0, 0.0,  0.0, 1.0, 0.0, 0.0,
                                                          0.0, 0.0, 1.0, 0.0,  0.0, 0.0, 0.0, 1.0);
    point q = inverse(to_world) * p;
    return 1.0 - q.x * q.x - q.y * q.y - q.z * q.z;
}
)", {0.7f, 1.6f});
  expectMatches(t, [](double x, double y, double z) {
    const double a = static_cast<float>(0.7), sx = static_cast<float>(1.6);
    // inverse: untranslate, unrotate, unscale
    const double px = x - 0.5, py = y + 0.25, pz = z - 0.1;
    const double rx = std::cos(a) * px + std::sin(a) * py, ry = -std::sin(a) * px + std::cos(a) * py;
    const double qx = rx / sx, qy = ry, qz = pz;
    return 1.0 - qx * qx - qy * qy - qz * qz;
  }, 1e-5);
  EXPECT_EQ(countOps(t, FieldOp::Cos), 0u);  // the matrix was folded: no trigonometry on the tape
}

TEST(FieldUnit, BranchesOnParametersAreDecidedWhenCompiled) {
  const std::string source = R"(
field float pick(point p, float which) {
    if (which > 0.5) {
        return 1.0 - length(p);
    }
    return 1.0 - max(abs(p.x), max(abs(p.y), abs(p.z)));
}
)";
  expectMatches(compileOk(source, {1.0f}), [](double x, double y, double z) { return 1 - std::sqrt(x * x + y * y + z * z); });
  expectMatches(compileOk(source, {0.0f}), [](double x, double y, double z) {
    return 1 - std::max(std::fabs(x), std::max(std::fabs(y), std::fabs(z)));
  });
}

TEST(FieldUnit, PowTanAndTheOtherTapeOperations) {
  const FieldTape t = compileOk(R"(
field float mixed(point p) {
    float a = pow(p.x, 3.0) - pow(p.y, -2.0);
    float b = pow(abs(p.z) + 1.0, 0.5) * exp(-p.x * p.x) + log(p.y * p.y + 1.0);
    return a + b + tan(p.z * 0.3) - sin(p.x) * cos(p.y) / (1.0 + sqrt(abs(p.z)));
}
)");
  expectMatches(t, [](double x, double y, double z) {
    const double a = x * x * x - 1.0 / (y * y);
    const double b = std::pow(std::fabs(z) + 1.0, 0.5) * std::exp(-x * x) + std::log(y * y + 1.0);
    return a + b + std::tan(z * 0.3) - std::sin(x) * std::cos(y) / (1.0 + std::sqrt(std::fabs(z)));
  }, 2e-5);
  EXPECT_EQ(countOps(t, FieldOp::Exp), 2u);  // exp(-x^2), and pow(., 0.5) as exp(0.5 log .)
}

TEST(FieldUnit, InverseTrigonometryThroughAtan) {
  const FieldTape t = compileOk(R"(
field float angles(point p) {
    return atan(p.x) + 0.5 * atan2(p.y, p.z) - asin(p.x * 0.4) + acos(p.y * 0.45);
}
)");
  expectMatches(t, [](double x, double y, double z) {
    return std::atan(x) + 0.5 * std::atan2(y, z) - std::asin(x * 0.4) + std::acos(y * 0.45);
  }, 2e-5);
  EXPECT_GT(countOps(t, FieldOp::Atan), 2u);
}

// The IR computes both arms of ?:; an arm a tape cannot hold is an error only when it is chosen.
TEST(FieldUnit, UnsupportedValuesAreErrorsWhereUsed) {
  const std::string source = "field float f(point p, float k) {\n  float a = k > 0.0 ? floor(p.x) : p.x;\n  return a;\n}\n";
  expectMatches(compileOk(source, {-1.0f}), [](double x, double, double) { return x; }, 0.0);
  EXPECT_NE(compileError(source, {1.0f}).find("f.pfl:2:23: error: 'floor (and fract, mod)' of a value that depends"),
            std::string::npos) << compileError(source, {1.0f});
  // An error inside a library function also names the field that called it.
  const std::string in_library = compileError("field float g(point p) {\n  return hfInt(p.x);\n}\n");
  EXPECT_NE(in_library.find("<stdlib>/hyperfun.pfl:"), std::string::npos) << in_library;
  EXPECT_NE(in_library.find("f.pfl:1:1: note: in field 'g', through the functions it calls"), std::string::npos) << in_library;
}

// fixed<bits,frac> in a field: values of its parameters fold when it is compiled; a
// point-dependent one has no tape form (tapes are floats and intervals) and is an error there.
TEST(FieldUnit, FixedPointValuesFoldOrAreErrors) {
  const std::string folded =
      "field float f(point p, float k) {\n  fixed<32,16> r = fixed<32,16>(k) / 3;\n  return float(r) - p.x;\n}\n";
  // 1 / 3 at 16 fraction bits is 21845 / 65536.
  expectMatches(compileOk(folded, {1.0f}), [](double x, double, double) { return 21845.0 / 65536.0 - x; }, 1e-7);
  const std::string error = compileError("field float f(point p) {\n  fixed<32,16> r = p.x;\n  return float(r);\n}\n");
  EXPECT_NE(error.find("f.pfl:2:22: error: 'fixed-point arithmetic (fixed<bits,frac>)' of a value that depends on the field's point"),
            std::string::npos) << error;
}

// A whole exponent is products however large (as HyperFun's ^), so negative bases keep their sign.
TEST(FieldUnit, LargeWholePowersAreProducts) {
  const FieldTape t = compileOk("field float f(point p) { return pow(p.x * 0.999, 3001.0) + 0.0 * p.y; }");
  EXPECT_EQ(countOps(t, FieldOp::Log), 0u);
  EXPECT_LT(testing::evaluateDouble(t, -1.0, 0.0, 0.0), 0.0);
}

TEST(FieldUnit, ChoosesTheFieldByName) {
  const std::string source = "field float a(point p) { return p.x; }\nfield float b(point p) { return p.y; }\n";
  expectMatches(compileOk(source, {}, "b"), [](double, double y, double) { return y; }, 0.0);
  EXPECT_NE(compileError(source).find("f.pfl:1:1: error: the source defines several fields ('a', 'b'): name the one"),
            std::string::npos);
  EXPECT_NE(compileError(source, {}, "c").find("no field named 'c' (its fields: 'a', 'b')"), std::string::npos);
  EXPECT_NE(compileError("float g(float x) { return x; }\n").find("the source defines no field"), std::string::npos);
}

TEST(FieldUnit, FieldsCallFieldsWithTheirParameters) {
  const std::string source = R"(
field float ball(point p, float r) { return r - length(p); }
field float pair(point p) { return max(ball(hfShift3D(p, 0.5, 0.0, 0.0), 0.4), ball(p, 0.2)); }
)";
  expectMatches(compileOk(source, {}, "pair"), [](double x, double y, double z) {
    return std::max(0.4 - std::sqrt((x - 0.5) * (x - 0.5) + y * y + z * z), 0.2 - std::sqrt(x * x + y * y + z * z));
  });
}

TEST(FieldUnit, FieldIsStillAnIdentifierOutsideUnitHeads) {
  // The implicit primitive has a parameter named `field`; a variable may be named so too.
  const FieldTape t = compileOk("field float f(point p) { float field = p.z * 2.0; return field; }\n");
  expectMatches(t, [](double, double, double z) { return 2 * z; }, 0.0);
}

struct BadField {
  const char* source;
  std::vector<float> params;
  const char* expected;
};

// Branches on the point: both sides run, joined by the tape's Select -- ifs, ?:, && || !, and
// break / continue / return taken at some points only (the masked execution of the pixel
// executor, done while compiling). Each against the same control flow written in C++.
TEST(FieldUnit, PointDependentBranchesBecomeSelects) {
  expectMatches(compileOk("field float f(point p) {\n  if (p.x > 0.0) { return 1.0; }\n  return -1.0;\n}\n"),
                [](double x, double, double) { return x > 0 ? 1.0 : -1.0; }, 0.0);
  expectMatches(compileOk("field float f(point p) { return p.x > 0.0 ? p.y : p.z; }"),
                [](double x, double y, double z) { return x > 0 ? y : z; }, 0.0);
  expectMatches(compileOk("field float f(point p) {\n"
                          "  if (p.x > 0.0 && !(p.y > 0.5) || p.z <= -1.0) { return p.x * p.y; }\n"
                          "  else if (p.x == p.y || p.y != p.y) { return 7.0; }\n"
                          "  return p.z;\n}\n"),
                [](double x, double y, double z) { return (x > 0 && !(y > 0.5)) || z <= -1 ? x * y : z; }, 1e-6);
  // An early return from inside a loop of a function: a break out of two loops at some points.
  expectMatches(compileOk("float g(point p) {\n  float s = 0.0;\n"
                          "  for (int i = 0; i < 5; i += 1) {\n    if (p.x < float(i) - 1.5) { return s; }\n"
                          "    s += p.y;\n  }\n  return -s;\n}\n"
                          "field float f(point p) { return g(p) + 1.0; }\n"),
                [](double x, double y, double) {
                  double s = 0;
                  for (int i = 0; i < 5; ++i) {
                    if (x < i - 1.5) return s + 1;
                    s += y;
                  }
                  return -s + 1;
                });
  // continue at some points; then a continue before a break of the rest.
  expectMatches(compileOk("field float f(point p) {\n  float s = 0.0;\n"
                          "  for (int i = 0; i < 4; i += 1) {\n    if (p.x > float(i) - 2.0) { continue; }\n"
                          "    s += p.y * float(i + 1);\n  }\n  return s;\n}\n"),
                [](double x, double y, double) {
                  double s = 0;
                  for (int i = 0; i < 4; ++i) {
                    if (x > i - 2.0) continue;
                    s += y * (i + 1);
                  }
                  return s;
                });
  expectMatches(compileOk("field float f(point p) {\n  float s = 0.0;\n"
                          "  for (int i = 0; i < 3; i += 1) {\n    s += 1.0;\n    if (p.x > 0.0) { continue; }\n"
                          "    break;\n  }\n  return s;\n}\n"),
                [](double x, double, double) { return x > 0 ? 3.0 : 1.0; }, 0.0);
  // A return from the loop (a break past it) after other points broke out of it part-way: those
  // run the code after the loop. (Found in review: they lost it.)
  expectMatches(compileOk("float g(point p) {\n  for (int i = 0; i < 4; i += 1) {\n"
                          "    if (p.x < float(i)) break;\n    if (i == 3) return 1.0;\n  }\n  return -1.0;\n}\n"
                          "field float f(point p) { return g(p); }\n"),
                [](double x, double, double) { return x < 3 ? -1.0 : 1.0; }, 0.0);
  // Both branches leave the same way after a continue inside one of them: the points that
  // continued go on. (Found in review: the break took them along.)
  expectMatches(compileOk("field float f(point p) {\n  float s = 0.0;\n  for (int i = 0; i < 3; i += 1) {\n"
                          "    s += 1.0;\n    if (p.x > 0.0) {\n      if (p.y > 0.0) continue;\n      break;\n"
                          "    } else {\n      break;\n    }\n  }\n  return s;\n}\n"),
                [](double x, double y, double) { return x > 0 && y > 0 ? 3.0 : 1.0; }, 0.0);
  // The unchosen side's inf never reaches the value: a guarded division, at the guard itself.
  const FieldTape guarded = compileOk("field float f(point p) { return p.x != 0.0 ? 1.0 / p.x : 0.0; }");
  EXPECT_EQ(testing::evaluateDouble(guarded, 0.0, 0.0, 0.0), 0.0);
  EXPECT_EQ(testing::evaluateDouble(guarded, 0.5, 0.0, 0.0), 2.0);
  EXPECT_EQ(countOps(guarded, FieldOp::Select), 1u);
  // sign and step of the point are choices too.
  expectMatches(compileOk("field float f(point p) { return sign(p.x) + 10.0 * step(0.5, p.y); }"),
                [](double x, double y, double) { return (x > 0 ? 1.0 : x < 0 ? -1.0 : 0.0) + (y < 0.5 ? 0.0 : 10.0); }, 0.0);
  // A value assigned in one branch only keeps its earlier value elsewhere.
  expectMatches(compileOk("field float f(point p) {\n  float r = p.z;\n  if (p.x < p.y) { r = p.x; }\n  return r;\n}\n"),
                [](double x, double y, double z) { return x < y ? x : z; }, 0.0);
}

TEST(FieldUnit, WhatATapeCannotHoldIsAnErrorAtItsLine) {
  const BadField cases[] = {
      {"field float f(point p) {\n  int k = p.x > 0.0 ? 1 : 2;\n  return float(k);\n}\n", {},
       "f.pfl:2:21: error: this choice (?:) depends on the field's point and picks an int"},
      {"field float f(point p) {\n  int k = 1;\n  if (p.x > 0.0) { k = 2; }\n  return float(k);\n}\n", {},
       "error: an int chosen by a condition that depends on the field's point has no tape form"},
      {"field float f(point p) {\n  return floor(p.x);\n}\n", {}, "f.pfl:2:10: error: 'floor (and fract, mod)' of a value that depends on the field's point has no tape form"},
      {"field float f(point p) {\n  return ceil(p.x);\n}\n", {}, "error: 'ceil' of a value that depends on the field's point"},
      {"field float f(point p) {\n  return noise(p);\n}\n", {}, "error: 'noise' of a value"},
      {"field float f(point p) {\n  float s = 0.0;\n  while (s < p.x) { s += 1.0; }\n  return s;\n}\n", {},
       "f.pfl:3:3: error: this loop's condition depends on the field's point"},
      {"field float f(point p) {\n  float s = 0.0;\n  while (true) { s += 1.0; }\n  return s;\n}\n", {},
       "f.pfl:3:3: error: field 'f' runs its loops more than 1000000 times while it is compiled"},
      {"field float f(point p) {\n  return X;\n}\n", {}, "f.pfl:2:10: error: 'X' is a pixel's built-in, which a field does not see"},
      {"float g(float a) { return a + X; }\nfield float f(point p) {\n  return g(p.x);\n}\n", {},
       "error: this reads a pixel's built-in (X, Y, Z, P or N) through a function"},
      {"field float f(float x) { return x; }\n", {}, "f.pfl:1:21: error: a field's first parameter is the point"},
      {"field vector f(point p) { return vector(p.x, 0.0, 0.0); }\n", {}, "error: field 'f' must return float"},
      {"field float f(point p, int n) { return p.x; }\n", {}, "error: a field's parameters after its point are numbers"},
      {"field float f(point p, float r) { return r - p.x; }\n", {}, "f.pfl:1:1: error: field 'f' takes 1 parameter value after its point; 0 given"},
      {"field float f(point p) { float a = p.x; }\n", {}, "error: field 'f' can reach its end without returning a float"},
      {"field float f(point p) { bound(0.0, 0.0, 1.0, 1.0); return p.x; }\n", {}, "'bound' is only allowed in a primitive"},
      {"field float f(point p) { return field_hit(0.0, p, p, 0, 0.0); }\n", {}, "error: field_hit() is only available in a primitive"},
  };
  for (const BadField& c : cases) {
    const std::string log = compileError(c.source, c.params);
    EXPECT_NE(log.find(c.expected), std::string::npos) << c.source << "\n--- gave:\n" << log;
  }
}

}  // namespace
}  // namespace pf::field
