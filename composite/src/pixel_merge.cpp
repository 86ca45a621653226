// Per-pixel depth merging and the run-length code of composited bands (pixel_merge.h): the
// compositor of PixelFlow's image-composition network (Molnar et al. 1992, seed 003 section 1),
// in software. The merge loops are branch-free so they vectorize.
#include "pixel_merge.h"

#include <algorithm>
#include <cstring>

namespace pf::composite {

namespace {

constexpr uint32_t kRunBit = 0x80000000u;
constexpr size_t kMaxRecord = 0x7fffffffu;  // pixels in one record
constexpr size_t kMinRun = 3;               // shorter runs go into literals: a run record costs 3 words

uint32_t bitsOf(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

float floatOf(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

template <bool kSrcWinsTies>
void mergeLoop(uint32_t* __restrict dc, float* __restrict dd, const uint32_t* __restrict sc,
               const float* __restrict sd, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const bool take = kSrcWinsTies ? sd[i] <= dd[i] : sd[i] < dd[i];
    dc[i] = take ? sc[i] : dc[i];
    dd[i] = take ? sd[i] : dd[i];
  }
}

template <bool kSrcWinsTies>
void mergeConstantLoop(uint32_t* __restrict dc, float* __restrict dd, uint32_t c, float d, size_t n) {
  for (size_t i = 0; i < n; ++i) {
    const bool take = kSrcWinsTies ? d <= dd[i] : d < dd[i];
    dc[i] = take ? c : dc[i];
    dd[i] = take ? d : dd[i];
  }
}

// Walks a code, calling run(offset, n, colour, depth) and literal(offset, n, colours, depths)
// for each record. False if malformed or if the pixels do not add up to `pixels`.
template <class Run, class Literal>
bool walkRecords(const uint32_t* code, size_t words, size_t pixels, Run run, Literal literal) {
  size_t at = 0, done = 0;
  while (at < words) {
    const uint32_t header = code[at++];
    const size_t n = header & ~kRunBit;
    if (n == 0 || n > pixels - done) return false;
    if (header & kRunBit) {
      if (words - at < 2) return false;
      run(done, n, code[at], floatOf(code[at + 1]));
      at += 2;
    } else {
      if ((words - at) / 2 < n) return false;
      literal(done, n, code + at, reinterpret_cast<const float*>(code + at + n));
      at += 2 * n;
    }
    done += n;
  }
  return done == pixels;
}

}  // namespace

void mergeByDepth(PixelSpan dst, ConstPixelSpan src, bool src_wins_ties) {
  const size_t n = std::min(dst.count, src.count);
  if (src_wins_ties) mergeLoop<true>(dst.color, dst.depth, src.color, src.depth, n);
  else mergeLoop<false>(dst.color, dst.depth, src.color, src.depth, n);
}

size_t maxEncodedWords(size_t pixels) {
  // One literal per kMaxRecord pixels at most.
  return 2 * pixels + (pixels + kMaxRecord - 1) / kMaxRecord + 1;
}

size_t encodeRuns(ConstPixelSpan src, uint32_t* out) {
  const size_t n = src.count, capacity = maxEncodedWords(n);
  size_t at = 0;             // words written
  size_t literal_from = 0;   // first pixel not yet written
  bool fits = true;
  auto literal = [&](size_t end) {
    while (literal_from < end) {
      const size_t len = std::min(end - literal_from, kMaxRecord);
      if (capacity - at < 1 + 2 * len) {
        fits = false;
        return;
      }
      out[at++] = static_cast<uint32_t>(len);
      std::memcpy(out + at, src.color + literal_from, len * sizeof(uint32_t));
      std::memcpy(out + at + len, src.depth + literal_from, len * sizeof(float));
      at += 2 * len;
      literal_from += len;
    }
  };
  size_t i = 0;
  while (i < n && fits) {
    const uint32_t c = src.color[i], d = bitsOf(src.depth[i]);
    size_t j = i + 1;
    while (j < n && j - i < kMaxRecord && src.color[j] == c && bitsOf(src.depth[j]) == d) ++j;
    if (j - i >= kMinRun) {
      literal(i);
      if (!fits || capacity - at < 3) {
        fits = false;
        break;
      }
      out[at++] = kRunBit | static_cast<uint32_t>(j - i);
      out[at++] = c;
      out[at++] = d;
      literal_from = j;
    }
    i = j;
  }
  if (fits) literal(n);
  if (!fits) {  // runs did not pay: everything as literals, which always fits
    at = 0;
    literal_from = 0;
    fits = true;
    literal(n);
  }
  return at;
}

bool mergeRuns(PixelSpan dst, const uint32_t* code, size_t words, bool src_wins_ties) {
  return walkRecords(
      code, words, dst.count,
      [&](size_t at, size_t n, uint32_t c, float d) {
        if (src_wins_ties) mergeConstantLoop<true>(dst.color + at, dst.depth + at, c, d, n);
        else mergeConstantLoop<false>(dst.color + at, dst.depth + at, c, d, n);
      },
      [&](size_t at, size_t n, const uint32_t* c, const float* d) {
        mergeByDepth({dst.color + at, dst.depth + at, n}, {c, d, n}, src_wins_ties);
      });
}

bool decodeRuns(PixelSpan dst, const uint32_t* code, size_t words) {
  return walkRecords(
      code, words, dst.count,
      [&](size_t at, size_t n, uint32_t c, float d) {
        std::fill_n(dst.color + at, n, c);
        std::fill_n(dst.depth + at, n, d);
      },
      [&](size_t at, size_t n, const uint32_t* c, const float* d) {
        std::copy_n(c, n, dst.color + at);
        std::memcpy(dst.depth + at, d, n * sizeof(float));
      });
}

}  // namespace pf::composite
