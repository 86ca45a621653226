// The lane kernels, compiled for three instruction sets (see lane_kernels.h).
#include "raster/lane_kernels.h"

#include <array>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "compiler/scalar_ops.h"
#include "raster/limits.h"

namespace pf {
namespace {

// The loop every kernel runs: with OP and WIDE compile-time constants the switch in
// evalScalar folds away and GCC vectorizes the loop for the function's instruction set.
#define PF_LANE_LOOP                                                                                       \
  for (int i = 0; i < kLanes; ++i)                                                                        \
    r[i] = evalScalar(OP, (WIDE & 1) ? a[i] : a[0], (WIDE & 2) ? b[i] : b[0], (WIDE & 4) ? c[i] : c[0], \
                      (WIDE & 8) ? d[i] : d[0], imm)

#define PF_LANE_PARAMS \
  uint32_t *__restrict r, const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d, uint32_t imm

struct Baseline {
  template <Op OP, unsigned WIDE>
  static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
};

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_LANE_ISAS 1
struct Avx2 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("avx2")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
};
// 512-bit vectors: GCC's generic tuning would otherwise keep AVX-512 code at 256 bits.
struct Avx512 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
};
#endif

template <class Isa, Op OP, size_t... W>
constexpr std::array<LaneKernel, 16> kernelsFor(std::index_sequence<W...>) {
  return {&Isa::template run<OP, static_cast<unsigned>(W)>...};
}

template <class Isa, size_t... I>
constexpr LaneKernelTable tableOf(std::index_sequence<I...>) {
  return {kernelsFor<Isa, static_cast<Op>(I)>(std::make_index_sequence<16>{})...};
}
template <class Isa>
constexpr LaneKernelTable tableOf() { return tableOf<Isa>(std::make_index_sequence<kLaneKernelOps>{}); }

constexpr LaneKernelTable kBaseline = tableOf<Baseline>();
#ifdef PF_LANE_ISAS
constexpr LaneKernelTable kAvx2 = tableOf<Avx2>();
constexpr LaneKernelTable kAvx512 = tableOf<Avx512>();
#endif

bool machineRuns(LaneIsa isa) {
  switch (isa) {
    case LaneIsa::Baseline: return true;
#ifdef PF_LANE_ISAS
    case LaneIsa::Avx2: return __builtin_cpu_supports("avx2");
    case LaneIsa::Avx512:  // x86-64-v4's AVX-512 subsets
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
             __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx2");
#endif
    default: return false;
  }
}

const LaneKernelTable* tableFor(LaneIsa isa) {
#ifdef PF_LANE_ISAS
  if (isa == LaneIsa::Avx2) return &kAvx2;
  if (isa == LaneIsa::Avx512) return &kAvx512;
#endif
  return &kBaseline;
}

LaneIsa initialIsa() {
  if (const char* e = std::getenv("PF_SIMD")) {
    for (LaneIsa isa : {LaneIsa::Baseline, LaneIsa::Avx2, LaneIsa::Avx512})
      if (std::strcmp(e, laneIsaName(isa)) == 0 && machineRuns(isa)) return isa;
  }
  return availableLaneIsas().back();
}

LaneIsa current_isa = LaneIsa::Baseline;

const LaneKernelTable* initialTable() {
  current_isa = initialIsa();
  return tableFor(current_isa);
}

}  // namespace

namespace detail {
std::atomic<const LaneKernelTable*> active_lane_kernels{initialTable()};
}

std::vector<LaneIsa> availableLaneIsas() {
  std::vector<LaneIsa> out;
  for (LaneIsa isa : {LaneIsa::Baseline, LaneIsa::Avx2, LaneIsa::Avx512})
    if (machineRuns(isa)) out.push_back(isa);
  return out;
}

LaneIsa laneIsa() { return current_isa; }

const char* laneIsaName(LaneIsa isa) {
  switch (isa) {
    case LaneIsa::Baseline: return "sse2";
    case LaneIsa::Avx2: return "avx2";
    case LaneIsa::Avx512: return "avx512";
  }
  return "?";
}

bool setLaneIsa(LaneIsa isa) {
  if (!machineRuns(isa)) return false;
  current_isa = isa;
  detail::active_lane_kernels.store(tableFor(isa), std::memory_order_relaxed);
  return true;
}

}  // namespace pf
