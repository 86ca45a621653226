// Code generation: the setup / per-pixel split, and programs run through both executors with
// results checked against values computed here by hand (the analytic answer for each lane).
#include <gtest/gtest.h>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {
bool pixelProgramUses(const CompiledPrimitive& p, Op op) {
  for (const Instr& i : p.pixel.code)
    if (i.op == op) return true;
  return false;
}
bool setupProgramUses(const CompiledPrimitive& p, Op op) {
  for (const Instr& i : p.setup.code)
    if (i.op == op) return true;
  return false;
}
}  // namespace

TEST(Codegen, UniformWorkIsHoistedIntoSetup) {
  // Everything but the final per-pixel expression depends only on the parameter.
  auto c = compile(
      "primitive p(float k[1]; inout varying float Z) {\n"
      "  float a = sqrt(k[0]) * 2.0 + 1.0;\n"
      "  float b = a * a;\n"
      "  Z = b * X;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  EXPECT_TRUE(setupProgramUses(p, Op::FSqrt));
  EXPECT_FALSE(pixelProgramUses(p, Op::FSqrt));
  EXPECT_FALSE(pixelProgramUses(p, Op::FAdd));
  // Pixel program: one multiply and the depth commit.
  ASSERT_EQ(p.pixel.code.size(), 2u) << disassemble(p.pixel, true);
  EXPECT_EQ(p.pixel.code[0].op, Op::FMul);
  EXPECT_EQ(p.pixel.num_uniform_slots, 1u);  // only b crosses from setup to pixels
  // Run it: k = 4 -> a = 5, b = 25, Z = 25 X (X = x + 0.5).
  BlockRun r = runBlock(p, {4.0f}, {}, 0, false);
  for (int x = 0; x < 8; ++x) EXPECT_FLOAT_EQ(r.depth[x], 1.0f);  // depth test off: no write
  r = runBlock(p, {4.0f}, {}, 0, true, 1000.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_FLOAT_EQ(r.depth[y * 8 + x], 25.0f * (x + 0.5f));
}

TEST(Codegen, UniformReturnBecomesKill) {
  auto c = compile("primitive p(float k[1]; inout varying float Z) { if (k[0] < 0.0) return; Z = X; }");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  EXPECT_TRUE(setupProgramUses(p, Op::Kill));
  EXPECT_FALSE(pixelProgramUses(p, Op::Retire));
  EXPECT_TRUE(runBlock(p, {-1.0f}, {}, 0).killed);
  EXPECT_FALSE(runBlock(p, {1.0f}, {}, 0).killed);
}

TEST(Codegen, VaryingIfElseMergesPerLane) {
  // Per lane: v = X < 4 ? 10 + Y : 20 - Y, with nested varying control and a late return.
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  float v = 0.0;\n"
      "  if (X < 4.0) { v = 10.0 + Y; if (Y > 6.0) v = v * 2.0; }\n"
      "  else v = 20.0 - Y;\n"
      "  if (X > 7.0 && Y < 1.0) return;\n"
      "  Z = v;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  EXPECT_TRUE(pixelProgramUses(p, Op::MaskIf));
  BlockRun r = runBlock(p, {}, {}, 0, true, 1e9f);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      float X = x + 0.5f, Y = y + 0.5f;
      float want = X < 4.0f ? (Y > 6.0f ? 2.0f * (10.0f + Y) : 10.0f + Y) : 20.0f - Y;
      bool retired = X > 7.0f && Y < 1.0f;
      EXPECT_FLOAT_EQ(r.depth[y * 8 + x], retired ? 1e9f : want) << x << "," << y;
      EXPECT_EQ(r.drawn(x, y), !retired) << x << "," << y;
    }
  }
}

TEST(Codegen, BlockWhoseLanesAllReturnStopsEarly) {
  auto c = compile("primitive p(inout varying float Z) { if (X >= 0.0) return; Z = 5.0; }");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0);
  for (int i = 0; i < 64; ++i) {
    EXPECT_FLOAT_EQ(r.depth[i], 1.0f);
    EXPECT_FALSE(r.shade_ids[(i / 8) * 64 + i % 8]);
  }
}

TEST(Codegen, IntegerAndBoolArithmetic) {
  auto c = compile(
      "primitive p(inout varying float Z) {\n"
      "  int i = int(X) * 3 + 7 / 2 - 10 % 4;\n"   // 3x + 3 - 2
      "  int j = int(Y) / 0;\n"                     // division by zero gives 0, never traps
      "  bool b = i > 10 || j != 0;\n"
      "  Z = b ? float(i) : -float(i);\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {}, {}, 0, true, 1e9f);
  for (int x = 0; x < 8; ++x) {
    int i = 3 * x + 1;
    float want = i > 10 ? static_cast<float>(i) : -static_cast<float>(i);
    EXPECT_FLOAT_EQ(r.depth[x], want) << x;
  }
}

TEST(Codegen, InterpolatorDataArithmeticAppliesToEveryChannel) {
  // The figure-8 formula: (1 - t) * a + t * b, on all channels of two sequence points.
  auto c = compile(
      "primitive p(float t[2]; interpolator_data d[2]; inout varying float Z) {\n"
      "  float s = t[0];\n"
      "  interpolation {\n"
      "  perspective_linear: linear:\n"
      "    interpolator_data m = (1 - s) * d[0] + s * d[1];\n"
      "    interpolator_return(m + d[1] * (X / 100.0));\n"
      "  default: interpolator_return;\n"
      "  }\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const std::vector<float> channels = {1.0f, 2.0f, 3.0f, 10.0f, 20.0f, 30.0f};  // 2 points x 3 channels
  for (InterpKind kind : {InterpKind::PerspectiveLinear, InterpKind::Linear}) {
    BlockRun r = runBlock(*c.find("p"), {0.25f, 0.0f}, channels, 3, true, 1.0f, kind);
    for (int x = 0; x < 8; ++x)
      for (int ch = 0; ch < 3; ++ch) {
        float a = channels[ch], b = channels[3 + ch];
        float want = (0.75f * a + 0.25f * b) + b * ((x + 0.5f) / 100.0f);
        EXPECT_NEAR(r.channel(ch, x, 0), want, 1e-5f * std::abs(want)) << "channel " << ch;
      }
  }
}

TEST(Codegen, BoundStatementReachesSetupOutput) {
  auto c = compile("primitive p(float r[1]) { bound(1.0, 2.0, r[0], r[0] * 2.0); }");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {3.0f}, {}, 0);
  ASSERT_TRUE(r.setup.has_bound);
  EXPECT_FLOAT_EQ(r.setup.bound[0], 1.0f);
  EXPECT_FLOAT_EQ(r.setup.bound[1], 2.0f);
  EXPECT_FLOAT_EQ(r.setup.bound[2], 3.0f);
  EXPECT_FLOAT_EQ(r.setup.bound[3], 6.0f);
}

TEST(Codegen, DisassemblyNamesBuiltins) {
  auto c = compile("primitive p(inout varying float Z) { Z = X + Y; }");
  ASSERT_TRUE(c.ok);
  std::string listing = disassemble(c.find("p")->pixel, true);
  EXPECT_NE(listing.find("fadd v10, X, Y"), std::string::npos) << listing;
  EXPECT_NE(listing.find("zcommit v10"), std::string::npos) << listing;
}
