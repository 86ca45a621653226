// Loops: uniform and varying, break and continue, nesting, loops in setup, and the iteration
// cap. Every per-pixel result is checked against the same computation done here in C++.
#include <gtest/gtest.h>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {
float laneX(int i) { return static_cast<float>(i % 8) + 0.5f; }
float laneY(int i) { return static_cast<float>(i / 8) + 0.5f; }
}  // namespace

TEST(Loops, UniformLoopWithPerPixelWork) {
  auto c = compile(
      "primitive p(float n[1]; inout varying float Z) {\n"
      "  float acc = 0.0;\n"
      "  for (int k = 0; k < int(n[0]); k += 1) acc = acc + X * float(k);\n"
      "  Z = acc;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  for (float n : {0.0f, 1.0f, 5.0f}) {
    BlockRun r = runBlock(*c.find("p"), {n}, {}, 0, true, 1e9f);
    for (int i = 0; i < 64; ++i) {
      float want = 0.0f;
      for (int k = 0; k < static_cast<int>(n); ++k) want = want + laneX(i) * static_cast<float>(k);
      EXPECT_FLOAT_EQ(r.depth[i], want) << "n = " << n << ", lane " << i;
    }
  }
}

TEST(Loops, VaryingWhileWithBreak) {
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float v = 0.0;\n"
      "  int steps = 0;\n"
      "  while (v < Y * 2.0) {\n"
      "    v = v + 1.5;\n"
      "    steps += 1;\n"
      "    if (steps > 3 && X > 4.0) break;\n"
      "  }\n"
      "  Z = v + float(steps) * 1000.0;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) {
    float v = 0.0f;
    int steps = 0;
    while (v < laneY(i) * 2.0f) {
      v = v + 1.5f;
      steps += 1;
      if (steps > 3 && laneX(i) > 4.0f) break;
    }
    EXPECT_FLOAT_EQ(r.depth[i], v + static_cast<float>(steps) * 1000.0f) << "lane " << i;
  }
}

TEST(Loops, ContinueSkipsTheRestOfAnIteration) {
  // Sum of the odd k below X + Y, skipping even ones with continue; the step still runs.
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float sum = 0.0;\n"
      "  for (int k = 0; float(k) < X + Y; k += 1) {\n"
      "    if (k % 2 == 0) continue;\n"
      "    sum += float(k);\n"
      "  }\n"
      "  Z = sum;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) {
    float sum = 0.0f;
    for (int k = 0; static_cast<float>(k) < laneX(i) + laneY(i); k += 1) {
      if (k % 2 == 0) continue;
      sum += static_cast<float>(k);
    }
    EXPECT_FLOAT_EQ(r.depth[i], sum) << "lane " << i;
  }
}

TEST(Loops, NestedLoopsWithInnerBreakAndReturn) {
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float total = 0.0;\n"
      "  for (int i = 0; i < 4; i += 1) {\n"
      "    int j = 0;\n"
      "    while (j < 10) {\n"
      "      if (float(j) > X) break;\n"
      "      total += float(i * 10 + j);\n"
      "      j += 1;\n"
      "    }\n"
      "    if (total > 100.0 && Y > 6.0) return;\n"
      "  }\n"
      "  Z = total;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) {
    float total = 0.0f;
    bool returned = false;
    for (int a = 0; a < 4 && !returned; a += 1) {
      int j = 0;
      while (j < 10) {
        if (static_cast<float>(j) > laneX(i)) break;
        total += static_cast<float>(a * 10 + j);
        j += 1;
      }
      if (total > 100.0f && laneY(i) > 6.0f) returned = true;
    }
    if (returned) {
      EXPECT_FLOAT_EQ(r.depth[i], 1e9f) << "lane " << i << " returned: untouched";
      EXPECT_FALSE(r.drawn(i % 8, i / 8));
    } else {
      EXPECT_FLOAT_EQ(r.depth[i], total) << "lane " << i;
    }
  }
}

TEST(Loops, UniformLoopRunsInSetupOnly) {
  // The bound comes from a loop over the parameters: all of it is setup work.
  auto c = compile(
      "primitive p(float x[4]; inout varying float Z) {\n"
      "  float lo = x[0];\n"
      "  float hi = x[0];\n"
      "  int k = 1;\n"
      "  while (k < 4) {\n"
      "    float v = x[0];\n"
      "    if (k == 1) v = x[1];\n"
      "    if (k == 2) v = x[2];\n"
      "    if (k == 3) v = x[3];\n"
      "    lo = min(lo, v);\n"
      "    hi = max(hi, v);\n"
      "    k += 1;\n"
      "  }\n"
      "  bound(lo, lo, hi, hi);\n"
      "  Z = hi;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  for (const Instr& in : p.pixel.code) EXPECT_NE(in.op, Op::LoopBegin) << disassemble(p.pixel, true);
  BlockRun r = runBlock(p, {3.0f, -2.0f, 7.5f, 1.0f}, {}, 0, true, 1e9f);
  ASSERT_TRUE(r.setup.has_bound);
  EXPECT_FLOAT_EQ(r.setup.bound[0], -2.0f);
  EXPECT_FLOAT_EQ(r.setup.bound[2], 7.5f);
  EXPECT_FLOAT_EQ(r.depth[0], 7.5f);
}

TEST(Loops, IterationCapStopsRunawayPixels) {
  // Lanes with X > 4 never leave the loop; the others do after 3 iterations.
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float v = 0.0;\n"
      "  while (X > 4.0 || v < 3.0) v = v + 1.0;\n"
      "  Z = v;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f, InterpKind::PerspectiveLinear, 100);
  EXPECT_EQ(r.counters.iteration_cap_lanes, 32u);
  for (int i = 0; i < 64; ++i) {
    if (laneX(i) > 4.0f) {
      EXPECT_FLOAT_EQ(r.depth[i], 1e9f) << "a runaway lane draws nothing";
      EXPECT_FALSE(r.drawn(i % 8, i / 8));
    } else {
      EXPECT_FLOAT_EQ(r.depth[i], 3.0f);
    }
  }
}

TEST(Loops, IterationCapStopsARunawaySetupLoop) {
  auto c = compile(
      "primitive p(float r[1]; inout varying float Z) {\n"
      "  float b = 0.0;\n"
      "  while (b < r[0]) b = b * 2.0;\n"   // never grows from 0: runaway for r > 0
      "  bound(0.0, 0.0, b, b);\n"
      "  Z = 0.5;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun ok = runBlock(*c.find("p"), {0.0f}, {}, 0);
  EXPECT_FALSE(ok.killed);
  BlockRun runaway = runBlock(*c.find("p"), {1.0f}, {}, 0, true, 1.0f, InterpKind::PerspectiveLinear, 1000);
  EXPECT_TRUE(runaway.killed);
  EXPECT_TRUE(runaway.setup.iteration_cap_hit);
}

TEST(Loops, SemanticErrors) {
  auto c = compile(
      "primitive p(interpolator_data d[1]) {\n"
      "  break;\n"
      "  while (1) { }\n"
      "  for (int i = 0; i < 2; i += 1) { interpolation { linear: continue; default: interpolator_return; } }\n"
      "  uniform float u = 0.0;\n"
      "  while (X > u) u = u + 1.0;\n"
      "}\n");
  ASSERT_FALSE(c.ok);
  EXPECT_NE(c.diagnostics.find("2:3: error: 'break' is only allowed inside a loop"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("3:10: error: the condition of a loop must be bool, not int"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("'continue' cannot leave an interpolation branch"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("'u' is declared uniform"), std::string::npos) << c.diagnostics;
  EXPECT_NE(c.diagnostics.find("loop whose number of iterations is varying"), std::string::npos) << c.diagnostics;
}

TEST(Loops, UniformBreakInALoopWithPerPixelWork) {
  // The break condition is uniform but changes every iteration: the pixel program computes it.
  auto c = compile(
      "primitive p(float n[1]; inout varying float Z) {\n"
      "  float acc = 0.0;\n"
      "  for (int k = 0; k < 10; k += 1) {\n"
      "    if (k == int(n[0])) break;\n"
      "    if (Y > 4.0) acc += X; else acc -= 1.0;\n"
      "  }\n"
      "  Z = acc;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  for (float n : {0.0f, 3.0f, 20.0f}) {
    BlockRun r = runBlock(*c.find("p"), {n}, {}, 0, true, 1e9f);
    int iterations = std::min(10, static_cast<int>(n));
    for (int i = 0; i < 64; ++i) {
      float acc = 0.0f;
      for (int k = 0; k < iterations; ++k) acc = laneY(i) > 4.0f ? acc + laneX(i) : acc - 1.0f;
      EXPECT_FLOAT_EQ(r.depth[i], acc) << "n = " << n << ", lane " << i;
    }
  }
}

// State read inside a loop that runs per pixel (here screen(), a LoadState of the viewport) is
// computed by the pixel program itself, with the instance's state.
TEST(Loops, StateReadInsideAPerPixelLoop) {
  auto c = compile(
      "primitive p(point vertex[1]; inout varying float Z) {\n"
      "  float acc = 0.0;\n"
      "  for (float t = 0.0; t < X; t += 1.0) {\n"
      "    point s = screen(vertex[0]);\n"
      "    acc += s.x;\n"
      "  }\n"
      "  Z = acc * 0.01;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  // vertex (0.5, 0, 0, 1): window x = 0.5 * 4 + 4 = 6 with runBlock's viewport.
  BlockRun r = runBlock(*c.find("p"), {0.5f, 0.0f, 0.0f, 1.0f}, {}, 0);
  for (int i = 0; i < 64; ++i) {
    const int iterations = i % 8 + 1;  // t = 0, 1, ... while t < X = i % 8 + 0.5
    EXPECT_FLOAT_EQ(r.depth[i], static_cast<float>(iterations) * 6.0f * 0.01f) << "lane " << i;
  }
}

// Deeper nesting than the executors' frame stacks is a compile error, not a primitive that
// silently draws nothing.
TEST(Loops, NestingPastTheExecutorsStacksIsAnError) {
  auto nested = [](int depth) {
    std::string s = "primitive p(inout varying float Z) {\n  float z = 0.0;\n";
    for (int i = 0; i < depth; ++i) s += "  if (X > " + std::to_string(i) + ".0) {\n";
    s += "  z = 0.5;\n";
    for (int i = 0; i < depth; ++i) s += "  }\n";
    return s + "  Z = z;\n}\n";
  };
  auto ok = compile(nested(60));
  EXPECT_TRUE(ok.ok) << ok.diagnostics;
  auto deep = compile(nested(70));
  EXPECT_FALSE(deep.ok);
  EXPECT_NE(deep.diagnostics.find("nest 70 deep"), std::string::npos) << deep.diagnostics;
}
