// The pixel executor's lane kernels: for every value-producing instruction and every shape of
// its operands (which are wide, one value per lane; which scalar), a loop over the kLanes lanes
// of evalScalar (compiler/scalar_ops.h). The loops are compiled three times -- for baseline
// x86-64 (SSE2), AVX2 and AVX-512 (x86-64-v4) -- and the best the machine runs is chosen at
// start-up: run-time dispatch over auto-vectorized loops (docs/architecture.md says why not
// Highway here). Every version computes the same bits (IEEE operations, no contraction; the
// reference interpreter and the per-ISA test check it).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "compiler/isa.h"

namespace pf {

using LaneKernel = void (*)(uint32_t* __restrict, const uint32_t*, const uint32_t*, const uint32_t*, const uint32_t*,
                            uint32_t imm);

enum class LaneIsa { Baseline, Avx2, Avx512 };

// Ops up to Mov produce values through kernels; operand shapes are 4 bits (a, b, c, d wide).
constexpr size_t kLaneKernelOps = static_cast<size_t>(Op::Mov) + 1;
using LaneKernelTable = std::array<std::array<LaneKernel, 16>, kLaneKernelOps>;

// The mask-handling loops the executor runs around the kernels, compiled per set as well.
struct LaneMaskOps {
  // Bit i set where lane i of v is not zero (a varying condition's lanes).
  uint64_t (*nonzero)(const uint32_t* v);
  // d = s in the lanes set in mask, d unchanged elsewhere (a merge value's write).
  void (*blend)(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask);
  // The depth buffer under a block, into a register with whole-vector stores (which the
  // program's vector loads of it can forward from).
  // Lanes outside the mask read nothing (they may lie past the framebuffer) and get 0.
  // An aligned block: lane i at base[(i / kBlockSize) * stride + i % kBlockSize].
  void (*load_block)(uint32_t* __restrict d, const float* base, int stride, uint64_t mask);
  // Packed lanes: lane i at base[offset[i]].
  void (*gather)(uint32_t* __restrict d, const float* base, const int32_t* offset, uint64_t mask);
  // A gang block's uniforms (PixelExecutor::runGangBlock): word k of records[m] into lanes
  // [first[m], first[m + 1]) of d + k * kLanes -- the last member's up to kLanes -- for every
  // k < words. Members in lane order, first[0] == 0.
  void (*spread)(uint32_t* __restrict d, const uint32_t* const* records, const int* first, int members, size_t words);
};

// The batched setup's kernels (raster/setup_batch.cpp): kSetupBatchLanes lanes, every operand
// one value per lane; dst may be one of the operands.
using BatchKernel = void (*)(uint32_t* dst, const uint32_t* a, const uint32_t* b, const uint32_t* c,
                             const uint32_t* d, uint32_t imm);
using BatchKernelTable = std::array<BatchKernel, kLaneKernelOps>;

// A multiply and the add or subtract that is its only use, as one kernel (the pixel program's
// decoder fuses them: raster/decoded_program.h): two roundings, exactly the two instructions'
// bits, one pass over the lanes. Operands (a, b) are the product's, c the other term.
enum class FusedForm : uint8_t {
  ProductPlus,   // a * b + c
  PlusProduct,   // c + a * b
  ProductMinus,  // a * b - c
  MinusProduct,  // c - a * b
};
constexpr size_t kFusedForms = 4;
using FusedKernelTable = std::array<std::array<LaneKernel, 8>, kFusedForms>;  // [form][a, b, c wide]

struct LaneIsaTables {
  const LaneKernelTable* kernels;
  LaneMaskOps masks;
  const BatchKernelTable* batch;
  const FusedKernelTable* fused;
};

namespace detail {
extern std::atomic<const LaneIsaTables*> active_lane_isa;
}

// The kernel of `op` (a value-producing op, up to Op::Mov) for operand shape `wide`.
inline LaneKernel laneKernel(Op op, unsigned wide) {
  return (*detail::active_lane_isa.load(std::memory_order_relaxed)->kernels)[static_cast<size_t>(op)][wide];
}
inline const LaneMaskOps& laneMaskOps() { return detail::active_lane_isa.load(std::memory_order_relaxed)->masks; }
inline BatchKernel batchKernel(Op op) {
  return (*detail::active_lane_isa.load(std::memory_order_relaxed)->batch)[static_cast<size_t>(op)];
}
// The tables in use, for a loop that runs many kernels (one load instead of one per kernel).
inline const LaneIsaTables& laneIsaTables() { return *detail::active_lane_isa.load(std::memory_order_relaxed); }

// The instruction sets this machine runs, best last; the one in use; its name ("sse2", "avx2",
// "avx512").
std::vector<LaneIsa> availableLaneIsas();
LaneIsa laneIsa();
const char* laneIsaName(LaneIsa isa);
// Pins the kernels to `isa` (tests and benchmarks compare them); false if the machine cannot
// run it. Call between frames. At start-up the choice is the best available, or the
// environment's PF_SIMD (sse2 / avx2 / avx512) when the machine runs it.
bool setLaneIsa(LaneIsa isa);

}  // namespace pf
