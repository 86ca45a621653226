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

namespace detail {
extern std::atomic<const LaneKernelTable*> active_lane_kernels;
}

// The kernel of `op` (a value-producing op, up to Op::Mov) for operand shape `wide`.
inline LaneKernel laneKernel(Op op, unsigned wide) {
  return (*detail::active_lane_kernels.load(std::memory_order_relaxed))[static_cast<size_t>(op)][wide];
}

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
