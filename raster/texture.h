// GL 1.x texturing as the shading pass applies it (GL 1.5 section 3.8): a draw's texture
// snapshot (TextureUnit: the bound texture's images and parameters and the texture
// environment, immutable once made, shared by the draws that use it) and the sampling of a span
// of pixels from the texture coordinates the primitives interpolated into the G-buffer.
//
// A texture is sampled per pixel in the deferred shading pass, after lighting, from the (s, t,
// r, q) channels the instance committed: so every primitive that interpolates shading
// parameters is textured the same way, and an ordered (blended) draw is textured before it
// blends. The level of detail comes from the screen-space derivatives of (s/q, t/q) times the
// level-0 size, GL's rho (equation 3.16), taken as differences between the pixel and its
// neighbours in the G-buffer (texture_sampling.cpp says which).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <GL/gl.h>

#include "raster/limits.h"

namespace pf {

// One mipmap level: width x height RGBA8 texels, row 0 first (t = 0). The components a base
// format lacks hold GL's defaults for it (table 3.15's conversion to RGBA): the env equations
// read what the base format has (TextureBase).
struct TextureLevel {
  int width = 0, height = 0;
  std::vector<uint8_t> texels;  // 4 per texel
};

// The base internal format (GL 1.5 table 3.15), which decides the texture environment's
// equations (tables 3.22 and 3.23).
enum class TextureBase : uint8_t { Alpha, Luminance, LuminanceAlpha, Intensity, Rgb, Rgba };

// Filters as GL names them (GL_NEAREST ... GL_LINEAR_MIPMAP_LINEAR), wraps (GL_REPEAT, GL_CLAMP,
// GL_CLAMP_TO_EDGE) and env modes (GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD).
struct TextureUnit {
  int dims = 2;  // 1: GL_TEXTURE_1D (t ignored), 2: GL_TEXTURE_2D
  TextureBase base = TextureBase::Rgba;
  // The levels a sample may read: the base level first, then each smaller one down to the
  // last a complete chain has (one level when the minification filter uses none).
  std::vector<std::shared_ptr<const TextureLevel>> levels;
  GLenum min_filter = GL_NEAREST_MIPMAP_LINEAR, mag_filter = GL_LINEAR;
  GLenum wrap_s = GL_REPEAT, wrap_t = GL_REPEAT;
  float border[4] = {0, 0, 0, 0};
  float min_lod = -1000.0f, max_lod = 1000.0f;
  GLenum env_mode = GL_MODULATE;
  float env_color[4] = {0, 0, 0, 0};
};

// What a span of one tile row needs to texture its pixels: the G-buffer's four texture
// coordinate planes (s, t, r, q), the shade ids of the whole tile (a neighbour counts only when
// it holds the same id), and the tile's size in pixels.
struct TextureSpan {
  const float* coord[4];  // planes, kTileSize x kTileSize, indexed y * kTileSize + x
  const uint32_t* ids;    // the tile's shade ids, the same indexing
  int tile_w, tile_h;
  int y, x, n;            // pixels [x, x + n) of tile row y
  uint32_t id;            // the span's shading state
};

// The texture's colour at each pixel of the span, combined with the fragment colours
// c[k][skip + i] (clamped to [0, 1] first) by the texture environment: c holds the result.
// Pixels of the span whose id differs from `id` are computed and left for the caller to skip.
void textureSpan(const TextureUnit& unit, const TextureSpan& span, float (*c)[kTileSize], int skip);

// GL's level of detail lambda for derivatives (in texels: s/q and t/q times the base level's
// width and height) along x and y: log2 of rho = the longer of the two derivative vectors.
float textureLod(float dudx, float dvdx, float dudy, float dvdy);

// One filtered sample at (s, t) (already divided by q) and level of detail `lod`, GL 1.5
// section 3.8.8 with the unit's filters and wraps, into rgba (0..1).
void sampleTexture(const TextureUnit& unit, float s, float t, float lod, float rgba[4]);

// The texture environment (tables 3.22, 3.23): fragment colour `f` and texture colour `tex`
// into `out`, clamped to [0, 1].
void textureEnvironment(const TextureUnit& unit, const float f[4], const float tex[4], float out[4]);

}  // namespace pf
