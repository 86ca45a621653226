// The lane kernels compiled for each instruction set (raster/lane_kernels.h) compute the same
// bits as the baseline ones: every value-producing op, every operand shape, on random and
// special inputs (NaN, infinities, signed zeros, subnormals, extreme ints), on every
// instruction set this machine runs; and the mask loops (lanes set, blend) and the depth loads
// do what they say. (The reference interpreter checks the chosen set against
// scalar code in every language test; this checks the sets against each other everywhere.)
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "compiler/fixed_point.h"
#include "compiler/scalar_ops.h"
#include "raster/lane_kernels.h"
#include "raster/limits.h"
#include "raster/setup_batch.h"

using namespace pf;

namespace {

// Restores the instruction set in use when the test started.
struct IsaGuard {
  LaneIsa saved = laneIsa();
  ~IsaGuard() { setLaneIsa(saved); }
};

std::vector<uint32_t> operandLanes(std::mt19937& rng, int which) {
  const float f_special[] = {0.0f, -0.0f, 1.0f, -1.0f, 0.5f, std::numeric_limits<float>::infinity(),
                             -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::denorm_min(), 3.4e38f, -1e-30f, 2.5f};
  const uint32_t i_special[] = {0u, 1u, 0xffffffffu, 0x80000000u, 0x7fffffffu, 2u, 0xfffffffeu};
  std::uniform_real_distribution<float> mag(-40.0f, 40.0f);
  std::vector<uint32_t> v(kLanes);
  for (int i = 0; i < kLanes; ++i) {
    switch ((rng() + static_cast<unsigned>(which)) % 5) {
      case 0: v[i] = std::bit_cast<uint32_t>(f_special[rng() % std::size(f_special)]); break;
      case 1: v[i] = i_special[rng() % std::size(i_special)]; break;
      case 2: v[i] = static_cast<uint32_t>(rng()); break;
      case 3: v[i] = static_cast<uint32_t>(rng() % 7) - 3u; break;  // small ints, bools
      default: v[i] = std::bit_cast<uint32_t>(std::ldexp(mag(rng) > 0 ? 1.0f : -1.0f, 0) * std::exp2(mag(rng)));
    }
  }
  return v;
}

// Equal bits, or both NaN: which NaN an operation on two NaNs returns is not IEEE-754's to say,
// and vector code may commute an addition. No NaN's payload or sign reaches an image (a NaN
// depth fails every test, a NaN colour clamps the same), so only NaN-ness must agree.
bool sameValue(uint32_t a, uint32_t b) {
  const auto nan = [](uint32_t x) { return (x & 0x7f800000u) == 0x7f800000u && (x & 0x007fffffu) != 0; };
  return a == b || (nan(a) && nan(b));
}

// Ops whose result is a float (where NaN-ness is the comparison); the others compare bits.
bool floatResult(Op op) {
  return op <= Op::FNoise || op == Op::I2F || op == Op::CrossSign || op == Op::QToF;
}

}  // namespace

TEST(LaneKernels, EveryInstructionSetComputesTheBaselineBits) {
  IsaGuard guard;
  const std::vector<LaneIsa> isas = availableLaneIsas();
  ASSERT_FALSE(isas.empty());
  ASSERT_EQ(isas.front(), LaneIsa::Baseline);
  for (LaneIsa isa : isas) std::printf("lane kernels available: %s\n", laneIsaName(isa));
  std::mt19937 rng(2026);
  // imm matters only to the fixed-point ops: a few formats and both words.
  const uint32_t imms[] = {0u, static_cast<uint32_t>(fixedImm({16, 8}, 1)), static_cast<uint32_t>(fixedImm({64, 32}, 0)),
                           static_cast<uint32_t>(fixedImm({64, 32}, 1)), static_cast<uint32_t>(fixedImm({7, 7}, 0))};
  size_t compared = 0;
  for (size_t op = 0; op < kLaneKernelOps; ++op) {
    for (unsigned wide = 0; wide < 16; ++wide) {
      for (int trial = 0; trial < 3; ++trial) {
        std::vector<uint32_t> in[4];
        for (int k = 0; k < 4; ++k) in[k] = operandLanes(rng, k + trial);
        // QConv's c is a fraction-bit count (0..64) in the programs the compiler makes.
        if (static_cast<Op>(op) == Op::QConv)
          for (uint32_t& x : in[2]) x %= 65u;
        const uint32_t imm = imms[rng() % std::size(imms)];
        std::vector<uint32_t> want(kLanes), got(kLanes);
        ASSERT_TRUE(setLaneIsa(LaneIsa::Baseline));
        laneKernel(static_cast<Op>(op), wide)(want.data(), in[0].data(), in[1].data(), in[2].data(), in[3].data(), imm);
        for (LaneIsa isa : isas) {
          ASSERT_TRUE(setLaneIsa(isa));
          laneKernel(static_cast<Op>(op), wide)(got.data(), in[0].data(), in[1].data(), in[2].data(), in[3].data(), imm);
          for (int i = 0; i < kLanes; ++i)
            ASSERT_TRUE(floatResult(static_cast<Op>(op)) ? sameValue(want[i], got[i]) : want[i] == got[i])
                << want[i] << " vs " << got[i] << ": " << opName(static_cast<Op>(op)) << " operand shape " << wide << " on "
                                       << laneIsaName(isa) << ", lane " << i << " (a " << in[0][i] << " b "
                                       << in[1][i] << " c " << in[2][i] << " d " << in[3][i] << ")";
          ++compared;
        }
      }
    }
  }
  EXPECT_GT(compared, kLaneKernelOps * 16 * 3 - 1);
}

TEST(LaneKernels, BatchedSetupKernelsComputeTheBaselineBitsOnEverySet) {
  IsaGuard guard;
  std::mt19937 rng(7);
  for (size_t op = 0; op < kLaneKernelOps; ++op) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<uint32_t> in[4];
      for (int k = 0; k < 4; ++k) {
        in[k] = operandLanes(rng, k + trial);
        in[k].resize(kSetupBatchLanes);
      }
      if (static_cast<Op>(op) == Op::QConv)
        for (uint32_t& x : in[2]) x %= 65u;
      const uint32_t imm = trial % 2 ? static_cast<uint32_t>(fixedImm({40, 12}, trial / 2)) : 0u;
      std::vector<uint32_t> want(kSetupBatchLanes), got(kSetupBatchLanes);
      ASSERT_TRUE(setLaneIsa(LaneIsa::Baseline));
      batchKernel(static_cast<Op>(op))(want.data(), in[0].data(), in[1].data(), in[2].data(), in[3].data(), imm);
      for (LaneIsa isa : availableLaneIsas()) {
        ASSERT_TRUE(setLaneIsa(isa));
        // In place, too: dst may be an operand.
        got = in[1];
        batchKernel(static_cast<Op>(op))(got.data(), in[0].data(), got.data(), in[2].data(), in[3].data(), imm);
        for (int l = 0; l < kSetupBatchLanes; ++l)
          ASSERT_TRUE(floatResult(static_cast<Op>(op)) ? sameValue(want[l], got[l]) : want[l] == got[l])
              << opName(static_cast<Op>(op)) << " on " << laneIsaName(isa) << ", lane " << l;
      }
    }
  }
}

TEST(LaneKernels, MaskLoopsAgreeWithTheirDefinition) {
  IsaGuard guard;
  std::mt19937_64 rng(99);
  for (LaneIsa isa : availableLaneIsas()) {
    ASSERT_TRUE(setLaneIsa(isa));
    for (int trial = 0; trial < 200; ++trial) {
      // Sparse, dense, all and none.
      const uint64_t masks[] = {rng(), rng() & rng() & rng(), ~0ull, 0ull, rng() | rng()};
      const uint64_t mask = masks[trial % 5];
      std::vector<uint32_t> v(kLanes), d(kLanes), s(kLanes), want(kLanes);
      uint64_t want_nonzero = 0;
      for (int i = 0; i < kLanes; ++i) {
        v[i] = (mask >> i) & 1u ? static_cast<uint32_t>(rng() | 1u) << (rng() % 32) : 0u;
        if (v[i] == 0 && (mask >> i) & 1u) v[i] = 0x80000000u;  // -0.0f is not zero here
        want_nonzero |= static_cast<uint64_t>(v[i] != 0) << i;
        d[i] = static_cast<uint32_t>(rng());
        s[i] = static_cast<uint32_t>(rng());
        want[i] = (mask >> i) & 1u ? s[i] : d[i];
      }
      EXPECT_EQ(laneMaskOps().nonzero(v.data()), want_nonzero) << laneIsaName(isa);
      EXPECT_EQ(want_nonzero, mask) << laneIsaName(isa);
      laneMaskOps().blend(d.data(), s.data(), mask);
      EXPECT_EQ(d, want) << laneIsaName(isa);
    }
  }
}

// A gang block's record spread (LaneMaskOps::spread) on every set against its definition: word
// k of member m in lanes [first[m], first[m + 1]) -- members of one lane, of 64, of lengths
// that cut the 8- and 16-lane groups anywhere, and members with no lane (first equal).
TEST(LaneKernels, GangRecordSpreadMatchesItsDefinition) {
  IsaGuard guard;
  std::mt19937 rng(17);
  for (LaneIsa isa : availableLaneIsas()) {
    ASSERT_TRUE(setLaneIsa(isa));
    for (int trial = 0; trial < 300; ++trial) {
      // Member boundaries: 0, then sorted cuts (repeats give members without a lane).
      const int members = 1 + static_cast<int>(rng() % (trial % 3 == 0 ? 64 : 6));
      std::vector<int> first(static_cast<size_t>(members), 0);
      for (int m = 1; m < members; ++m) first[static_cast<size_t>(m)] = static_cast<int>(rng() % kLanes);
      std::sort(first.begin(), first.end());
      const size_t words = 1 + rng() % 45;
      std::vector<std::vector<uint32_t>> records(static_cast<size_t>(members), std::vector<uint32_t>(words));
      std::vector<const uint32_t*> record_ptrs;
      for (auto& r : records) {
        for (uint32_t& w : r) w = static_cast<uint32_t>(rng());
        record_ptrs.push_back(r.data());
      }
      std::vector<uint32_t> got(words * kLanes, 0xdeadbeefu), want(words * kLanes, 0xdeadbeefu);
      for (int m = 0; m < members; ++m) {
        const int l1 = m + 1 < members ? first[static_cast<size_t>(m) + 1] : kLanes;
        for (size_t k = 0; k < words; ++k)
          for (int l = first[static_cast<size_t>(m)]; l < l1; ++l)
            want[k * kLanes + static_cast<size_t>(l)] = records[static_cast<size_t>(m)][k];
      }
      laneMaskOps().spread(got.data(), record_ptrs.data(), first.data(), members, words);
      ASSERT_EQ(got, want) << laneIsaName(isa) << ", trial " << trial << ", " << members << " members";
    }
  }
}

// The fused multiply-and-add kernels (the decoder's FusedForm) compute, on every set and for
// every operand shape, the bits of the FMul and then the FAdd / FSub they stand for.
TEST(LaneKernels, FusedProductsAreTheTwoInstructionsBits) {
  IsaGuard guard;
  std::mt19937 rng(5);
  for (LaneIsa isa : availableLaneIsas()) {
    ASSERT_TRUE(setLaneIsa(isa));
    for (size_t form = 0; form < kFusedForms; ++form)
      for (unsigned wide = 0; wide < 8; ++wide)
        for (int trial = 0; trial < 4; ++trial) {
          const std::vector<uint32_t> a = operandLanes(rng, trial), b = operandLanes(rng, trial + 1),
                                      c = operandLanes(rng, trial + 2), zero(kLanes, 0u);
          std::vector<uint32_t> got(kLanes);
          (*laneIsaTables().fused)[form][wide](got.data(), a.data(), b.data(), c.data(), zero.data(), 0);
          for (int i = 0; i < kLanes; ++i) {
            const uint32_t m = evalScalar(Op::FMul, (wide & 1) ? a[i] : a[0], (wide & 2) ? b[i] : b[0], 0u);
            const uint32_t t = (wide & 4) ? c[i] : c[0];
            const FusedForm f = static_cast<FusedForm>(form);
            const uint32_t want = f == FusedForm::ProductPlus    ? evalScalar(Op::FAdd, m, t, 0u)
                                  : f == FusedForm::PlusProduct  ? evalScalar(Op::FAdd, t, m, 0u)
                                  : f == FusedForm::ProductMinus ? evalScalar(Op::FSub, m, t, 0u)
                                                                 : evalScalar(Op::FSub, t, m, 0u);
            EXPECT_TRUE(sameValue(got[i], want))
                << laneIsaName(isa) << " form " << form << " shape " << wide << " lane " << i;
          }
        }
  }
}

// The depth loads (load_block: an aligned block's rows; gather: packed lanes' pixels) give the
// value under every lane in the mask and 0 elsewhere, and read nothing outside the mask: the
// block hangs past the end of an exactly sized buffer, and the lanes outside the mask of the
// gather carry offsets far outside it.
TEST(LaneKernels, DepthLoadsReadTheMaskedLanesOnly) {
  IsaGuard guard;
  std::mt19937_64 rng(7);
  constexpr int kW = 13, kH = 11;
  std::vector<float> depth(static_cast<size_t>(kW) * kH);
  for (float& z : depth) z = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
  for (LaneIsa isa : availableLaneIsas()) {
    ASSERT_TRUE(setLaneIsa(isa));
    for (int trial = 0; trial < 100; ++trial) {
      // The block at (8, 8): 5 columns and 3 rows inside the buffer.
      uint64_t inside = 0;
      for (int i = 0; i < kLanes; ++i)
        if (8 + i % kBlockSize < kW && 8 + i / kBlockSize < kH) inside |= 1ull << i;
      const uint64_t mask = inside & (trial % 3 == 0 ? ~0ull : rng());
      std::vector<uint32_t> got(kLanes, 0xdeadbeefu);
      laneMaskOps().load_block(got.data(), depth.data() + 8 * kW + 8, kW, mask);
      for (int i = 0; i < kLanes; ++i) {
        const uint32_t want =
            (mask >> i) & 1u ? std::bit_cast<uint32_t>(depth[static_cast<size_t>(8 + i / kBlockSize) * kW + 8 + i % kBlockSize]) : 0u;
        EXPECT_EQ(got[i], want) << laneIsaName(isa) << " lane " << i;
      }
      // Packed lanes: any pixels; outside the mask, offsets no read may follow.
      const uint64_t gather_mask = trial % 4 == 0 ? ~0ull : rng();
      std::vector<int32_t> offset(kLanes);
      for (int i = 0; i < kLanes; ++i)
        offset[i] = (gather_mask >> i) & 1u ? static_cast<int32_t>(rng() % depth.size()) : 0x7fff0000 - i;
      std::fill(got.begin(), got.end(), 0xdeadbeefu);
      laneMaskOps().gather(got.data(), depth.data(), offset.data(), gather_mask);
      for (int i = 0; i < kLanes; ++i) {
        const uint32_t want = (gather_mask >> i) & 1u ? std::bit_cast<uint32_t>(depth[static_cast<size_t>(offset[i])]) : 0u;
        EXPECT_EQ(got[i], want) << laneIsaName(isa) << " lane " << i;
      }
    }
  }
}

TEST(LaneKernels, PinningAnUnavailableSetIsRefused) {
  IsaGuard guard;
  const std::vector<LaneIsa> isas = availableLaneIsas();
  for (LaneIsa isa : {LaneIsa::Baseline, LaneIsa::Avx2, LaneIsa::Avx512}) {
    const bool available = std::find(isas.begin(), isas.end(), isa) != isas.end();
    EXPECT_EQ(setLaneIsa(isa), available) << laneIsaName(isa);
    if (available) {
      EXPECT_EQ(laneIsa(), isa);
    }
  }
}
