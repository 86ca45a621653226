// Block rejection's walk as native code (compiler/native/interval_codegen.h), of one region or of
// several at once (a tile's 4, a region's 16 blocks), gives the interpreter's verdict (raster/block_rejection.cpp) --
// rejected, accepted or unknown -- for
// every built-in primitive's pixel program and its covered variant, and for a probe of edge,
// discriminant, ratio and square-root tests, over random uniform records (NaN, infinities,
// zeros, values through pixel centres among them) and regions.
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <random>
#include <vector>

#include "compile_helpers.h"
#include "rejection_probe.h"
#include "compiler/builtin_primitives.h"
#include "compiler/native/native_cache.h"
#include "raster/block_rejection.h"
#include "raster/native_blocks.h"

using namespace pf;
using namespace pf::test;

namespace {

// The shared probe, and one of abs, min, max, floor and an int conversion.
const std::string kProbe = std::string(kRejectionProbe) + R"(
primitive probe2(float k[1][4]; varying float X, Y; inout varying float Z) {
    float dx = X - k[0][0];
    float dy = Y - k[0][1];
    if (abs(dx) > k[0][2] || min(dx, dy) > 3 || max(dx, dy) < -3 || floor(dx) == k[0][3]) return;
    int i = int(dx);
    if (i * 2 + 1 < 0 || i == 7) return;
    Z = 0.5;
}
)";

uint32_t randomWord(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 19);
  std::uniform_real_distribution<float> u(-40.0f, 40.0f);
  switch (kind(rng)) {
    case 0: return std::bit_cast<uint32_t>(std::numeric_limits<float>::quiet_NaN());
    case 1: return std::bit_cast<uint32_t>(std::numeric_limits<float>::infinity());
    case 2: return std::bit_cast<uint32_t>(-std::numeric_limits<float>::infinity());
    case 3: return 0u;
    case 4: return 1u;  // a true bool, a small int
    case 5: return std::bit_cast<uint32_t>(std::round(u(rng)) + 0.5f);
    default: return std::bit_cast<uint32_t>(u(rng));
  }
}

// Counts of each verdict the two walks agreed on; for the walk over several regions at once, the
// regions it left undecided where the interpreter decided (where they part ways at a jump).
struct Agreed {
  int rejected = 0, accepted = 0, unknown = 0;
  int parted = 0;
};

// `setup`: the records come from its setup program run on random parameters (else they are
// random words).
Agreed compareWalks(const PixelProgram& program, const std::string& what, int trials, uint32_t seed,
                    const CompiledPrimitive* setup = nullptr) {
  Agreed agreed;
  if (program.last_early_retire < 0) return agreed;
  std::mt19937 rng(seed);
  BlockRejection interpreted;
  NativeBlocks native;
  RasterState state;
  state.vp_scale_x = state.vp_offset_x = state.vp_scale_y = state.vp_offset_y = 128;
  std::uniform_int_distribution<int> corner(-48, 48);
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<uint32_t> record(program.num_uniform_slots + 1);
    for (uint32_t& w : record) w = randomWord(rng);
    if (setup) {
      std::vector<uint32_t> params(static_cast<size_t>(setup->param_floats));
      for (uint32_t& w : params) w = randomWord(rng);
      record.assign(SetupExecutor::recordWords(*setup, 0) + 1, 0u);
      ChannelLayout layout = ChannelLayout::ofKind(0, InterpKind::PerspectiveLinear);
      SetupExecutor executor;
      if (executor.run(*setup, SetupInput{params.data(), nullptr, &layout, &state, 1}, record.data()).killed) continue;
    }
    const int x0 = corner(rng) / 8 * 8, y0 = corner(rng) / 8 * 8;
    const int size = trial % 3 == 0 ? 8 : 32;
    const RegionVerdict want = interpreted.verdict(program, record.data(), state, x0, y0, x0 + size, y0 + size);
    const double region[4] = {x0 + 0.5, x0 + size - 0.5, y0 + 0.5, y0 + size - 0.5};
    uint32_t got = 0;
    if (!native.verdict(program, record.data(), state, region, got)) {
      ADD_FAILURE() << what << ": no native walk";
      return agreed;
    }
    EXPECT_EQ(static_cast<uint32_t>(want), got) << what << ", trial " << trial << " at (" << x0 << ", " << y0 << ")";
    agreed.rejected += want == RegionVerdict::Rejected;
    agreed.accepted += want == RegionVerdict::Accepted;
    agreed.unknown += want == RegionVerdict::Unknown;
    // The walks over kNativeRegionLanes and kNativeVerdictLanes regions at once, each its own
    // size and place around this one: each region's verdict the interpreter's, or undecided
    // where it parted ways.
    for (const int lanes : {kNativeRegionLanes, kNativeVerdictLanes}) {
      double regions[4][kNativeVerdictLanes];
      RegionVerdict wanted[kNativeVerdictLanes];
      for (int i = 0; i < lanes; ++i) {
        const int rx = i == 0 ? x0 : corner(rng) / 8 * 8, ry = i == 0 ? y0 : corner(rng) / 8 * 8;
        const int rsize = i == 0 ? size : (i % 4 == 0 ? 32 : 8);
        regions[0][i] = rx + 0.5;
        regions[1][i] = rx + rsize - 0.5;
        regions[2][i] = ry + 0.5;
        regions[3][i] = ry + rsize - 0.5;
        wanted[i] = interpreted.verdict(program, record.data(), state, rx, ry, rx + rsize, ry + rsize);
      }
      // (Bound by bound, `lanes` apart.)
      double packed[4 * kNativeVerdictLanes];
      for (int k = 0; k < 4; ++k)
        for (int i = 0; i < lanes; ++i) packed[k * lanes + i] = regions[k][i];
      uint8_t verdicts[kNativeVerdictLanes];
      if (!native.verdicts(program, record.data(), state, lanes, packed, verdicts)) {
        ADD_FAILURE() << what << ": no native walk over " << lanes << " regions";
        return agreed;
      }
      for (int i = 0; i < lanes; ++i) {
        if (verdicts[i] == static_cast<uint8_t>(wanted[i])) continue;
        EXPECT_EQ(verdicts[i], 0) << what << ", trial " << trial << ", " << lanes << " lanes, region " << i << " at ("
                                  << regions[0][i] << ", " << regions[2][i] << "): decided otherwise than the interpreter";
        ++agreed.parted;
      }
    }
  }
  return agreed;
}

}  // namespace

TEST(NativeRejection, TheProbesVerdictsAreTheInterpreters) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setWalkThreshold(0);
  Compiled c = compile(kProbe);
  ASSERT_TRUE(c.ok) << c.diagnostics;
  const Agreed a = compareWalks(c.find("probe")->pixel, "probe", 4000, 7, c.find("probe"));
  // The random records reach all three verdicts (the comparison is not of unknowns alone).
  EXPECT_GT(a.rejected, 100);
  EXPECT_GT(a.accepted, 10);
  EXPECT_GT(a.unknown, 100);
  // (The probes branch on varying conditions only: no region parts from the others.)
  EXPECT_EQ(a.parted, 0);
  const Agreed b = compareWalks(c.find("probe2")->pixel, "probe2", 2000, 9, c.find("probe2"));
  EXPECT_GT(b.rejected + b.accepted, 100);
  EXPECT_EQ(b.parted, 0);
}

TEST(NativeRejection, EveryBuiltinPrimitivesVerdictsAreTheInterpreters) {
  if (!nativeCodeAvailable()) GTEST_SKIP() << "native code is unavailable here";
  NativeProgramCache::instance().setWalkThreshold(0);
  int walked = 0;
  for (const auto& prim : builtinPrimitives().in_order) {
    if (nativeVerdictSupports(prim->pixel)) {
      const Agreed a = compareWalks(prim->pixel, prim->name, 600, 3);
      // Regions part ways only at jumps on uniform values, which every region takes alike.
      EXPECT_EQ(a.parted, 0) << prim->name;
      ++walked;
    }
    if (prim->pixel.covered && nativeVerdictSupports(*prim->pixel.covered))
      compareWalks(*prim->pixel.covered, prim->name + " (covered)", 200, 5);
  }
  EXPECT_GE(walked, 5);
}
