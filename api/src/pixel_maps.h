// Pixel transfer (GL 1.5 section 3.6.5): glPixelTransfer's modes, glPixelMap's ten tables, and
// the operations that apply them to the pixels entering or leaving the framebuffer or a texture
// -- which of them each command applies is OSMesa's (Mesa 22.3 with llvmpipe), not always the
// specification's: docs/api.md, "Pixel transfer", lists the departures.
#pragma once

#include <cstddef>
#include <cstdint>

#include <GL/gl.h>

struct PFcontextRec;

namespace pf {

struct Query;

// GL_MAX_PIXEL_MAP_TABLE, Mesa's: every table has room for this many entries, fixed.
constexpr int kMaxPixelMapTable = 256;

// glPixelTransfer's state (GL 1.5 table 6.17), part of GL_PIXEL_MODE_BIT.
struct PixelTransferModes {
  bool map_color = false, map_stencil = false;
  int index_shift = 0, index_offset = 0;
  float scale[4] = {1.0f, 1.0f, 1.0f, 1.0f};  // GL_RED_SCALE .. GL_ALPHA_SCALE
  float bias[4] = {0.0f, 0.0f, 0.0f, 0.0f};   // GL_RED_BIAS .. GL_ALPHA_BIAS
  float depth_scale = 1.0f, depth_bias = 0.0f;
  bool colorIdentity() const {  // scale 1, bias 0 and no maps: colours pass unchanged
    return !map_color && scale[0] == 1.0f && scale[1] == 1.0f && scale[2] == 1.0f && scale[3] == 1.0f &&
           bias[0] == 0.0f && bias[1] == 0.0f && bias[2] == 0.0f && bias[3] == 0.0f;
  }
};

// One table of glPixelMap: `size` entries used of a fixed kMaxPixelMapTable (GL's initial
// table: one entry, 0). Entries are kept as Mesa keeps them: floats, the colour tables' clamped
// to [0, 1], S_TO_S's rounded to integers.
struct PixelMap {
  int size = 1;
  float v[kMaxPixelMapTable] = {};
};

// The ten tables (not in any attribute group), by GL_PIXEL_MAP_I_TO_I + k.
struct PixelMaps {
  static constexpr int kCount = 10;
  PixelMap table[kCount];
  // The table `map` names; null for another enum.
  PixelMap* find(GLenum map) {
    return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A ? &table[map - GL_PIXEL_MAP_I_TO_I] : nullptr;
  }
  const PixelMap& operator[](GLenum map) const { return table[map - GL_PIXEL_MAP_I_TO_I]; }
};

// How an RGBA-to-RGBA table is indexed by a colour c (clamped to [0, 1]) of a table of n entries:
enum class ColorMapIndex {
  // round(c (n - 1)), halves to even: GL's rule, which OSMesa follows where it transfers on the
  // CPU (glReadPixels, glTexImage, glCopyTexImage);
  kNearest,
  // floor(t n / 256) of t = min(floor(256 c), 255), the entry quantised to 8 bits: OSMesa's
  // glDrawPixels and glCopyPixels, which look the colour up in a 256-texel texture of the maps.
  kTexel256,
};

// Scale and bias (each component c * scale + bias), then, under GL_MAP_COLOR, the R_TO_R ..
// A_TO_A tables, on `n` RGBA colours in place (nothing when colorIdentity()).
void transferColors(const PixelTransferModes& modes, const PixelMaps& maps, ColorMapIndex indexing, float* rgba,
                    size_t n);

// Colours of 8-bit components (c / 255, as unpacked) as Mesa and llvmpipe turn them into floats
// -- c * (1 / 255) in float, sometimes one ulp away -- so that scaled and biased values round to
// bytes as OSMesa's do; for images about to be transferred.
void byteColorsAsMesa(float* rgba, size_t n);

// Colour indices to RGBA (4 floats each): under `shift_offset` GL_INDEX_SHIFT and
// GL_INDEX_OFFSET first (as unsigned arithmetic, Mesa's), then each index (masked to the table's
// size - 1) looked up in I_TO_R .. I_TO_A. No I_TO_I, scale, bias or RGBA maps, as in OSMesa.
void indicesToColors(const PixelTransferModes& modes, const PixelMaps& maps, bool shift_offset, const uint32_t* indices,
                     size_t n, float* rgba);

// A depth value under GL_DEPTH_SCALE and GL_DEPTH_BIAS (not clamped).
inline float transferDepth(const PixelTransferModes& modes, float d) { return d * modes.depth_scale + modes.depth_bias; }

// A stencil value as glReadPixels returns it: shifted and offset, then under GL_MAP_STENCIL
// looked up in S_TO_S, in 8 bits at each step (Mesa transfers its 8-bit stencil values in place).
uint8_t transferStencil(const PixelTransferModes& modes, const PixelMaps& maps, uint8_t s);

// glGet* of the transfer modes, the tables' sizes and GL_MAX_PIXEL_MAP_TABLE (pixel_map_commands.cpp);
// false for another name.
bool pixelTransferQuery(const PFcontextRec& ctx, GLenum pname, Query& q);

}  // namespace pf
