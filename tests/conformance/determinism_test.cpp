// primflow's output is byte-identical for any number of rasterizer threads: every GL case of the
// conformance suite rendered with 1, 2, 3 and 8 threads, colour and depth compared bytewise;
// for any instruction set the pixel kernels are compiled for; and with pixel programs as
// native code or on the interpreter.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "compiler/native/native_cache.h"
#include "conformance.h"
#include "raster/lane_kernels.h"

namespace {

// Pixel programs compiled on their first block (the default waits for a thousand), so that
// native code draws these small cases; put back afterwards.
struct NativeOnFirstBlock {
  uint64_t saved = pf::NativeProgramCache::instance().threshold();
  NativeOnFirstBlock() { pf::NativeProgramCache::instance().setThreshold(0); }
  ~NativeOnFirstBlock() { pf::NativeProgramCache::instance().setThreshold(saved); }
};

class Determinism : public ::testing::TestWithParam<std::string> {};

// Puts back the lane kernels' instruction set in use when a test started.
struct LaneIsaSaved {
  pf::LaneIsa isa = pf::laneIsa();
  ~LaneIsaSaved() { pf::setLaneIsa(isa); }
};

std::vector<std::string> caseNames();

TEST_P(Determinism, ByteIdenticalForAnyThreadCount) {
  const int w = 256, h = 256;
  pfconf::Rendering one = pfconf::renderPrimflow(GetParam(), w, h, 1);
  ASSERT_TRUE(one.image.ok);
  for (int threads : {2, 3, 8}) {
    pfconf::Rendering many = pfconf::renderPrimflow(GetParam(), w, h, threads);
    ASSERT_TRUE(many.image.ok);
    size_t differing = 0;
    for (size_t i = 0; i < one.image.rgba.size(); ++i) differing += one.image.rgba[i] != many.image.rgba[i];
    EXPECT_EQ(differing, 0u) << threads << " threads: colour bytes differing from 1 thread";
    EXPECT_TRUE(one.image.depth == many.image.depth) << threads << " threads: the depth buffer differs";
    EXPECT_TRUE(one.output.errors == many.output.errors && one.output.numbers == many.output.numbers);
  }
}

// And for any instruction set of the pixel kernels (raster/lane_kernels.h) the machine runs:
// the same bytes as the baseline (SSE2) kernels.
TEST_P(Determinism, ByteIdenticalForEveryLaneInstructionSet) {
  const LaneIsaSaved saved;
  const int w = 256, h = 256;
  ASSERT_TRUE(pf::setLaneIsa(pf::LaneIsa::Baseline));
  pfconf::Rendering base = pfconf::renderPrimflow(GetParam(), w, h, 1);
  ASSERT_TRUE(base.image.ok);
  for (pf::LaneIsa isa : pf::availableLaneIsas()) {
    ASSERT_TRUE(pf::setLaneIsa(isa));
    pfconf::Rendering other = pfconf::renderPrimflow(GetParam(), w, h, 2);
    ASSERT_TRUE(other.image.ok);
    EXPECT_TRUE(base.image.rgba == other.image.rgba) << pf::laneIsaName(isa) << ": colour differs from sse2";
    EXPECT_TRUE(base.image.depth == other.image.depth) << pf::laneIsaName(isa) << ": depth differs from sse2";
  }
}

// Native code against the interpreter: the interpreter's image with 1 thread, and native code's
// for the machine's best instruction set with 1 thread (every block native) and 2 (some blocks
// interpreted while another thread compiles); every fourth case also for the other instruction
// sets (compiling each case for each set would be most of the suite's time; the lane-kernel
// test above covers every set on every case). (Block rejection's walk stays interpreted here:
// native_rejection_test compares the two walks.)
TEST_P(Determinism, ByteIdenticalWithNativeCodeAndInterpreter) {
  const LaneIsaSaved saved;
  const NativeOnFirstBlock native_on_first_block;
  const int w = 256, h = 256;
  pfconf::Rendering interpreted = pfconf::renderPrimflow(GetParam(), w, h, 1, 0);
  ASSERT_TRUE(interpreted.image.ok);
  const std::vector<pf::LaneIsa> isas = pf::availableLaneIsas();
  const std::vector<std::string> names = caseNames();
  const bool every_isa = (std::find(names.begin(), names.end(), GetParam()) - names.begin()) % 4 == 0;
  for (pf::LaneIsa isa : isas) {
    if (isa != isas.back() && !every_isa) continue;
    ASSERT_TRUE(pf::setLaneIsa(isa));
    for (int threads : {1, 2}) {
      if (threads == 2 && isa != isas.back()) continue;
      pfconf::Rendering native = pfconf::renderPrimflow(GetParam(), w, h, threads, 1);
      ASSERT_TRUE(native.image.ok);
      EXPECT_TRUE(interpreted.image.rgba == native.image.rgba)
          << pf::laneIsaName(isa) << ", " << threads << " threads: native code's colour differs from the interpreter's";
      EXPECT_TRUE(interpreted.image.depth == native.image.depth)
          << pf::laneIsaName(isa) << ", " << threads << " threads: native code's depth differs from the interpreter's";
      EXPECT_TRUE(interpreted.output.errors == native.output.errors && interpreted.output.numbers == native.output.numbers);
    }
  }
}

std::vector<std::string> caseNames() {
  std::vector<std::string> names;
  for (const pfconf::GlCase& c : pfconf::glCases()) names.push_back(c.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Cases, Determinism, ::testing::ValuesIn(caseNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace

// Vertex arrays draw what immediate mode draws: the ID mesh through glDrawElements (case
// vertex_arrays, below its strip) is byte-identical to the same mesh in glBegin / glVertex
// (case mesh_ids).
TEST(VertexArrays, DrawExactlyLikeImmediateMode) {
  pfconf::Rendering arrays = pfconf::renderPrimflow("vertex_arrays", 256, 256, 1);
  pfconf::Rendering immediate = pfconf::renderPrimflow("mesh_ids", 256, 256, 1);
  ASSERT_TRUE(arrays.image.ok && immediate.image.ok);
  size_t differing = 0, drawn = 0;
  for (size_t i = 0; i < size_t(256) * 236 * 4; ++i) differing += arrays.image.rgba[i] != immediate.image.rgba[i];
  for (size_t i = 0; i < size_t(256) * 236; ++i) drawn += immediate.image.rgba[i * 4] != pfconf::kClear[0];
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(drawn, 40000u);
}
