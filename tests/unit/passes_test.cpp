// The optimization passes: each kind of rewrite fires where it should and says why, never
// where a value can change (merge values in loops), and never changes what a program computes
// (every program here runs optimized and unoptimized, lane by lane, with identical results).
#include <gtest/gtest.h>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {

size_t count(const Bytecode& b, Op op) {
  size_t n = 0;
  for (const Instr& i : b.code) n += i.op == op;
  return n;
}

// Runs `source` (a primitive p writing Z) optimized and not; expects identical depth per lane.
void expectSameResults(const std::string& source, const std::vector<float>& params = {}) {
  auto opt = compile(source, "t.pfl", true);
  auto raw = compile(source, "t.pfl", false);
  ASSERT_TRUE(opt.ok && raw.ok) << opt.diagnostics;
  BlockRun a = runBlock(*opt.find("p"), params, {}, 0, true, 1e9f);
  BlockRun b = runBlock(*raw.find("p"), params, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) EXPECT_EQ(a.depth[i], b.depth[i]) << "lane " << i << "\n" << source;
  EXPECT_EQ(a.killed, b.killed);
}

}  // namespace

TEST(Passes, FoldsConstantsWithTheExecutorsArithmetic) {
  std::string explain;
  auto c = compile("primitive p(inout varying float Z) { float k = sqrt(16.0) * 2.0 + float(7 / 2); Z = X * k; }",
                   "t.pfl", true, &explain);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  EXPECT_EQ(p.setup.code.size(), 0u) << disassemble(p.setup, false);  // k = 11, known at compile time
  ASSERT_EQ(p.pixel.code.size(), 2u) << disassemble(p.pixel, true);
  EXPECT_NE(disassemble(p.pixel, true).find("#11"), std::string::npos);
  EXPECT_NE(explain.find("t.pfl:1:48: "), std::string::npos) << explain;
  EXPECT_NE(explain.find("constant operands, folded to 11"), std::string::npos) << explain;
}

TEST(Passes, SharesCommonSubexpressionsIncludingCommutedOnes) {
  std::string explain;
  auto c = compile(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  float s = a[0] * X + a[0] * Y;\n"
      "  float t = Y * a[0] + X * a[0];\n"  // the same products, commuted
      "  Z = s + t;\n"
      "}\n",
      "t.pfl", true, &explain);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  EXPECT_EQ(count(c.find("p")->pixel, Op::FMul), 2u) << disassemble(c.find("p")->pixel, true);
  EXPECT_NE(explain.find("computed before as"), std::string::npos) << explain;
  expectSameResults(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  float s = a[0] * X + a[0] * Y;\n"
      "  float t = Y * a[0] + X * a[0];\n"
      "  Z = s + t;\n"
      "}\n",
      {1.75f});
}

TEST(Passes, RemovesDeadCodeInBothPrograms) {
  auto c = compile(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  float unused_u = sin(a[0]) * 3.0;\n"
      "  float unused_v = cos(X) * Y;\n"
      "  Z = X;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  EXPECT_EQ(count(c.find("p")->setup, Op::FSin), 0u);
  EXPECT_EQ(count(c.find("p")->pixel, Op::FCos), 0u);
}

TEST(Passes, NeverSharesAcrossAValueThatChangesInALoop) {
  // `acc * 2.0` before and inside the loop read different values of acc.
  const std::string src =
      "primitive p(inout varying float Z) {\n"
      "  float acc = X;\n"
      "  float before = acc * 2.0;\n"
      "  for (int k = 0; k < 3; k += 1) acc = acc * 2.0 + before;\n"
      "  Z = acc * 2.0 + before;\n"
      "}\n";
  expectSameResults(src);
  auto c = compile(src);
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int i = 0; i < 64; ++i) {
    float x = static_cast<float>(i % 8) + 0.5f, acc = x, before = acc * 2.0f;
    for (int k = 0; k < 3; ++k) acc = acc * 2.0f + before;
    EXPECT_FLOAT_EQ(r.depth[i], acc * 2.0f + before);
  }
}

TEST(Passes, OptimizedProgramsComputeTheSame) {
  expectSameResults(
      "float f(float v) { if (v > 3.0) return v * v; return v + 1.0; }\n"
      "primitive p(float a[2]; inout varying float Z) {\n"
      "  float u = a[0] * a[1] + a[1] * a[0];\n"
      "  float w = 0.0;\n"
      "  int n = 0;\n"
      "  while (w < Y * u) { w += f(X) + f(X); n += 1; if (n > 9) break; }\n"
      "  if (X > 4.0) w = w * (2.0 + 3.0); else w = -w;\n"
      "  Z = w + f(u) * f(u);\n"
      "}\n",
      {0.5f, 1.5f});
  // The shipped triangle, too: optimized and not, the same depth on every lane.
  FILE* fp = std::fopen((std::string(PF_SOURCE_DIR) + "/primitives/screen_triangle.pfl").c_str(), "rb");
  ASSERT_NE(fp, nullptr);
  std::string text;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, fp)) > 0) text.append(buf, n);
  std::fclose(fp);
  auto opt = compile(text, "s.pfl", true), raw = compile(text, "s.pfl", false);
  ASSERT_TRUE(opt.ok && raw.ok);
  std::vector<float> verts = {0.5f, 0.25f, 0.1f, 1.0f, 7.75f, 1.5f, 0.6f, 1.0f, 2.25f, 7.5f, 0.9f, 1.0f};
  std::vector<float> ch = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1};
  BlockRun a = runBlock(*opt.find("screen_triangle"), verts, ch, 4, true, 1.0f, InterpKind::Linear);
  BlockRun b = runBlock(*raw.find("screen_triangle"), verts, ch, 4, true, 1.0f, InterpKind::Linear);
  int covered = 0;
  for (int i = 0; i < 64; ++i) {
    EXPECT_EQ(a.depth[i], b.depth[i]) << i;
    covered += a.depth[i] < 1.0f;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a.channel(k, i % 8, i / 8), b.channel(k, i % 8, i / 8));
  }
  EXPECT_GT(covered, 10);
}
