// Coarse depth culling (the Hi-Z of GPUs, for any primitive that states its depths): per 8x8
// block of the tile being run, the nearest and farthest depth stored under it. An instance whose
// setup called depth_bound(zmin, zmax) promises that every pixel it draws passed ztest(z) with z
// in [zmin, zmax]; where no depth in that range passes the context's depth test against any
// depth stored in a block, none of its pixels there can be drawn, and the block is skipped
// without running a lane.
//
// Why it pays: overlapping primitives drawn in no particular order (particles, atoms, a mesh
// drawn back to front) spend most of their pixel work on pixels that lose the depth test -- with
// 100k spheres over a 1024x1024 image, most lanes that start never commit, and most blocks
// pfbench's 2000 large triangles cover are behind what is already drawn (`--stats` counts). A block's range is
// recomputed from the depth buffer only when asked after something was written under it, so
// the bookkeeping costs one pass over 64 depths per (written block, later instance) pair.
//
// Exact by construction: a skipped block is one where the program's own depth test would have
// failed for every lane (the test is of the same float values), so images are identical to the
// bit with culling off (Renderer::setDepthCulling) -- provided the primitive keeps its promise.
#pragma once

#include <cstdint>

#include "raster/limits.h"
#include "raster/raster_state.h"

namespace pf {

// Whether no depth z in [zmin, zmax] passes `func` (z against the stored d, as ZTest compares)
// for any stored d in [dmin, dmax]. False where it cannot tell (NotEqual, Always, NaN bounds).
inline bool depthRangeFails(DepthFunc func, float zmin, float zmax, float dmin, float dmax) {
  // Each case: even the most favourable pair (z, d) fails. NaN bounds make every comparison
  // false, so no case claims anything for them.
  switch (func) {
    case DepthFunc::Never: return true;
    case DepthFunc::Less: return zmin >= dmax;          // z < d fails for every pair
    case DepthFunc::LessEqual: return zmin > dmax;      // z <= d
    case DepthFunc::Greater: return zmax <= dmin;       // z > d
    case DepthFunc::GreaterEqual: return zmax < dmin;   // z >= d
    case DepthFunc::Equal: return zmin > dmax || zmax < dmin;
    case DepthFunc::NotEqual: case DepthFunc::Always: return false;
  }
  return false;
}

// Bit i set where some depth z in [zmin, zmax] may pass `func` against d[i] -- that is, where
// !depthRangeFails(func, zmin, zmax, d[i], d[i]) -- for i < n <= 64. One pass of independent
// loads and compares (no branch per pixel, no chain of loads).
uint64_t depthPassMask(DepthFunc func, float zmin, float zmax, const float* d, int n);

class CoarseDepth {
 public:
  static constexpr int kBlocksPerSide = kTileSize / kBlockSize;

  // Starts a tile: the pixels [x0, x0 + w) x [y0, y0 + h) of `depth` (rows `stride` floats
  // apart); no block's range is known yet. `cleared`: the tile's depth was just cleared.
  void startTile(const float* depth, int stride, int x0, int y0, int w, int h, bool cleared);
  // Where the executor marks the pixels it commits (BlockTarget::committed_pixels).
  uint64_t* committedPixels() { return committed_; }

  // Whether no depth in [zmin, zmax] can pass `func` anywhere in the tile's block (bx, by)
  // (block indices within the tile): depthRangeFails against the block's stored range,
  // recomputed first if something was written under it since it was last asked.
  // A block of a cleared tile where some pixel was not drawn yet holds the clear depth, which
  // a range can hardly lose to (GL_LESS against a far clear): no verdict, without measuring
  // (measures are the cost of culling where it rarely succeeds -- small, scattered instances).
  bool fails(DepthFunc func, float zmin, float zmax, int bx, int by) {
    Block& b = blocks_[by * kBlocksPerSide + bx];
    if (!b.known) {
      if (~committed_[by * kBlocksPerSide + bx]) return false;
      measure(b, bx, by);
    }
    return !b.has_nan && depthRangeFails(func, zmin, zmax, b.dmin, b.dmax);
  }

  // Depths under the pixels [px0, px1) x [py0, py1) (tile-relative) may have changed.
  void written(int px0, int py0, int px1, int py1) {
    for (int by = py0 / kBlockSize; by <= (py1 - 1) / kBlockSize; ++by)
      for (int bx = px0 / kBlockSize; bx <= (px1 - 1) / kBlockSize; ++bx) blocks_[by * kBlocksPerSide + bx].known = false;
  }

 private:
  struct Block {
    float dmin = 0, dmax = 0;
    bool known = false;
    bool has_nan = false;  // a NaN (or an infinity) stored under the block: no verdict
  };
  void measure(Block& b, int bx, int by) const;

  Block blocks_[kBlocksPerSide * kBlocksPerSide];
  // Per block, the pixels drawn since the tile's clear (and those outside the framebuffer, or
  // every pixel if there was no clear): a block is measured only once all are set.
  uint64_t committed_[kBlocksPerSide * kBlocksPerSide];
  const float* depth_ = nullptr;
  int stride_ = 0, x0_ = 0, y0_ = 0, w_ = 0, h_ = 0;
};

}  // namespace pf
