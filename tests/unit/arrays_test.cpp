// Arrays indexed at run time: local arrays (uniform or varying index, read and write; outside
// the array a read gives zero and a write is lost) and parameter-sized parameters (`T name[]`,
// as many elements as the instance has sequence points; the count in `name_count`). Every
// result is checked lane by lane against values computed here, and (by runBlock) against the
// scalar reference interpreter.
#include <gtest/gtest.h>

#include <cmath>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {
int laneX(int i) { return i % 8; }  // X = laneX + 0.5
int laneY(int i) { return i / 8; }
}  // namespace

TEST(Arrays, UniformIndexWritesAndVaryingIndexReads) {
  auto c = compile(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  float t[4];\n"
      "  for (int i = 0; i < 4; i += 1) t[i] = float(i + 1) * a[0];\n"
      "  Z = t[int(X)];\n"  // lanes with X > 4 read outside: zero
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {0.125f}, {}, 0);
  ASSERT_FALSE(r.killed);
  for (int i = 0; i < 64; ++i) {
    int k = laneX(i);
    float want = k < 4 ? static_cast<float>(k + 1) * 0.125f : 0.0f;
    EXPECT_EQ(r.depth[i], want) << "lane " << i;
  }
}

TEST(Arrays, VaryingIndexWriteChangesOneElementPerPixel) {
  auto c = compile(
      "primitive p(float a[1]; inout varying float Z) {\n"
      "  vector t[3];\n"
      "  t[int(Y) % 3].y = a[0];\n"
      "  t[int(Y) + 5].z = 1.0;\n"  // always outside: lost
      "  Z = t[0].y * 0.25 + t[1].y * 0.5 + t[2].y + t[0].z + t[1].z + t[2].z;\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {0.5f}, {}, 0);
  for (int i = 0; i < 64; ++i) {
    const float weights[3] = {0.25f, 0.5f, 1.0f};
    EXPECT_EQ(r.depth[i], 0.5f * weights[laneY(i) % 3]) << "lane " << i;
  }
}

TEST(Arrays, ComponentOfAnAggregateAtARunTimeIndex) {
  auto c = compile(
      "primitive p(color k[1]; inout varying float Z) {\n"
      "  Z = k[0][int(X) % 4];\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  BlockRun r = runBlock(*c.find("p"), {0.1f, 0.2f, 0.3f, 0.4f}, {}, 0);
  for (int i = 0; i < 64; ++i) EXPECT_FLOAT_EQ(r.depth[i], 0.1f * static_cast<float>(laneX(i) % 4 + 1));
}

TEST(Arrays, ParameterSizedArrayTakesTheInstancesCount) {
  auto c = compile(
      "primitive p(int w_count; float w[]; inout varying float Z) {\n"
      "  float sum = 0.0;\n"
      "  for (int i = 0; i < w_count; i += 1) sum += w[i];\n"
      "  Z = sum + w[w_count] + w[-1 + 0 * w_count];\n"  // both outside: zero
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  EXPECT_EQ(p.sequence_points, 0);
  EXPECT_EQ(p.count_slot, 0);
  EXPECT_EQ(p.param_floats, 1);
  EXPECT_EQ(p.sized_floats, 1);
  for (int n : {0, 1, 5}) {
    std::vector<float> params = {std::bit_cast<float>(static_cast<uint32_t>(n))};
    float want = 0.0f;
    for (int i = 0; i < n; ++i) {
      params.push_back(0.0625f * static_cast<float>(i + 1));
      want += params.back();
    }
    BlockRun r = runBlock(p, params, {}, 0, true, 1.0f, InterpKind::PerspectiveLinear, 65536, n);
    for (int i = 0; i < 64; ++i) EXPECT_EQ(r.depth[i], want) << n << " sequence points, lane " << i;
  }
}

TEST(Arrays, ParameterSizedArraysSitAfterTheFixedPartPerSequencePoint) {
  // Two parameter-sized arrays and no declared count: a hidden count slot.
  auto c = compile(
      "primitive p(float s; point v[]; float w[]; inout varying float Z) {\n"
      "  Z = s + v[1].y * w[2];\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  const ParamInfo* v = p.findParam("v");
  const ParamInfo* w = p.findParam("w");
  ASSERT_TRUE(v && w);
  EXPECT_EQ(p.param_floats, 2);  // s, the hidden count
  EXPECT_EQ(p.count_slot, 1);
  EXPECT_EQ(p.paramOffset(*v, 3, 1), 2 + 4);
  EXPECT_EQ(p.paramOffset(*w, 3, 2), 2 + 3 * 4 + 2);
  std::vector<float> params(static_cast<size_t>(p.paramFloats(3)), 0.0f);
  params[0] = 0.25f;
  params[1] = std::bit_cast<float>(3u);
  params[static_cast<size_t>(p.paramOffset(*v, 3, 1)) + 1] = 0.5f;
  params[static_cast<size_t>(p.paramOffset(*w, 3, 2))] = 0.5f;
  BlockRun r = runBlock(p, params, {}, 0, true, 1.0f, InterpKind::PerspectiveLinear, 65536, 3);
  for (int i = 0; i < 64; ++i) EXPECT_EQ(r.depth[i], 0.5f);
}

TEST(Arrays, ParameterSizedInterpolatorData) {
  auto c = compile(
      "primitive p(int k_count; float k[]; interpolator_data d[]; inout varying float Z) {\n"
      "  int pick = int(k[0]);\n"
      "  Z = 0.5;\n"
      "  interpolation {\n"
      "  perspective_linear:\n"
      "    interpolator_return(d[pick] + d[pick + 100]);\n"  // the second is outside: zero
      "  }\n"
      "}\n");
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& p = *c.find("p");
  // Three sequence points of two channels each.
  std::vector<float> channels = {1, 2, 3, 4, 5, 6};
  for (int pick = 0; pick < 3; ++pick) {
    std::vector<float> params = {std::bit_cast<float>(3u), static_cast<float>(pick), 0.0f, 0.0f};
    BlockRun r = runBlock(p, params, channels, 2, true, 1.0f, InterpKind::PerspectiveLinear, 65536, 3);
    for (int ch = 0; ch < 2; ++ch) EXPECT_EQ(r.channel(ch, 3, 3), channels[static_cast<size_t>(pick * 2 + ch)]);
  }
}

TEST(Arrays, Errors) {
  struct Case {
    const char* source;
    const char* message;
  } cases[] = {
      {"primitive p(float w[]; inout varying float Z) { Z = w[int(X)]; }\n",
       "parameter-sized array is read once per instance, so its index must be uniform"},
      {"primitive p(float w[]; float q[3]; inout varying float Z) { Z = w[0] + q[0]; }\n",
       "all array parameters are indexed by the instance's sequence points"},
      {"primitive p(float w[]; inout varying float Z) { Z = w[-2]; }\n", "never negative"},
      {"primitive p(float w[]; inout varying float Z) {\n"
       "  for (float t = 0.0; t < X; t += 1.0) { if (w[int(t)] > 0.5) return; }\n"
       "  Z = 0.5;\n}\n",
       "index must be uniform"},
      {"primitive p(int w_count; float w[]; inout varying float Z) {\n"
       "  float z = 0.0;\n"
       "  for (int i = 0; i < w_count; i += 1) { z += w[i]; if (X > z) return; }\n"
       "  Z = z;\n}\n",
       "inside a loop that runs per pixel"},
      {"float f(float w[]) { return w[0]; }\n", "expected an array size"},
      {"primitive p(float a[2]; inout varying float Z) { uniform float t[2]; t[int(X)] = 1.0; Z = a[0]; }\n",
       "declared uniform, but it is written at a varying index"},
  };
  for (const Case& k : cases) {
    auto c = compile(k.source);
    EXPECT_FALSE(c.ok) << k.source;
    EXPECT_NE(c.diagnostics.find(k.message), std::string::npos) << k.source << "\n" << c.diagnostics;
  }
}
