// The batched setup executor (raster/setup_batch.h) against the scalar one: for every shipped
// primitive and shared interpolator, random instances -- degenerate ones among them (radius
// <= 0, NaN, infinities, points behind the eye) -- set up both ways must give the same records,
// bounds, kill, cap and facing flags and instruction counts, bit for bit. The same sweep runs
// the batches in native code (compiler/native/setup_codegen.h), compiled at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "compiler/native/native_cache.h"
#include "raster/setup_batch.h"
#include "setup_batch_helpers.h"

namespace {

using namespace pf;
using namespace pf::test;

struct Sweep {
  bool native = false;  // the batches in native code
  uint64_t compared = 0, batched = 0, resumed = 0, in_native = 0;
};

// Sets up `n` random instances of `prim` scalar, one by one, and batched, and compares.
void compareBoth(const CompiledPrimitive& prim, const ChannelLayout& layout, const RasterState& state, int n,
                 uint32_t seed, double degenerate_share, Sweep& sweep) {
  std::mt19937 rng(seed);
  const int count = prim.sequence_points == 0 ? 7 : prim.sequence_points;
  const size_t words = SetupExecutor::recordWords(prim, layout.count);
  std::vector<std::vector<uint32_t>> params(n);
  std::vector<std::vector<float>> channels(n);
  std::uniform_real_distribution<float> unit(0, 1);
  for (int i = 0; i < n; ++i) {
    params[i] = instanceParams(prim, count, rng, unit(rng) < degenerate_share);
    channels[i].resize(static_cast<size_t>(count) * layout.count);
    for (float& c : channels[i]) c = unit(rng);
  }
  std::vector<SetupInput> in(n);
  std::vector<std::vector<uint32_t>> scalar_records(n, std::vector<uint32_t>(words + 1, 0xdeadbeefu));
  std::vector<std::vector<uint32_t>> batch_records = scalar_records;
  std::vector<uint32_t*> records(n);
  std::vector<SetupOutput> scalar_out(n), batch_out(n);
  SetupExecutor scalar;
  for (int i = 0; i < n; ++i) {
    in[i] = SetupInput{params[i].data(), channels[i].data(), &layout, &state, count, nullptr, 0};
    records[i] = batch_records[i].data();
    scalar_out[i] = scalar.run(prim, in[i], scalar_records[i].data());
  }
  BatchSetupExecutor batch;
  batch.batch_callers = true;
  batch.use_native = sweep.native;
  batch.run(prim, in.data(), n, records.data(), batch_out.data());
  for (int i = 0; i < n; ++i) {
    const SetupOutput &a = scalar_out[i], &b = batch_out[i];
    const std::string what = prim.name + " instance " + std::to_string(i) + " (seed " + std::to_string(seed) + ")";
    EXPECT_EQ(a.killed, b.killed) << what;
    EXPECT_EQ(a.iteration_cap_hit, b.iteration_cap_hit) << what;
    EXPECT_EQ(a.has_bound, b.has_bound) << what;
    EXPECT_EQ(a.back_facing, b.back_facing) << what;
    EXPECT_EQ(a.instructions, b.instructions) << what;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(u(a.bound[k]), u(b.bound[k])) << what << ", bound " << k;
    EXPECT_EQ(a.has_depth_bound, b.has_depth_bound) << what;
    for (int k = 0; k < 2; ++k) EXPECT_EQ(u(a.depth_bound[k]), u(b.depth_bound[k])) << what << ", depth bound " << k;
    EXPECT_EQ(scalar_records[i], batch_records[i]) << what << ": records differ";
  }
  EXPECT_EQ(batch.counters.lanes_batched + batch.counters.lanes_resumed + batch.counters.lanes_scalar,
            static_cast<uint64_t>(n));
  sweep.compared += static_cast<uint64_t>(n);
  sweep.batched += batch.counters.lanes_batched;
  sweep.resumed += batch.counters.lanes_resumed;
  sweep.in_native += batch.counters.lanes_native;
  if (!sweep.native) {
    EXPECT_EQ(batch.counters.batches_native, 0u);
  }
}

// Native code compiled on a program's first batch, for the test's length.
class CompileAtOnce {
 public:
  CompileAtOnce() : saved_(NativeProgramCache::instance().setupThreshold()) {
    NativeProgramCache::instance().setSetupThreshold(0);
  }
  ~CompileAtOnce() { NativeProgramCache::instance().setSetupThreshold(saved_); }

 private:
  uint64_t saved_;
};

// compareBoth's sweep over every built-in, interpreted or in native code.
void sweepEveryBuiltin(bool native) {
  ASSERT_TRUE(builtinPrimitives().errors.empty()) << builtinPrimitives().errors;
  const RasterState state = testState();
  const RasterState capped = testState(3);  // loops of more than 3 iterations stop
  const ChannelLayout one = ChannelLayout::ofKind(4, InterpKind::PerspectiveLinear), split = splitLayout();
  const ChannelLayout none;
  int primitives = 0;
  uint64_t in_native = 0;
  for (const CompiledPrimitive* prim : everyBuiltin()) {
    Sweep sweep;
    sweep.native = native;
    const double compile_ms = NativeProgramCache::instance().stats().milliseconds;
    for (uint32_t seed = 1; seed <= 3; ++seed) {
      const ChannelLayout& layout = prim->is_interpolator ? none : seed == 2 ? split : one;
      compareBoth(*prim, layout, state, 53, seed, 0.0, sweep);    // plausible instances
      compareBoth(*prim, layout, state, 53, seed, 0.35, sweep);   // about a third broken
      compareBoth(*prim, layout, capped, 21, seed, 0.2, sweep);
    }
    // Plausible instances mostly take one path: most lanes must have run batched (a primitive
    // that calls others, up to its first call).
    const uint64_t exercised = BatchSetupExecutor::batchable(*prim) ? sweep.batched : sweep.resumed;
    EXPECT_GT(exercised, sweep.compared / 3) << prim->name << ": the batch path was hardly exercised ("
                                             << sweep.batched << " batched, " << sweep.resumed << " resumed of "
                                             << sweep.compared << " lanes)";
    std::printf("%-20s %5llu lanes: %5llu finished batched (%5llu in native code, compiled in %.0f ms), %5llu "
                "resumed scalar\n",
                prim->name.c_str(), static_cast<unsigned long long>(sweep.compared),
                static_cast<unsigned long long>(sweep.batched), static_cast<unsigned long long>(sweep.in_native),
                NativeProgramCache::instance().stats().milliseconds - compile_ms,
                static_cast<unsigned long long>(sweep.resumed));
    in_native += sweep.in_native;
    ++primitives;
  }
  EXPECT_GE(primitives, 30);
  if (native) {
    // Native code ran batches to their end: the comparison above compared it.
    EXPECT_GT(in_native, 0u);
    const NativeCacheStats stats = NativeProgramCache::instance().stats();
    std::printf("native code: %llu functions compiled in %.0f ms\n", static_cast<unsigned long long>(stats.compiled),
                stats.milliseconds);
  }
}

}  // namespace

TEST(SetupBatch, EveryBuiltinPrimitiveMatchesScalarSetupBitForBit) { sweepEveryBuiltin(false); }

TEST(SetupBatch, EveryBuiltinPrimitiveMatchesScalarSetupBitForBitInNativeCode) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  CompileAtOnce at_once;
  sweepEveryBuiltin(true);
}

TEST(SetupBatch, BatchMixingKilledAndLiveInstances) {
  const CompiledPrimitive& prim = builtin("sphere_impostors");
  const RasterState state = testState();
  const ChannelLayout layout = ChannelLayout::ofKind(4, InterpKind::PerspectiveLinear);
  std::mt19937 rng(11);
  std::vector<std::vector<uint32_t>> params(kSetupBatchLanes);
  std::vector<float> channels(4, 0.5f);
  const size_t radius = static_cast<size_t>(prim.findParam("radius")->offset);
  const float radii[] = {-1.0f, 0.0f, std::numeric_limits<float>::quiet_NaN()};
  const int killed_lanes[] = {2, 5, 11};
  for (int l = 0; l < kSetupBatchLanes; ++l) params[l] = instanceParams(prim, 1, rng, false);
  for (int k = 0; k < 3; ++k) params[killed_lanes[k]][radius] = u(radii[k]);
  const size_t words = SetupExecutor::recordWords(prim, 4);
  std::vector<std::vector<uint32_t>> want(kSetupBatchLanes, std::vector<uint32_t>(words, 0u)), got = want;
  SetupInput in[kSetupBatchLanes];
  uint32_t* records[kSetupBatchLanes];
  SetupOutput scalar_out[kSetupBatchLanes], batch_out[kSetupBatchLanes];
  SetupExecutor scalar;
  for (int l = 0; l < kSetupBatchLanes; ++l) {
    in[l] = SetupInput{params[l].data(), channels.data(), &layout, &state, 1, nullptr, 0};
    records[l] = got[l].data();
    scalar_out[l] = scalar.run(prim, in[l], want[l].data());
  }
  BatchSetupExecutor batch;
  batch.run(prim, in, kSetupBatchLanes, records, batch_out);
  for (int l = 0; l < kSetupBatchLanes; ++l) {
    const bool should_die = l == 2 || l == 5 || l == 11;
    EXPECT_EQ(scalar_out[l].killed, should_die) << "lane " << l;
    EXPECT_EQ(batch_out[l].killed, should_die) << "lane " << l;
    EXPECT_EQ(scalar_out[l].instructions, batch_out[l].instructions) << "lane " << l;
    EXPECT_EQ(scalar_out[l].has_bound, batch_out[l].has_bound) << "lane " << l;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(u(scalar_out[l].bound[k]), u(batch_out[l].bound[k])) << "lane " << l;
    if (!should_die) {
      EXPECT_EQ(want[l], got[l]) << "lane " << l;
    }
  }
  // The three killed lanes left the batch at the radius test; the 13 others finished in it.
  EXPECT_EQ(batch.counters.batches, 1u);
  EXPECT_EQ(batch.counters.lanes_resumed, 3u);
  EXPECT_EQ(batch.counters.lanes_batched, 13u);
  EXPECT_LT(scalar_out[2].instructions, scalar_out[0].instructions);
}
