// Pixel store modes and reading pixels: glPixelStorei / glPixelStoref for every pack and unpack
// mode of GL 1.5 table 3.1 (the unpack modes read by glTexImage and glTexSubImage, the pack modes
// written by glReadPixels and glGetTexImage, both through pixel_transfer.h), and glReadPixels
// with pixel transfer (section 3.6.5 as 4.3.2 applies it, pixel_maps.h): colours through scale,
// bias and the colour maps, depth through depth scale and bias, stencil indices through index
// shift and offset and the stencil map.
#include <algorithm>
#include <cmath>
#include <cstring>

#include <primflow/gl.h>

#include "api/src/context_state.h"
#include "api/src/pixel_maps.h"
#include "api/src/pixel_transfer.h"

namespace {

// glPixelStore: `value` (glPixelStoref's rounded to nearest, halves away from zero, as Mesa does
// -- booleans too: 0.25 is false) into the mode `pname` names. Booleans take value != 0; lengths
// and skips must not be negative, the alignment must be 1, 2, 4 or 8 (GL_INVALID_VALUE);
// another name: GL_INVALID_ENUM.
void pixelStore(GLenum pname, double value) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  pf::PixelStore& pack = ctx->pack;
  pf::PixelStore& unpack = ctx->unpack;
  bool* flag = nullptr;
  int* number = nullptr;
  switch (pname) {
    case GL_PACK_SWAP_BYTES: flag = &pack.swap_bytes; break;
    case GL_PACK_LSB_FIRST: flag = &pack.lsb_first; break;
    case GL_PACK_ROW_LENGTH: number = &pack.row_length; break;
    case GL_PACK_SKIP_ROWS: number = &pack.skip_rows; break;
    case GL_PACK_SKIP_PIXELS: number = &pack.skip_pixels; break;
    case GL_PACK_ALIGNMENT: number = &pack.alignment; break;
    case GL_PACK_IMAGE_HEIGHT: number = &pack.image_height; break;
    case GL_PACK_SKIP_IMAGES: number = &pack.skip_images; break;
    case GL_UNPACK_SWAP_BYTES: flag = &unpack.swap_bytes; break;
    case GL_UNPACK_LSB_FIRST: flag = &unpack.lsb_first; break;
    case GL_UNPACK_ROW_LENGTH: number = &unpack.row_length; break;
    case GL_UNPACK_SKIP_ROWS: number = &unpack.skip_rows; break;
    case GL_UNPACK_SKIP_PIXELS: number = &unpack.skip_pixels; break;
    case GL_UNPACK_ALIGNMENT: number = &unpack.alignment; break;
    case GL_UNPACK_IMAGE_HEIGHT: number = &unpack.image_height; break;
    case GL_UNPACK_SKIP_IMAGES: number = &unpack.skip_images; break;
    default: return ctx->setError(GL_INVALID_ENUM);
  }
  const double rounded = std::round(value);
  if (flag) {
    *flag = rounded != 0.0;
    return;
  }
  const bool alignment = pname == GL_PACK_ALIGNMENT || pname == GL_UNPACK_ALIGNMENT;
  if (!(rounded >= 0.0 && rounded <= 2147483647.0) ||
      (alignment && rounded != 1 && rounded != 2 && rounded != 4 && rounded != 8))
    return ctx->setError(GL_INVALID_VALUE);
  *number = static_cast<int>(rounded);
}

}  // namespace

extern "C" {

void pfglPixelStorei(GLenum pname, GLint param) { pixelStore(pname, param); }
void pfglPixelStoref(GLenum pname, GLfloat param) { pixelStore(pname, param); }

// Colour as RGBA or RGB, bytes or floats; depth as floats, or unsigned ints / shorts scaled to
// their range; stencil values (GL_STENCIL_INDEX) as they are, in any of the four types. Written by the pack modes (GL 1.5 section 4.3.2): rows GL_PACK_ROW_LENGTH pixels
// long (0: `width`), starting on GL_PACK_ALIGNMENT boundaries, after GL_PACK_SKIP_ROWS rows and
// GL_PACK_SKIP_PIXELS pixels, each component's bytes reversed under GL_PACK_SWAP_BYTES. Pixels
// outside the framebuffer are left as they are in `pixels` (GL leaves them undefined). Drawing
// is finished first. Colours through scale, bias and the colour maps (a float read unclamped,
// as Mesa's), depth through scale and bias (then clamped to [0, 1], as Mesa clamps it),
// stencil values through shift, offset and GL_MAP_STENCIL in 8 bits (Mesa's).
void pfglReadPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum format, GLenum type, GLvoid* pixels) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  int components;
  switch (format) {
    case GL_RGBA: components = 4; break;
    case GL_RGB: components = 3; break;
    case GL_DEPTH_COMPONENT: case GL_STENCIL_INDEX: components = 1; break;
    default: ctx->setError(GL_INVALID_ENUM); return;
  }
  size_t bytes;
  switch (type) {
    case GL_UNSIGNED_BYTE: bytes = 1; break;
    case GL_UNSIGNED_SHORT: bytes = 2; break;
    case GL_UNSIGNED_INT: case GL_FLOAT: bytes = 4; break;
    default: ctx->setError(GL_INVALID_ENUM); return;
  }
  if ((format == GL_DEPTH_COMPONENT && ctx->depth_bits <= 0) || (format == GL_STENCIL_INDEX && ctx->stencil_bits <= 0)) {
    ctx->setError(GL_INVALID_OPERATION);
    return;
  }
  if (!pixels || !ctx->color || width == 0 || height == 0) return;
  ctx->finish();
  const pf::PixelStore& pack = ctx->pack;
  const pf::PixelTransferModes& modes = ctx->pixel_mode.transfer;
  const bool transfer_colors = format != GL_DEPTH_COMPONENT && format != GL_STENCIL_INDEX && !modes.colorIdentity();
  const bool transfer_depth = modes.depth_scale != 1.0f || modes.depth_bias != 0.0f;
  // (The rows laid out as every client image is: pixel_transfer.h.)
  const pf::ImageLayout layout = pf::imageLayout(pack, format, type, width);
  const size_t pixel_bytes = layout.pixel_bytes;
  const size_t row_bytes = layout.row_bytes;
  auto* out = static_cast<unsigned char*>(pixels) + layout.offset;
  for (int row = 0; row < height; ++row) {
    const long fy = static_cast<long>(y) + row;
    if (fy < 0 || fy >= ctx->height) continue;
    for (int col = 0; col < width; ++col) {
      const long fx = static_cast<long>(x) + col;
      if (fx < 0 || fx >= ctx->width) continue;
      const size_t at = static_cast<size_t>(fy) * ctx->width + static_cast<size_t>(fx);
      double v[4] = {0, 0, 0, 0};
      if (format == GL_DEPTH_COMPONENT) {
        v[0] = transfer_depth ? std::clamp(pf::transferDepth(modes, ctx->depth[at]), 0.0f, 1.0f) : ctx->depth[at];
      } else if (transfer_colors) {  // (in floats, as Mesa converts and transfers)
        float rgba[4];
        for (int c = 0; c < 4; ++c) rgba[c] = ctx->color[at * 4 + c] * (1.0f / 255.0f);
        pf::transferColors(modes, ctx->pixel_maps, pf::ColorMapIndex::kNearest, rgba, 1);
        for (int c = 0; c < 4; ++c) v[c] = rgba[c];
      } else {
        for (int c = 0; c < 4; ++c) v[c] = ctx->color[at * 4 + c] / 255.0;
      }
      unsigned char* dst = out + row * row_bytes + static_cast<size_t>(col) * pixel_bytes;
      if (format == GL_STENCIL_INDEX) {  // an index: not scaled to the type's range
        const uint8_t index = pf::transferStencil(modes, ctx->pixel_maps, ctx->stencil[at]);
        const float f = index;
        const uint16_t u16 = index;
        const uint32_t u32 = index;
        if (type == GL_FLOAT) std::memcpy(dst, &f, 4);
        else if (type == GL_UNSIGNED_BYTE) dst[0] = index;
        else if (type == GL_UNSIGNED_SHORT) std::memcpy(dst, &u16, 2);
        else std::memcpy(dst, &u32, 4);
        if (pack.swap_bytes) std::reverse(dst, dst + bytes);
        continue;
      }
      for (int c = 0; c < components; ++c) {
        const double f = v[c] > 0.0 ? std::min(v[c], 1.0) : 0.0;  // (NaN as 0)
        if (type == GL_FLOAT) {
          const float s = static_cast<float>(format == GL_DEPTH_COMPONENT || transfer_colors ? v[c] : f);
          std::memcpy(dst + c * 4, &s, 4);
        } else if (type == GL_UNSIGNED_BYTE) {
          dst[c] = format == GL_DEPTH_COMPONENT ? static_cast<unsigned char>(std::nearbyint(f * 255.0))
                   : transfer_colors ? static_cast<unsigned char>(std::nearbyint(static_cast<float>(f) * 255.0f))
                                     : ctx->color[at * 4 + c];
        } else if (type == GL_UNSIGNED_SHORT) {
          const uint16_t s = static_cast<uint16_t>(std::nearbyint(f * 65535.0));
          std::memcpy(dst + c * 2, &s, 2);
        } else {
          const uint32_t s = static_cast<uint32_t>(std::nearbyint(f * 4294967295.0));
          std::memcpy(dst + c * 4, &s, 4);
        }
        if (pack.swap_bytes) std::reverse(dst + c * bytes, dst + (c + 1) * bytes);
      }
    }
  }
}

}  // extern "C"
