// The deferred shading pass: after every instance of a tile has run, each pixel that some
// instance covered is shaded once from the shading parameters left in the G-buffer.
// Shading is the colour parameter (lit per vertex already, or unlit), or -- for primitives that
// set their normal N -- GL's lighting evaluated per pixel from the G-buffer's P and N; then the
// texture and fog, clamped and rounded to 8 bits.
#pragma once

#include <cstdint>
#include <memory>

#include "raster/fog.h"
#include "raster/fragment_ops.h"
#include "raster/lighting.h"
#include "raster/texture.h"

namespace pf {

// What the shading pass needs to know about a shading state: where its parameters are.
struct ShadeState {
  int color_slot = -1;  // first of 4 G-buffer slots (r, g, b, a); -1: the state's constant colour
  // Two-sided lighting: the slots of the back colour, for instances that show their back
  // (facing()); -1: one colour for both faces.
  int back_color_slot = -1;
  float constant_color[4] = {1, 1, 1, 1};
  // Per-pixel lighting: the 6 slots of P (eye coordinates) and N, and the lighting state (an
  // index into the frame's lighting states, set by the renderer); -1: none.
  int surface_slot = -1;
  int lighting = -1;
  // Texturing (raster/texture.h): the 4 slots of (s, t, r, q) and the draw's texture snapshot,
  // applied after lighting; null: untextured.
  int texcoord_slot = -1;
  std::shared_ptr<const TextureUnit> texture;
  // Fog (raster/fog.h), applied after texturing: the slot of the fog coordinate (-1: no fog).
  int fog_slot = -1;
  FogParams fog;

  bool operator==(const ShadeState&) const = default;
};

struct ShadeTarget {
  uint8_t* color;   // RGBA8, row 0 at the bottom
  int stride;       // pixels per row
  int x0, y0, w, h; // the tile's pixels in window coordinates
  uint8_t color_mask = 0xf;  // RGBA channels written (bit k: channel k)
  // An ordered draw's fragment operations (fragment_ops.h), or null: the colours replace the
  // pixels'. With them, `discarded` (a kTileSize x kTileSize plane, like the ids) gets 1 where
  // the alpha test discarded the pixel's fragment, 0 at the other shaded pixels.
  const FragmentOps* fragments = nullptr;
  uint8_t* discarded = nullptr;
  // The tile's rows [row_begin, row_end) to shade (-1: to the last); an ordered draw's pixels
  // lie within its bound's rows.
  int row_begin = 0, row_end = -1;
};

// Shades the tile: for every pixel with a non-zero shade id (1 + index into `shades`).
// Returns the number of pixels shaded.
// `equations[i]` is `lightings[i]`'s equation.
uint64_t shadeTile(const uint32_t* shade_ids, const float* const* slots, const ShadeState* shades,
                   const LightingState* lightings, const LightingEquation* equations, const ShadeTarget& target);

// Float colour component -> 8 bits: clamp to [0, 1], scale, round to nearest (as GL does).
inline uint8_t toUnorm8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<uint8_t>(c * 255.0f + 0.5f);
}
// toUnorm8 with selects instead of branches -- the same value for every float (clamped to
// [0, 1] first, 1 gives 255.5 -> 255) -- for loops the compiler should vectorize.
inline int toUnorm8Select(float c) {
  float v = c > 0.0f ? c : 0.0f;  // NaN too
  v = v < 1.0f ? v : 1.0f;
  return static_cast<int>(v * 255.0f + 0.5f);
}

}  // namespace pf
