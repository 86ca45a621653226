// The shading pass (see shading.h).
#include "raster/shading.h"

#include <cstddef>

#include "raster/limits.h"

namespace pf {

uint64_t shadeTile(const uint32_t* shade_ids, const float* const* slots, const ShadeState* shades,
                   const LightingState* lightings, const LightingEquation* equations, const ShadeTarget& t) {
  uint64_t shaded = 0;
  for (int y = 0; y < t.h; ++y) {
    for (int x = 0; x < t.w; ++x) {
      size_t i = static_cast<size_t>(y) * kTileSize + x;
      uint32_t id = shade_ids[i];
      if (id == 0) continue;
      const ShadeState& s = shades[id - 1];
      float c[4];
      for (int k = 0; k < 4; ++k) c[k] = s.color_slot >= 0 ? slots[s.color_slot + k][i] : s.constant_color[k];
      if (s.lighting >= 0) {  // GL's lighting at this pixel; the colour is the material's where tracked
        const LightingState& l = lightings[s.lighting];
        const glm::vec3 p(slots[s.surface_slot][i], slots[s.surface_slot + 1][i], slots[s.surface_slot + 2][i]);
        glm::vec3 n(slots[s.surface_slot + 3][i], slots[s.surface_slot + 4][i], slots[s.surface_slot + 5][i]);
        if (glm::length(n) > 0.0f) n = glm::normalize(n);
        // Two-sided lighting: a normal facing away from the eye shows the back face.
        const int face = l.two_side && glm::dot(n, -p) < 0.0f ? 1 : 0;
        const glm::vec4 lit =
            equations[s.lighting].shade(trackedMaterial(l, face, glm::vec4(c[0], c[1], c[2], c[3])), p, face ? -n : n);
        for (int k = 0; k < 4; ++k) c[k] = lit[k];
      }
      uint8_t* px = t.color + (static_cast<size_t>(t.y0 + y) * t.stride + t.x0 + x) * 4;
      for (int k = 0; k < 4; ++k)
        if (t.color_mask & (1u << k)) px[k] = toUnorm8(c[k]);
      ++shaded;
    }
  }
  return shaded;
}

}  // namespace pf
