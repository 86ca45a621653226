// The renderer's per-tile work for GL's per-fragment operations (raster/fragment_ops.h): the
// pending clear within a tile (under the scissor box), and resolving the tile's G-buffer --
// shading what it holds, an ordered draw's pixels through their fragment operations
// (docs/architecture.md, "Ordered fragments"). Renderer::runTile decides when.
#include <algorithm>
#include <cstring>

#include "raster/renderer.h"

namespace pf {

void Renderer::clearTile(int x0, int y0, int w, int h) {
  // The clear's pixels within the tile.
  const PixelRect& r = scene_.clear.rect;
  const int cx0 = std::max(x0, r.x0), cy0 = std::max(y0, r.y0);
  const int cx1 = std::min(x0 + w, r.x1), cy1 = std::min(y0 + h, r.y1);
  if (cx0 >= cx1 || cy0 >= cy1) return;
  // (The clears read the buffers' addresses into locals first: a byte store may alias any
  // member, and the loops would reload them at every pixel instead of filling rows.)
  const size_t stride = static_cast<size_t>(width_);
  if (scene_.clear.color) {
    uint8_t c[4];
    for (int k = 0; k < 4; ++k) c[k] = toUnorm8(scene_.clear.rgba[k]);
    const uint8_t mask = scene_.clear.color_mask;
    uint8_t* const color = color_;
    uint32_t pixel;
    std::memcpy(&pixel, c, sizeof pixel);
    for (int y = cy0; y < cy1; ++y) {
      uint8_t* const row = color + ((static_cast<size_t>(y) * stride) + static_cast<size_t>(cx0)) * 4;
      if (mask == 0xf) {
        for (int x = 0; x < cx1 - cx0; ++x) std::memcpy(row + 4 * x, &pixel, sizeof pixel);
        continue;
      }
      for (int x = 0; x < cx1 - cx0; ++x)
        for (int k = 0; k < 4; ++k)
          if (mask & (1u << k)) row[4 * x + k] = c[k];
    }
  }
  if (scene_.clear.depth && depth_) {
    float* const depth = depth_;
    const float z = scene_.clear.z;
    for (int y = cy0; y < cy1; ++y) std::fill_n(depth + static_cast<size_t>(y) * stride + cx0, cx1 - cx0, z);
  }
}

void Renderer::resolveTile(WorkerScratch& s, int x0, int y0, int w, int h, const RasterState* ordered,
                           const PixelRect& bound) {
  ShadeTarget st{color_, width_, x0, y0, w, h, scene_.color_mask};
  constexpr size_t kPlane = static_cast<size_t>(kTileSize) * kTileSize;
  if (ordered) {
    s.discarded.resize(kPlane);
    st.fragments = &ordered->fragment;
    st.discarded = s.discarded.data();
  }
  s.pixels_shaded += shadeTile(s.shade_ids.data(), s.slot_planes.data(), scene_.shades.data(), scene_.lightings.data(),
                               scene_.lighting_equations.data(), st);
  // The G-buffer's pixels are written: empty it for what follows (only the bound's rows hold
  // an ordered draw's).
  const int row0 = ordered ? bound.y0 - y0 : 0, row1 = ordered ? bound.y1 - y0 : h;
  if (ordered && !s.depth_before.empty()) {
    // Under a fragment the alpha test discarded, the depth its program wrote goes back.
    const int bw = bound.x1 - bound.x0;
    for (int y = row0; y < row1; ++y) {
      const size_t t0 = static_cast<size_t>(y) * kTileSize + static_cast<size_t>(bound.x0 - x0);
      float* const depth = depth_ + static_cast<size_t>(y0 + y) * width_ + bound.x0;
      const float* const before = s.depth_before.data() + static_cast<size_t>(y - row0) * bw;
      for (int x = 0; x < bw; ++x)
        if (s.shade_ids[t0 + x] != 0 && s.discarded[t0 + x] != 0) depth[x] = before[x];
    }
  }
  std::fill(s.shade_ids.begin() + static_cast<std::ptrdiff_t>(row0) * kTileSize,
            s.shade_ids.begin() + static_cast<std::ptrdiff_t>(row1) * kTileSize, 0u);
}

}  // namespace pf
