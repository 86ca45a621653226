// Pixel transfer operations on pixels (see pixel_maps.h): scale and bias, the colour tables,
// colour indices to RGBA, and the stencil index arithmetic, in Mesa's arithmetic (floats; indices
// unsigned) so that the results are OSMesa's bit for bit.
#include "api/src/pixel_maps.h"

#include <algorithm>
#include <cmath>

namespace pf {
namespace {

// The entry of `table` a colour component `c` selects (see ColorMapIndex).
float lookUp(const PixelMap& table, ColorMapIndex indexing, float c) {
  const int n = table.size;
  if (indexing == ColorMapIndex::kNearest) {
    const float clamped = c > 0.0f ? std::min(c, 1.0f) : 0.0f;  // (NaN as 0)
    const int i = static_cast<int>(std::nearbyint(clamped * static_cast<float>(n - 1)));  // halves to even
    return table.v[std::clamp(i, 0, n - 1)];
  }
  const float texel = c > 0.0f ? std::min(std::floor(c * 256.0f), 255.0f) : 0.0f;
  const int i = static_cast<int>(texel) * n / 256;
  return std::nearbyint(table.v[i] * 255.0f) / 255.0f;  // (an 8-bit texel of the maps)
}

}  // namespace

void transferColors(const PixelTransferModes& modes, const PixelMaps& maps, ColorMapIndex indexing, float* rgba,
                    size_t n) {
  if (modes.colorIdentity()) return;
  for (size_t i = 0; i < n; ++i) {
    float* c = rgba + i * 4;
    for (int k = 0; k < 4; ++k) {
      const float scaled = c[k] * modes.scale[k];  // (two roundings, as Mesa's c * scale + bias)
      c[k] = scaled + modes.bias[k];
    }
    if (modes.map_color)
      for (int k = 0; k < 4; ++k) c[k] = lookUp(maps[static_cast<GLenum>(GL_PIXEL_MAP_R_TO_R + k)], indexing, c[k]);
  }
}

void byteColorsAsMesa(float* rgba, size_t n) {
  for (size_t i = 0; i < n * 4; ++i) rgba[i] = std::nearbyint(rgba[i] * 255.0f) * (1.0f / 255.0f);
}

void indicesToColors(const PixelTransferModes& modes, const PixelMaps& maps, bool shift_offset, const uint32_t* indices,
                     size_t n, float* rgba) {
  const int shift = modes.index_shift;
  const uint32_t offset = static_cast<uint32_t>(modes.index_offset);
  for (size_t i = 0; i < n; ++i) {
    uint32_t index = indices[i];
    if (shift_offset) {
      // (x86's shifts, which take the count modulo 32, as Mesa's compiled C does)
      if (shift > 0) index <<= (shift & 31);
      else if (shift < 0) index >>= (static_cast<uint32_t>(-static_cast<int64_t>(shift)) & 31);
      index += offset;
    }
    for (int k = 0; k < 4; ++k) {
      const PixelMap& table = maps[static_cast<GLenum>(GL_PIXEL_MAP_I_TO_R + k)];
      rgba[i * 4 + k] = table.v[index & static_cast<uint32_t>(table.size - 1)];
    }
  }
}

uint8_t transferStencil(const PixelTransferModes& modes, const PixelMaps& maps, uint8_t s) {
  const int shift = modes.index_shift;
  if (shift > 0) s = static_cast<uint8_t>(uint32_t{s} << (shift & 31));
  else if (shift < 0) s = static_cast<uint8_t>(uint32_t{s} >> (static_cast<uint32_t>(-static_cast<int64_t>(shift)) & 31));
  s = static_cast<uint8_t>(s + static_cast<uint32_t>(modes.index_offset));
  if (modes.map_stencil) {
    const PixelMap& table = maps[GL_PIXEL_MAP_S_TO_S];
    // (a float to 8 bits as Mesa's compiled C converts it: truncated to a 32-bit integer --
    // INT_MIN when out of range or NaN -- whose low 8 bits it keeps)
    const float v = table.v[s & (table.size - 1)];
    const int32_t i = v >= -2147483648.0f && v < 2147483648.0f ? static_cast<int32_t>(v) : INT32_MIN;
    s = static_cast<uint8_t>(static_cast<uint32_t>(i));
  }
  return s;
}

}  // namespace pf
