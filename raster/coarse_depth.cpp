// Coarse depth culling (see coarse_depth.h).
#include "raster/coarse_depth.h"

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pf {

uint64_t depthPassMask(DepthFunc func, float zmin, float zmax, const float* d, int n) {
  // Each case the negation of depthRangeFails's for one stored depth (NaN stored: passes,
  // as depthRangeFails claims nothing for it). Four depths at a time where SSE2 is (every
  // x86-64): the tile walk asks this of every row of every small instance's bound, and one
  // compare and bit a depth cost it a few percent of a frame of 100k sphere impostors. The
  // SSE compares are the scalar ones' negations: cmpnge(a, b) is !(a >= b), true for NaN too.
  auto mask = [&](auto may_pass, [[maybe_unused]] auto may_pass4) {
    uint64_t m = 0;
    int i = 0;
#if defined(__SSE2__)
    for (; i + 4 <= n; i += 4)
      m |= static_cast<uint64_t>(_mm_movemask_ps(may_pass4(_mm_loadu_ps(d + i)))) << i;
#endif
    for (; i < n; ++i) m |= static_cast<uint64_t>(may_pass(d[i])) << i;
    return m;
  };
#if defined(__SSE2__)
  const __m128 lo = _mm_set1_ps(zmin), hi = _mm_set1_ps(zmax);
#define PF_SSE(expr) [&](__m128 v) { return expr; }
#else
#define PF_SSE(expr) 0
#endif
  switch (func) {
    case DepthFunc::Never: return 0;
    case DepthFunc::Less: return mask([&](float v) { return !(zmin >= v); }, PF_SSE(_mm_cmpnge_ps(lo, v)));
    case DepthFunc::LessEqual: return mask([&](float v) { return !(zmin > v); }, PF_SSE(_mm_cmpngt_ps(lo, v)));
    case DepthFunc::Greater: return mask([&](float v) { return !(zmax <= v); }, PF_SSE(_mm_cmpnle_ps(hi, v)));
    case DepthFunc::GreaterEqual: return mask([&](float v) { return !(zmax < v); }, PF_SSE(_mm_cmpnlt_ps(hi, v)));
    case DepthFunc::Equal:
      return mask([&](float v) { return !(zmin > v || zmax < v); },
                  PF_SSE(_mm_and_ps(_mm_cmpngt_ps(lo, v), _mm_cmpnlt_ps(hi, v))));
    case DepthFunc::NotEqual: case DepthFunc::Always: break;
  }
#undef PF_SSE
  return n >= 64 ? ~0ull : (1ull << n) - 1;
}

void CoarseDepth::startTile(const float* depth, int stride, int x0, int y0, int w, int h, bool cleared) {
  depth_ = depth;
  stride_ = stride;
  x0_ = x0;
  y0_ = y0;
  w_ = w;
  h_ = h;
  for (Block& b : blocks_) b.known = false;
  if (!cleared || (w == kTileSize && h == kTileSize)) {
    std::fill_n(committed_, kBlocksPerSide * kBlocksPerSide, cleared ? 0ull : ~0ull);
    return;
  }
  for (int by = 0; by < kBlocksPerSide; ++by)
    for (int bx = 0; bx < kBlocksPerSide; ++bx) {
      // Pixels outside the framebuffer (a cut tile) never hold the clear depth: set.
      uint64_t outside = 0;
      for (int y = 0; y < kBlockSize; ++y)
        for (int x = 0; x < kBlockSize; ++x)
          if (bx * kBlockSize + x >= w || by * kBlockSize + y >= h) outside |= 1ull << (y * kBlockSize + x);
      committed_[by * kBlocksPerSide + bx] = outside;
    }
}

void CoarseDepth::measure(Block& b, int bx, int by) const {
  // Only the block's pixels inside the framebuffer (a tile at its right or top edge is cut).
  const int px0 = bx * kBlockSize, py0 = by * kBlockSize;
  const int cols = std::min(kBlockSize, w_ - px0), rows = std::min(kBlockSize, h_ - py0);
  b.known = true;
  if (cols <= 0 || rows <= 0) {  // (never asked of a block outside; no verdict if it were)
    b.has_nan = true;
    return;
  }
  const float* first = depth_ + static_cast<size_t>(y0_ + py0) * stride_ + x0_ + px0;
  if (cols == kBlockSize) {
    // A whole row at a time (the common case; GCC makes each row one vector min, max and
    // compare): asked once per block written and then tested, it must cost little.
    // NaN shows in `probe` (d * 0 is NaN for a NaN d, and for an infinite one: no verdict
    // either, which is merely cautious).
    float lo[kBlockSize], hi[kBlockSize], probe[kBlockSize];
    for (int x = 0; x < kBlockSize; ++x) {
      lo[x] = hi[x] = first[x];
      probe[x] = first[x] * 0.0f;
    }
    for (int y = 1; y < rows; ++y) {
      const float* row = first + static_cast<size_t>(y) * stride_;
      for (int x = 0; x < kBlockSize; ++x) {
        const float d = row[x];
        lo[x] = d < lo[x] ? d : lo[x];
        hi[x] = d > hi[x] ? d : hi[x];
        probe[x] += d * 0.0f;
      }
    }
    float l = lo[0], h = hi[0], p = probe[0];
    for (int x = 1; x < kBlockSize; ++x) {
      l = std::min(l, lo[x]);
      h = std::max(h, hi[x]);
      p += probe[x];
    }
    b.dmin = l;
    b.dmax = h;
    b.has_nan = p != p;
    return;
  }
  float lo = first[0], hi = first[0];
  bool nan = false;
  for (int y = 0; y < rows; ++y) {
    const float* row = first + static_cast<size_t>(y) * stride_;
    for (int x = 0; x < cols; ++x) {
      const float d = row[x];
      nan |= d != d;
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  b.dmin = lo;
  b.dmax = hi;
  b.has_nan = nan;
}

}  // namespace pf
