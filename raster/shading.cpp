// The shading pass (see shading.h).
#include "raster/shading.h"

#include <cstddef>

#include "raster/limits.h"

namespace pf {

uint64_t shadeTile(const uint32_t* shade_ids, const float* const* slots, const ShadeState* shades,
                   const ShadeTarget& t) {
  uint64_t shaded = 0;
  for (int y = 0; y < t.h; ++y) {
    for (int x = 0; x < t.w; ++x) {
      size_t i = static_cast<size_t>(y) * kTileSize + x;
      uint32_t id = shade_ids[i];
      if (id == 0) continue;
      const ShadeState& s = shades[id - 1];
      float c[4];
      for (int k = 0; k < 4; ++k) c[k] = s.color_slot >= 0 ? slots[s.color_slot + k][i] : s.constant_color[k];
      uint8_t* px = t.color + (static_cast<size_t>(t.y0 + y) * t.stride + t.x0 + x) * 4;
      for (int k = 0; k < 4; ++k)
        if (t.color_mask & (1u << k)) px[k] = toUnorm8(c[k]);
      ++shaded;
    }
  }
  return shaded;
}

}  // namespace pf
