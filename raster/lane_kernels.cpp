// The lane kernels (the pixel executor's and the batched setup's), compiled for three
// instruction sets (see lane_kernels.h).
#include "raster/lane_kernels.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <utility>

#include "compiler/scalar_ops.h"
#include "raster/limits.h"
#include "raster/setup_batch.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace pf {
namespace {

static_assert(kLanes % 16 == 0 && kLanes <= 64, "lane masks are 64-bit, handled 8 and 16 lanes at a time");

// The loop every kernel runs: with OP and WIDE compile-time constants the switch in
// evalScalar folds away and GCC vectorizes the loop for the function's instruction set.
#define PF_LANE_LOOP                                                                                       \
  for (int i = 0; i < kLanes; ++i)                                                                        \
    r[i] = evalScalar(OP, (WIDE & 1) ? a[i] : a[0], (WIDE & 2) ? b[i] : b[0], (WIDE & 4) ? c[i] : c[0], \
                      (WIDE & 8) ? d[i] : d[0], imm)

// The fused multiply-then-add kernels' loop: the product rounded, then the sum (the two
// instructions' evalScalar, nothing contracted).
#define PF_FUSED_LOOP                                                                              \
  for (int i = 0; i < kLanes; ++i) {                                                              \
    const uint32_t m = evalScalar(Op::FMul, (WIDE & 1) ? a[i] : a[0], (WIDE & 2) ? b[i] : b[0], 0u); \
    const uint32_t t = (WIDE & 4) ? c[i] : c[0];                                                  \
    r[i] = FORM == FusedForm::ProductPlus    ? evalScalar(Op::FAdd, m, t, 0u)                     \
           : FORM == FusedForm::PlusProduct  ? evalScalar(Op::FAdd, t, m, 0u)                     \
           : FORM == FusedForm::ProductMinus ? evalScalar(Op::FSub, m, t, 0u)                     \
                                             : evalScalar(Op::FSub, t, m, 0u);                    \
  }

// The batched setup's loop: into a temporary first, dst may be one of the operands.
#define PF_BATCH_LOOP                                                                          \
  alignas(64) uint32_t r[kSetupBatchLanes];                                                   \
  for (int l = 0; l < kSetupBatchLanes; ++l) r[l] = evalScalar(OP, a[l], b[l], c[l], d[l], imm); \
  std::memcpy(dst, r, sizeof r)

#define PF_BATCH_PARAMS \
  uint32_t *dst, const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d, uint32_t imm

#define PF_LANE_PARAMS \
  uint32_t *__restrict r, const uint32_t *a, const uint32_t *b, const uint32_t *c, const uint32_t *d, uint32_t imm

// The mask loops. Portable versions for machines other than x86-64; on x86-64 each set has
// its own, with intrinsics: compilers turn the per-lane bit tests into long shuffle sequences.
[[maybe_unused]] uint64_t nonzeroPortable(const uint32_t* v) {
  uint64_t m = 0;
  for (int i = 0; i < kLanes; ++i) m |= static_cast<uint64_t>(v[i] != 0) << i;
  return m;
}
[[maybe_unused]] void blendPortable(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) {
  for (int i = 0; i < kLanes; ++i)
    if ((mask >> i) & 1u) d[i] = s[i];
}
// The depth loads' portable forms (the baseline set's too: SSE2 has no masked loads).
void loadBlockPortable(uint32_t* __restrict d, const float* base, int stride, uint64_t mask) {
  for (int row = 0; row < kBlockSize; ++row) {
    uint32_t* z = d + row * kBlockSize;
    const unsigned row_mask = static_cast<unsigned>(mask >> (row * kBlockSize)) & ((1u << kBlockSize) - 1u);
    if (row_mask == 0) {
      std::fill_n(z, kBlockSize, 0u);
      continue;
    }
    const float* depth = base + static_cast<ptrdiff_t>(row) * stride;
    if (row_mask == (1u << kBlockSize) - 1u) {
      std::memcpy(z, depth, sizeof(float) * kBlockSize);
      continue;
    }
    for (int lx = 0; lx < kBlockSize; ++lx) z[lx] = (row_mask >> lx) & 1u ? fromF(depth[lx]) : 0u;
  }
}
void gatherPortable(uint32_t* __restrict d, const float* base, const int32_t* offset, uint64_t mask) {
  for (int i = 0; i < kLanes; ++i) d[i] = (mask >> i) & 1u ? fromF(base[offset[i]]) : 0u;
}

void spreadPortable(uint32_t* __restrict d, const uint32_t* const* records, const int* first, int members,
                    size_t words) {
  for (int m = 0; m < members; ++m) {
    const int l0 = first[m], l1 = m + 1 < members ? first[m + 1] : kLanes;
    const uint32_t* r = records[m];
    uint32_t* w = d + l0;
    for (size_t k = 0; k < words; ++k, w += kLanes) std::fill(w, w + (l1 - l0), r[k]);
  }
}

// The members a gang block's lane groups of N hold: for each group, its members in lane
// order and the group's lanes each has (bit i: lane N g + i). The first member of a group
// fills it; the others are merged over it.
template <int N>
struct SpreadGroups {
  struct Group {
    int count = 0;
    int member[N];
    unsigned bits[N];
  } group[kLanes / N];
  SpreadGroups(const int* first, int members) {
    for (int m = 0; m < members; ++m) {
      const int l0 = first[m], l1 = m + 1 < members ? first[m + 1] : kLanes;
      for (int g = l0 / N; l1 > l0 && g <= (l1 - 1) / N; ++g) {
        const int a = std::max(l0, g * N) - g * N, b = std::min(l1, (g + 1) * N) - g * N;
        Group& gr = group[g];
        gr.member[gr.count] = m;
        gr.bits[gr.count] = ((b - a == 32 ? 0u : (1u << (b - a))) - 1u) << a;
        ++gr.count;
      }
    }
  }
};

struct Baseline {
  template <Op OP, unsigned WIDE>
  static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  template <FusedForm FORM, unsigned WIDE>
  static void fused(PF_LANE_PARAMS) { (void)d; (void)imm; PF_FUSED_LOOP }
  static void load_block(uint32_t* __restrict d, const float* base, int stride, uint64_t mask) {
    loadBlockPortable(d, base, stride, mask);
  }
  static void gather(uint32_t* __restrict d, const float* base, const int32_t* offset, uint64_t mask) {
    gatherPortable(d, base, offset, mask);
  }
  static void spread(uint32_t* __restrict d, const uint32_t* const* records, const int* first, int members,
                     size_t words) {
    spreadPortable(d, records, first, members, words);
  }
  template <Op OP>
  static void batch(PF_BATCH_PARAMS) { PF_BATCH_LOOP; }
#if defined(__x86_64__)
  // SSE2 (every x86-64): 4 lanes per compare; a lane's mask from its own bit of the group's
  // nibble (AND with 1, 2, 4, 8 and compare).
  static uint64_t nonzero(const uint32_t* v) {
    uint64_t m = 0;
    const __m128i zero = _mm_setzero_si128();
    for (int g = 0; g < kLanes / 4; ++g) {
      const __m128i is_zero = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(v + 4 * g)), zero);
      m |= static_cast<uint64_t>(~_mm_movemask_ps(_mm_castsi128_ps(is_zero)) & 0xf) << (4 * g);
    }
    return m;
  }
  static void blend(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) {
    const __m128i bit = _mm_setr_epi32(1, 2, 4, 8);
    for (int g = 0; g < kLanes / 4; ++g) {
      const __m128i nibble = _mm_set1_epi32(static_cast<int>((mask >> (4 * g)) & 0xf));
      const __m128i take = _mm_cmpeq_epi32(_mm_and_si128(nibble, bit), bit);
      __m128i* dp = reinterpret_cast<__m128i*>(d + 4 * g);
      const __m128i sv = _mm_loadu_si128(reinterpret_cast<const __m128i*>(s + 4 * g));
      _mm_storeu_si128(dp, _mm_or_si128(_mm_and_si128(take, sv), _mm_andnot_si128(take, _mm_loadu_si128(dp))));
    }
  }
#else
  static uint64_t nonzero(const uint32_t* v) { return nonzeroPortable(v); }
  static void blend(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) { blendPortable(d, s, mask); }
#endif
};

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define PF_LANE_ISAS 1
struct Avx2 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("avx2")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  template <FusedForm FORM, unsigned WIDE>
  [[gnu::target("avx2")]] static void fused(PF_LANE_PARAMS) { (void)d; (void)imm; PF_FUSED_LOOP }
  template <Op OP>
  [[gnu::target("avx2")]] static void batch(PF_BATCH_PARAMS) { PF_BATCH_LOOP; }
  // 8 lanes per compare; blendv takes each lane's top bit.
  [[gnu::target("avx2")]] static uint64_t nonzero(const uint32_t* v) {
    uint64_t m = 0;
    const __m256i zero = _mm256_setzero_si256();
    for (int g = 0; g < kLanes / 8; ++g) {
      const __m256i is_zero = _mm256_cmpeq_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(v + 8 * g)), zero);
      m |= static_cast<uint64_t>(~_mm256_movemask_ps(_mm256_castsi256_ps(is_zero)) & 0xff) << (8 * g);
    }
    return m;
  }
  // A row (8 lanes) per masked load; masked-off lanes are not read.
  [[gnu::target("avx2")]] static __m256i rowMask(unsigned bits) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    return _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), bit), bit);
  }
  [[gnu::target("avx2")]] static void load_block(uint32_t* __restrict d, const float* base, int stride,
                                                 uint64_t mask) {
    static_assert(kBlockSize == 8, "a row of a block is one 256-bit vector");
    for (int row = 0; row < kBlockSize; ++row) {
      const unsigned bits = static_cast<unsigned>(mask >> (row * kBlockSize)) & 0xffu;
      const __m256 v = bits ? _mm256_maskload_ps(base + static_cast<ptrdiff_t>(row) * stride, rowMask(bits))
                            : _mm256_setzero_ps();
      _mm256_storeu_ps(reinterpret_cast<float*>(d + row * kBlockSize), v);
    }
  }
  [[gnu::target("avx2")]] static void gather(uint32_t* __restrict d, const float* base, const int32_t* offset,
                                             uint64_t mask) {
    for (int g = 0; g < kLanes / 8; ++g) {
      const unsigned bits = static_cast<unsigned>(mask >> (8 * g)) & 0xffu;
      const __m256i idx = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(offset + 8 * g));
      const __m256 v = bits ? _mm256_mask_i32gather_ps(_mm256_setzero_ps(), base, idx,
                                                       _mm256_castsi256_ps(rowMask(bits)), 4)
                            : _mm256_setzero_ps();
      _mm256_storeu_ps(reinterpret_cast<float*>(d + 8 * g), v);
    }
  }
  // Each 8-lane group of each word built in a register (a broadcast per member it holds,
  // blended) and stored whole: masked stores are slow where a gang needs them most (AMD).
  [[gnu::target("avx2")]] static void spread(uint32_t* __restrict d, const uint32_t* const* records, const int* first,
                                             int members, size_t words) {
    SpreadGroups<8> groups(first, members);
    for (size_t k = 0; k < words; ++k, d += kLanes)
      for (int g = 0; g < kLanes / 8; ++g) {
        const SpreadGroups<8>::Group& gr = groups.group[g];
        __m256i v = _mm256_set1_epi32(static_cast<int>(records[gr.member[0]][k]));
        for (int e = 1; e < gr.count; ++e)
          v = _mm256_blendv_epi8(v, _mm256_set1_epi32(static_cast<int>(records[gr.member[e]][k])), rowMask(gr.bits[e]));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(d + 8 * g), v);
      }
  }
  [[gnu::target("avx2")]] static void blend(uint32_t* __restrict d, const uint32_t* __restrict s, uint64_t mask) {
    const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    for (int g = 0; g < kLanes / 8; ++g) {
      const __m256i byte = _mm256_set1_epi32(static_cast<int>((mask >> (8 * g)) & 0xff));
      const __m256 take = _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(byte, bit), bit));
      float* dp = reinterpret_cast<float*>(d + 8 * g);
      const __m256 sv = _mm256_loadu_ps(reinterpret_cast<const float*>(s + 8 * g));
      _mm256_storeu_ps(dp, _mm256_blendv_ps(_mm256_loadu_ps(dp), sv, take));
    }
  }
};
// 512-bit vectors: GCC's generic tuning would otherwise keep AVX-512 code at 256 bits.
struct Avx512 {
  template <Op OP, unsigned WIDE>
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void run(PF_LANE_PARAMS) { PF_LANE_LOOP; }
  template <FusedForm FORM, unsigned WIDE>
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void fused(PF_LANE_PARAMS) {
    (void)d;
    (void)imm;
    PF_FUSED_LOOP
  }
  template <Op OP>
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void batch(PF_BATCH_PARAMS) { PF_BATCH_LOOP; }
  // AVX-512 has mask registers for exactly these: a test per 16 lanes, a masked move.
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static uint64_t nonzero(const uint32_t* v) {
    uint64_t m = 0;
    for (int g = 0; g < kLanes / 16; ++g) {
      const __m512i x = _mm512_loadu_si512(v + 16 * g);
      m |= static_cast<uint64_t>(_mm512_test_epi32_mask(x, x)) << (16 * g);
    }
    return m;
  }
  // Two rows per 512-bit store, each by a masked load (masked-off lanes are not read).
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void load_block(uint32_t* __restrict d,
                                                                                  const float* base, int stride,
                                                                                  uint64_t mask) {
    static_assert(kBlockSize == 8, "two rows of a block are one 512-bit vector");
    for (int g = 0; g < kLanes / 16; ++g) {
      const __mmask8 lo_bits = static_cast<__mmask8>(mask >> (16 * g)), hi_bits = static_cast<__mmask8>(mask >> (16 * g + 8));
      const __m256 lo = lo_bits ? _mm256_maskz_loadu_ps(lo_bits, base + static_cast<ptrdiff_t>(2 * g) * stride)
                                : _mm256_setzero_ps();
      const __m256 hi = hi_bits ? _mm256_maskz_loadu_ps(hi_bits, base + static_cast<ptrdiff_t>(2 * g + 1) * stride)
                                : _mm256_setzero_ps();
      _mm512_storeu_ps(d + 16 * g, _mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1));
    }
  }
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void gather(uint32_t* __restrict d,
                                                                              const float* base,
                                                                              const int32_t* offset, uint64_t mask) {
    for (int g = 0; g < kLanes / 16; ++g) {
      const __mmask16 bits = static_cast<__mmask16>(mask >> (16 * g));
      const __m512i idx = _mm512_loadu_si512(offset + 16 * g);
      _mm512_storeu_ps(d + 16 * g, bits ? _mm512_mask_i32gather_ps(_mm512_setzero_ps(), bits, idx, base, 4)
                                        : _mm512_setzero_ps());
    }
  }
  // Each 16-lane group of each word built in a register (a broadcast per member it holds,
  // merged under its lanes' mask) and stored whole: masked stores to memory are slow on AMD.
  [[gnu::target("arch=x86-64-v4,prefer-vector-width=512")]] static void spread(uint32_t* __restrict d,
                                                                              const uint32_t* const* records,
                                                                              const int* first, int members,
                                                                              size_t words) {
    SpreadGroups<16> groups(first, members);
    for (size_t k = 0; k < words; ++k, d += kLanes)
      for (int g = 0; g < kLanes / 16; ++g) {
        const SpreadGroups<16>::Group& gr = groups.group[g];
        __m512i v = _mm512_set1_epi32(static_cast<int>(records[gr.member[0]][k]));
        for (int e = 1; e < gr.count; ++e)
          v = _mm512_mask_mov_epi32(v, static_cast<__mmask16>(gr.bits[e]),
                                    _mm512_set1_epi32(static_cast<int>(records[gr.member[e]][k])));
        _mm512_storeu_si512(d + 16 * g, v);
      }
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

template <class Isa, FusedForm FORM, size_t... W>
constexpr std::array<LaneKernel, 8> fusedFor(std::index_sequence<W...>) {
  return {&Isa::template fused<FORM, static_cast<unsigned>(W)>...};
}
template <class Isa>
constexpr FusedKernelTable fusedTableOf() {
  return {fusedFor<Isa, FusedForm::ProductPlus>(std::make_index_sequence<8>{}),
          fusedFor<Isa, FusedForm::PlusProduct>(std::make_index_sequence<8>{}),
          fusedFor<Isa, FusedForm::ProductMinus>(std::make_index_sequence<8>{}),
          fusedFor<Isa, FusedForm::MinusProduct>(std::make_index_sequence<8>{})};
}

template <class Isa, size_t... I>
constexpr BatchKernelTable batchTableOf(std::index_sequence<I...>) {
  return {&Isa::template batch<static_cast<Op>(I)>...};
}
template <class Isa>
constexpr BatchKernelTable batchTableOf() { return batchTableOf<Isa>(std::make_index_sequence<kLaneKernelOps>{}); }

constexpr LaneKernelTable kBaselineKernels = tableOf<Baseline>();
constexpr BatchKernelTable kBaselineBatch = batchTableOf<Baseline>();
constexpr FusedKernelTable kBaselineFused = fusedTableOf<Baseline>();
constexpr LaneIsaTables kBaseline{&kBaselineKernels,
                                  {&Baseline::nonzero, &Baseline::blend, &Baseline::load_block, &Baseline::gather, &Baseline::spread},
                                  &kBaselineBatch, &kBaselineFused};
#ifdef PF_LANE_ISAS
constexpr LaneKernelTable kAvx2Kernels = tableOf<Avx2>();
constexpr LaneKernelTable kAvx512Kernels = tableOf<Avx512>();
constexpr BatchKernelTable kAvx2Batch = batchTableOf<Avx2>();
constexpr BatchKernelTable kAvx512Batch = batchTableOf<Avx512>();
constexpr FusedKernelTable kAvx2Fused = fusedTableOf<Avx2>();
constexpr FusedKernelTable kAvx512Fused = fusedTableOf<Avx512>();
constexpr LaneIsaTables kAvx2{&kAvx2Kernels, {&Avx2::nonzero, &Avx2::blend, &Avx2::load_block, &Avx2::gather, &Avx2::spread},
                              &kAvx2Batch, &kAvx2Fused};
constexpr LaneIsaTables kAvx512{&kAvx512Kernels,
                                {&Avx512::nonzero, &Avx512::blend, &Avx512::load_block, &Avx512::gather, &Avx512::spread},
                                &kAvx512Batch, &kAvx512Fused};
#endif

bool machineRuns(LaneIsa isa) {
#ifdef PF_LANE_ISAS
  // The choice is made in a static initializer, possibly before libgcc's own CPU detection
  // has run: run it first (it is idempotent).
  __builtin_cpu_init();
#endif
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
