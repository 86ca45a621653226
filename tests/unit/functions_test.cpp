// User functions: inlined at every call, uniform or varying as each call decides, with early
// returns (also from inside loops), calls between functions, and the errors around them.
#include <gtest/gtest.h>

#include <algorithm>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {
float laneX(int i) { return static_cast<float>(i % 8) + 0.5f; }
float laneY(int i) { return static_cast<float>(i / 8) + 0.5f; }

const char* kFunctions =
    "float clamp01(float v) {\n"
    "  if (v < 0.0) return 0.0;\n"
    "  if (v > 1.0) return 1.0;\n"
    "  return v;\n"
    "}\n"
    "float sumTo(int n) {\n"          // reads X: its result is varying whatever n is
    "  float s = 0.0;\n"
    "  for (int k = 0; k < n; k += 1) {\n"
    "    if (float(k) > X) return s;\n"
    "    s += float(k);\n"
    "  }\n"
    "  return s;\n"
    "}\n"
    "vector scaled(vector v, float k) { return v * clamp01(k); }\n";

float clamp01(float v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }
float sumTo(int n, float X) {
  float s = 0.0f;
  for (int k = 0; k < n; k += 1) {
    if (static_cast<float>(k) > X) return s;
    s += static_cast<float>(k);
  }
  return s;
}
}  // namespace

TEST(Functions, UniformAndVaryingCallsOfOneFunction) {
  auto c = compile(std::string(kFunctions) +
                   "primitive p(float a[1]; inout varying float Z) {\n"
                   "  float u = clamp01(a[0]);\n"
                   "  float w = clamp01(X / 8.0 - u + Y / 16.0);\n"
                   "  Z = w + sumTo(6) * 100.0 + scaled(vector(1.0, 2.0, 3.0), Y / 4.0).z * 1000.0;\n"
                   "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  // The uniform call is setup work: its comparisons are in the setup program.
  bool setup_has_compare = false;
  for (const Instr& in : p.setup.code) setup_has_compare = setup_has_compare || in.op == Op::FLt;
  EXPECT_TRUE(setup_has_compare) << disassemble(p.setup, false);
  for (float a : {-0.5f, 0.25f, 3.0f}) {
    BlockRun r = runBlock(p, {a}, {}, 0, true, 1e9f);
    float u = clamp01(a);
    for (int i = 0; i < 64; ++i) {
      float w = clamp01(laneX(i) / 8.0f - u + laneY(i) / 16.0f);
      float want = w + sumTo(6, laneX(i)) * 100.0f + 3.0f * clamp01(laneY(i) / 4.0f) * 1000.0f;
      EXPECT_FLOAT_EQ(r.depth[i], want) << "a = " << a << ", lane " << i;
    }
  }
}

TEST(Functions, FunctionsCallFunctionsAndSeeOnlyTheirParameters) {
  auto c = compile(
      "float sq(float v) { return v * v; }\n"
      "float dist2(float x, float y) { float d = sq(x) + sq(y); return d; }\n"
      "primitive p(inout varying float Z) {\n"
      "  float d = 3.0;\n"  // the caller's d is not the function's d
      "  Z = dist2(X - 4.0, Y - 4.0) + d;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) {
    float x = laneX(i) - 4.0f, y = laneY(i) - 4.0f;
    EXPECT_FLOAT_EQ(r.depth[i], (x * x + y * y) + 3.0f) << "lane " << i;
  }
}

TEST(Functions, Errors) {
  auto c = compile(
      "float f(float v) { if (v > 0.0) return 1.0; }\n"         // may fall off the end
      "float g(float v) { return h(v); }\n"
      "float h(float v) { return g(v) + 1.0; }\n"               // g <-> h
      "float sqrt(float v) { return v; }\n"                     // a built-in's name
      "float k(float v) { return true; }\n"                     // wrong type
      "primitive p(inout varying float Z) {\n"
      "  Z = f(1.0, 2.0);\n"
      "  Z = nosuch(1.0);\n"
      "  return 3;\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  const std::string& d = c.diagnostics;
  EXPECT_NE(d.find("1:1: error: function 'f' can reach its end without returning a float"), std::string::npos) << d;
  EXPECT_NE(d.find("error: recursion is not allowed (functions are inlined): g -> h -> g"), std::string::npos) << d;
  EXPECT_NE(d.find("4:1: error: 'sqrt' is the name of a built-in function"), std::string::npos) << d;
  EXPECT_NE(d.find("5:27: error: cannot return from 'k': expected float, found bool"), std::string::npos) << d;
  EXPECT_NE(d.find("7:7: error: 'f' takes 1 argument, not 2"), std::string::npos) << d;
  EXPECT_NE(d.find("8:7: error: 'nosuch' is not a built-in function"), std::string::npos) << d;
  EXPECT_NE(d.find("9:10: error: a primitive's 'return' takes no value"), std::string::npos) << d;
}

// A function whose only return ends its body is lowered without the loop that early returns
// need: its uniform part stays in setup even where the call as a whole is varying.
TEST(Functions, StraightLineFunctionsKeepTheirUniformWorkInSetup) {
  auto c = compile(
      "float scaledX(float a) {\n"
      "  float k = sqrt(a) * 3.0;\n"  // uniform for a uniform a
      "  return X * k;\n"
      "}\n"
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  Z = scaledX(a[0]) + Y;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  for (const Instr& in : p.pixel.code) {
    EXPECT_NE(in.op, Op::FSqrt) << disassemble(p.pixel, true);
    EXPECT_NE(in.op, Op::LoopBegin) << disassemble(p.pixel, true);
  }
  BlockRun r = runBlock(p, {4.0f}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) EXPECT_FLOAT_EQ(r.depth[i], laneX(i) * 6.0f + laneY(i)) << "lane " << i;
}

// The space transforms skip the terms of literal zeros: transforming a direction (w = 0) along
// an axis costs a column, not a matrix product (and none of it runs per pixel).
TEST(Functions, TransformsOfLiteralAxesAreColumns) {
  auto c = compile(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  point e = eye(point(1.0, 0.0, 0.0, 0.0));\n"
      "  Z = X * e.x + a[0];\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  int multiplies = 0;
  for (const Instr& in : p.setup.code) multiplies += in.op == Op::FMul;
  EXPECT_EQ(multiplies, 0) << disassemble(p.setup, false);  // e.x is InvProjection[0] itself
}
