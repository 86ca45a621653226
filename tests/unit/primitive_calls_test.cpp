// Calls of one primitive from another (paper section 5: polygon -> screen_triangle): a uniform
// statement that submits an instance of the callee with the arguments as its parameters and
// sequence points. Checked here: what setup hands over, in order; the errors around calls.
#include <gtest/gtest.h>

#include "compile_helpers.h"

using namespace pf;
using namespace pf::test;

namespace {

// Records the instances a setup program submits.
struct RecordingSink : SubInstanceSink {
  struct Call {
    std::string callee;
    std::vector<uint32_t> params;
    std::vector<float> channels;
    int depth;
  };
  std::vector<Call> calls;
  int channels_per_vertex = 0;
  void submitCall(const CompiledPrimitive& callee, const uint32_t* params, const float* vertex_channels,
                  int depth) override {
    Call c{callee.name, std::vector<uint32_t>(params, params + callee.paramFloats(callee.sequence_points)),
           std::vector<float>(vertex_channels, vertex_channels + callee.sequence_points * channels_per_vertex),
           depth};
    calls.push_back(std::move(c));
  }
};

const char* kPair =
    "primitive dot(float c[2]; interpolator_data d[2]; inout varying float Z) {\n"
    "  if (X > c[0]) return;\n"
    "  Z = c[1];\n"
    "}\n"
    "primitive pairs(int c_count; float c[]; interpolator_data d[]) {\n"
    "  for (int i = 0; i + 1 < c_count; i += 1) {\n"
    "    float two[2];\n"
    "    interpolator_data e[2];\n"
    "    two[0] = c[i] * 2.0;  e[0] = d[i + 1];\n"
    "    two[1] = c[i + 1];    e[1] = d[i] * 0.5;\n"
    "    if (two[0] > 100.0) return;\n"  // uniform control: the rest of the instance is killed
    "    dot(two, e);\n"
    "  }\n"
    "}\n";

}  // namespace

TEST(PrimitiveCalls, SetupSubmitsEachCallWithItsArguments) {
  auto c = compile(kPair);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const CompiledPrimitive& pairs = *c.find("pairs");
  ASSERT_EQ(pairs.callees.size(), 1u);
  EXPECT_EQ(pairs.callees[0]->name, "dot");
  EXPECT_EQ(pairs.call_depth, 1);
  EXPECT_TRUE(pairs.pixel.code.empty()) << "a primitive that only calls has no per-pixel work";

  const int n = 5, nch = 2;
  std::vector<uint32_t> params = {static_cast<uint32_t>(n)};
  const float values[n] = {1.0f, 2.0f, 3.0f, 60.0f, 4.0f};  // 2 * 60 > 100: the fourth pair returns
  for (float v : values) params.push_back(f2u(v));
  std::vector<float> channels = {10, 11, 20, 21, 30, 31, 40, 41, 50, 51};
  ChannelLayout layout = ChannelLayout::ofKind(nch, InterpKind::PerspectiveLinear);
  RasterState st;
  RecordingSink sink;
  sink.channels_per_vertex = nch;
  SetupExecutor setup;
  std::vector<uint32_t> record(SetupExecutor::recordWords(pairs, nch) + 1);
  SetupOutput out = setup.run(pairs, SetupInput{params.data(), channels.data(), &layout, &st, n, &sink, 0}, record.data());
  EXPECT_TRUE(out.killed) << "the fourth iteration returns";
  ASSERT_EQ(sink.calls.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    const auto& call = sink.calls[static_cast<size_t>(i)];
    EXPECT_EQ(call.callee, "dot");
    EXPECT_EQ(call.depth, 1);
    ASSERT_EQ(call.params.size(), 2u);
    EXPECT_EQ(std::bit_cast<float>(call.params[0]), values[i] * 2.0f);
    EXPECT_EQ(std::bit_cast<float>(call.params[1]), values[i + 1]);
    ASSERT_EQ(call.channels.size(), 4u);
    EXPECT_EQ(call.channels[0], channels[static_cast<size_t>((i + 1) * 2)]);
    EXPECT_EQ(call.channels[1], channels[static_cast<size_t>((i + 1) * 2 + 1)]);
    EXPECT_EQ(call.channels[2], channels[static_cast<size_t>(i * 2)] * 0.5f);
    EXPECT_EQ(call.channels[3], channels[static_cast<size_t>(i * 2 + 1)] * 0.5f);
  }
}

TEST(PrimitiveCalls, CallableFromAnotherModule) {
  Compiled first = compile(kPair);
  ASSERT_TRUE(first.ok) << first.diagnostics;
  PrimitiveTable table;
  for (auto& p : first.module.primitives) table[p->name] = p;
  CompiledModule module;
  DiagnosticLog log;
  ASSERT_TRUE(compileSource("user.pfl",
                            "primitive one(float c[2]; interpolator_data d[2]) { dot(c, d); }\n",
                            module, log, EmitStage::None, nullptr, true, &table))
      << log.format();
  ASSERT_EQ(module.primitives.size(), 1u);
  EXPECT_EQ(module.primitives[0]->callees[0], table["dot"]) << "the callee is shared, not recompiled";
}

TEST(PrimitiveCalls, CallsNestAtMostEightDeep) {
  std::string chain = "primitive p0(float c[1]; inout varying float Z) { Z = c[0]; }\n";
  for (int i = 1; i <= 9; ++i)
    chain += "primitive p" + std::to_string(i) + "(float c[1]) { p" + std::to_string(i - 1) + "(c); }\n";
  auto deep = compile(chain);
  EXPECT_FALSE(deep.ok);
  EXPECT_NE(deep.diagnostics.find("nests primitive calls 9 deep; the limit is 8"), std::string::npos) << deep.diagnostics;
}

TEST(PrimitiveCalls, Errors) {
  const std::string callee = "primitive dot(float c[2]; inout varying float Z) { Z = c[1]; }\n";
  struct Case {
    std::string source;
    const char* message;
  } cases[] = {
      {callee + "primitive p(float c[2]; inout varying float Z) { if (X > 2.0) dot(c); }\n",
       "must be under uniform control flow; here it is under an 'if' whose condition is varying (line 2)"},
      {callee + "primitive p(float c[2]; inout varying float Z) { float t[2]; t[0] = X; dot(t); }\n",
       "argument 'c' of 'dot' must be uniform"},
      {callee + "primitive p(float c[2]) { dot(c, c); }\n", "'dot' takes 1 argument, not 2"},
      {callee + "primitive p(float c[3]) { dot(c); }\n", "expected float[2], found float[3]"},
      {callee + "float f(float c[2]) { dot(c); return 1.0; }\n", "which only a primitive can do"},
      {callee + "primitive p(float c[2]; inout varying float Z) { Z = dot(c); }\n", "has no value"},
      {std::string("primitive p(float c[2]) { later(c); }\n") +
           "primitive later(float c[2]; inout varying float Z) { Z = c[0]; }\n",
       "primitive 'later' is defined further down"},
      {callee + "primitive p(float c[2]; inout varying float Z) {\n"
                "  Z = 0.5;\n  interpolation { default: dot(c); interpolator_return; }\n}\n",
       "cannot happen inside 'interpolation'"},
      {"primitive s(float w[]; inout varying float Z) { Z = w[0]; }\n"
       "primitive p(float c[2]) { s(c); }\n",
       "takes a parameter-sized array"},
  };
  for (const Case& k : cases) {
    auto c = compile(k.source);
    EXPECT_FALSE(c.ok) << k.source;
    EXPECT_NE(c.diagnostics.find(k.message), std::string::npos) << k.source << "\n" << c.diagnostics;
  }
}
