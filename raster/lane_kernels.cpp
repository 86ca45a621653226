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

static_assert(kLanes % 16 == 0 && kLanes <= 64, "lane masks are 64-bit, handled 8 and 16 lanes at a time");

// The loop every kernel runs: with OP and WIDE compile-time constants the switch in
// evalScalar folds away and GCC vectorizes the loop for the function's instruction set.
#define PF_LANE_LOOP                                                                                       \
  for (int i = 0; i < kLanes; ++i)                                                                        \
    r[i] = evalScalar(OP, (WIDE & 1) ? a[i] : a[0], (WIDE & 2) ? b[i] : b[0], (WIDE & 4) ? c[i] : c[0], \
                      (WIDE & 8) ? d[i] : d[0], imm)

#define PF_LANE_PARAMS \
  uint32_t *__restrict r, const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d, uint32_t imm

// The mask loops: written so that GCC vectorizes them (byte flags, then 8 flags packed per
// byte with a multiply), the same source for every set.
#define PF_NONZERO_BODY                                                                   \
  uint8_t flag[kLanes];                                                                   \
  for (int i = 0; i < kLanes; ++i) flag[i] = v[i] != 0;                                   \
  uint64_t m = 0;                                                                         \
  for (int g = 0; g < kLanes / 8; ++g) {                                                  \
    uint64_t eight;                                                                       \
    std::memcpy(&eight, flag + 8 * g, 8);                                                 \
    m |= ((eight * 0x0102040810204080ull) >> 56) << (8 * g); /* bit j of the byte = flag j */ \
  }                                                                                       \
  return m

// Per group of 8 lanes, each lane tests its own constant bit of the group's byte: a vector
// AND with (1, 2, 4, ..., 128) and a compare, where a shift by the lane's index is not.
#define PF_BLEND_BODY                                                       \
  for (int g = 0; g < kLanes / 8; ++g) {                                    \
    const uint32_t bits = static_cast<uint32_t>(mask >> (8 * g)) & 0xffu;   \
    for (int j = 0; j < 8; ++j) {                                           \
      const uint32_t m = (bits & (1u << j)) ? ~0u : 0u;                     \
      d[8 * g + j] = (s[8 * g + j] & m) | (d[8 * g + j] & ~m);              \
    }                                                                       \
  }

struct Baseline {
  template <Op OP, unsigned WIDE>
  static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  static uint64_t nonzero(const uint32_t* v) { PF_NONZERO_BODY; }
  static void blend(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) { PF_BLEND_BODY }
};

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_LANE_ISAS 1
#include <immintrin.h>
struct Avx2 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("avx2")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  [[gnu::target("avx2")]] static uint64_t nonzero(const uint32_t* v) { PF_NONZERO_BODY; }
  [[gnu::target("avx2")]] static void blend(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) {
    PF_BLEND_BODY
  }
};
// 512-bit vectors: GCC's generic tuning would otherwise keep AVX-512 code at 256 bits.
struct Avx512 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  // AVX-512 has mask registers for exactly these: a test per 16 lanes, a masked move.
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static uint64_t nonzero(const uint32_t* v) {
    uint64_t m = 0;
    for (int g = 0; g < kLanes / 16; ++g) {
      const __m512i x = _mm512_loadu_si512(v + 16 * g);
      m |= static_cast<uint64_t>(_mm512_test_epi32_mask(x, x)) << (16 * g);
    }
    return m;
  }
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void blend(uint32_t* __restrict d,
                                                                             const uint32_t* __restrict s,
                                                                             uint64_t mask) {
    for (int g = 0; g < kLanes / 16; ++g)
      _mm512_mask_storeu_epi32(d + 16 * g, static_cast<__mmask16>(mask >> (16 * g)), _mm512_loadu_si512(s + 16 * g));
  }
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

constexpr LaneKernelTable kBaselineKernels = tableOf<Baseline>();
constexpr LaneIsaTables kBaseline{&kBaselineKernels, {&Baseline::nonzero, &Baseline::blend}};
#ifdef PF_LANE_ISAS
constexpr LaneKernelTable kAvx2Kernels = tableOf<Avx2>();
constexpr LaneKernelTable kAvx512Kernels = tableOf<Avx512>();
constexpr LaneIsaTables kAvx2{&kAvx2Kernels, {&Avx2::nonzero, &Avx2::blend}};
constexpr LaneIsaTables kAvx512{&kAvx512Kernels, {&Avx512::nonzero, &Avx512::blend}};
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

const LaneIsaTables* tableFor(LaneIsa isa) {
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

const LaneIsaTables* initialTable() {
  current_isa = initialIsa();
  return tableFor(current_isa);
}

}  // namespace

namespace detail {
std::atomic<const LaneIsaTables*> active_lane_isa{initialTable()};
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
  detail::active_lane_isa.store(tableFor(isa), std::memory_order_relaxed);
  return true;
}

}  // namespace pf
