// The renderer's per-tile work for GL's per-fragment operations (raster/fragment_ops.h): the
// pending clear within a tile (under the scissor box; the stencil buffer's too), resolving the
// tile's G-buffer -- shading what it holds, an ordered draw's pixels through their fragment
// operations -- and a stencil draw's stencil operations (docs/architecture.md, "Ordered
// fragments"). Renderer::runTile decides when.
#include <algorithm>
#include <cstring>

#include "raster/fragment_ops.h"
#include "raster/renderer.h"

namespace pf {

void Renderer::clearStencil(uint8_t value, uint8_t write_mask, const PixelRect& rect) {
  if (!scene_.instances.empty() || (scene_.clearing() && !(scene_.clear.rect == rect)) ||
      (scene_.clear.stencil && scene_.clear.stencil_mask != write_mask))
    flush();
  scene_.clear.rect = rect;
  scene_.clear.stencil = true;
  scene_.clear.stencil_value = value;
  scene_.clear.stencil_mask = write_mask;
}

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
    // (Rounded a tie to even, as llvmpipe packs its clear colour: 0.5 / 255 clears to 0.)
    for (int k = 0; k < 4; ++k) c[k] = toUnorm8Even(scene_.clear.rgba[k]);
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
  if (scene_.clear.stencil && stencil_) {
    uint8_t* const stencil = stencil_;
    const uint8_t keep = static_cast<uint8_t>(~scene_.clear.stencil_mask);
    const uint8_t set = scene_.clear.stencil_value & scene_.clear.stencil_mask;
    for (int y = cy0; y < cy1; ++y) {
      uint8_t* const row = stencil + static_cast<size_t>(y) * stride;
      for (int x = cx0; x < cx1; ++x) row[x] = static_cast<uint8_t>((row[x] & keep) | set);
    }
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
    st.row_begin = bound.y0 - y0;
    st.row_end = bound.y1 - y0;
  }
  // (Under an empty colour mask nothing is written: only the alpha test needs the colours.)
  const bool alpha_test = ordered && ordered->fragment.alpha_test;
  if (scene_.color_mask != 0 || alpha_test)
    s.pixels_shaded += shadeTile(s.shade_ids.data(), s.slot_planes.data(), scene_.shades.data(),
                                 scene_.lightings.data(), scene_.lighting_equations.data(), st);
  // The G-buffer's pixels are written: empty it for what follows (only the bound's rows hold
  // an ordered draw's).
  const int row0 = ordered ? bound.y0 - y0 : 0, row1 = ordered ? bound.y1 - y0 : h;
  if (alpha_test && !s.depth_before.empty()) {
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

void Renderer::coverStencil(WorkerScratch& s, int x0, int y0, int w, int h, const RasterState& state,
                            const PixelRect& bound) {
  const int bw = bound.x1 - bound.x0, bh = bound.y1 - bound.y0;
  s.covered.assign(static_cast<size_t>(bw) * bh, 0);
  // The alpha test comes first (GL 1.5 section 4.1): a fragment it discards touches no stencil
  // value. Its verdicts, without writing a pixel: the fragment operations reduced to it, under
  // an empty colour mask.
  constexpr size_t kPlane = static_cast<size_t>(kTileSize) * kTileSize;
  const bool alpha_test = state.fragment.alpha_test;
  if (alpha_test) {
    FragmentOps alpha_only;
    alpha_only.alpha_test = true;
    alpha_only.alpha_func = state.fragment.alpha_func;
    alpha_only.alpha_ref = state.fragment.alpha_ref;
    ShadeTarget st{color_, width_, x0, y0, w, h, 0};
    s.discarded.resize(kPlane);
    st.fragments = &alpha_only;
    st.discarded = s.discarded.data();
    st.row_begin = bound.y0 - y0;
    st.row_end = bound.y1 - y0;
    shadeTile(s.shade_ids.data(), s.slot_planes.data(), scene_.shades.data(), scene_.lightings.data(),
              scene_.lighting_equations.data(), st);
  }
  for (int y = 0; y < bh; ++y) {
    const size_t t0 = static_cast<size_t>(bound.y0 - y0 + y) * kTileSize + static_cast<size_t>(bound.x0 - x0);
    for (int x = 0; x < bw; ++x)
      s.covered[static_cast<size_t>(y) * bw + x] =
          s.shade_ids[t0 + x] != 0 && !(alpha_test && s.discarded[t0 + x] != 0) ? 1 : 0;
    std::fill_n(s.shade_ids.begin() + static_cast<std::ptrdiff_t>(t0), bw, 0u);
  }
}

void Renderer::applyStencil(WorkerScratch& s, int x0, int y0, const RasterState& state, const PixelRect& bound) {
  const StencilOps& op = state.fragment.stencil;
  const int bw = bound.x1 - bound.x0, bh = bound.y1 - bound.y0;
  const bool restore_depth = !s.depth_before.empty();
  for (int y = 0; y < bh; ++y) {
    const size_t t0 = static_cast<size_t>(bound.y0 - y0 + y) * kTileSize + static_cast<size_t>(bound.x0 - x0);
    const size_t row = static_cast<size_t>(bound.y0 + y) * width_ + static_cast<size_t>(bound.x0);
    uint8_t* const stencil = stencil_ + row;
    for (int x = 0; x < bw; ++x) {
      uint32_t& id = s.shade_ids[t0 + x];
      const bool covered = s.covered[static_cast<size_t>(y) * bw + x] != 0;
      const bool stencil_passes = covered && op.passes(stencil[x]);
      if (covered) stencil[x] = stencilApply(op, !stencil_passes ? op.fail : id != 0 ? op.depth_pass : op.depth_fail,
                                             stencil[x]);
      if (id != 0 && !stencil_passes) {  // failed the stencil test (or discarded by the alpha test)
        id = 0;
        if (restore_depth) depth_[row + x] = s.depth_before[static_cast<size_t>(y) * bw + x];
      }
    }
  }
}

}  // namespace pf
