// glDrawPixels and glCopyPixels (GL 1.5 sections 3.6 and 4.3.3) with glPixelZoom: an image --
// unpacked by glPixelStore's unpack modes, or copied from the framebuffer -- drawn at the
// current raster position (rounded to the nearest pixel, halves away from zero, as Mesa rounds
// it). Image pixel (i, j) becomes the fragments whose centres lie in the rectangle from
// (x + zoom_x i, y + zoom_y j) to (x + zoom_x (i + 1), y + zoom_y (j + 1)), for any zoom,
// negative (mirrored) and fractional too. Colour images give fragments of the image's colour at
// the raster depth; depth images fragments of the raster colour at the image's depth (clamped to
// [0, 1]); both go through the per-fragment operations as instances of pixel_rectangle
// (pixel_rectangles.h). Stencil images are written to the stencil buffer through the scissor
// test and the stencil write mask, as GL says (no fragments). An invalid raster position draws
// nothing. Pixel transfer (section 3.6.5, pixel_maps.h) as OSMesa applies it: colour images
// through scale, bias and the colour maps (indexed as OSMesa's texture of them is), colour
// indices through the index-to-RGBA maps alone, glDrawPixels' depth through depth scale and
// bias, copied depth and stencil images unchanged. In a display list glDrawPixels' image is
// unpacked when the list is compiled and transferred when it runs; glCopyPixels reads the
// framebuffer when the list runs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <vector>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/pixel_maps.h"
#include "api/src/pixel_rectangles.h"
#include "api/src/pixel_transfer.h"

namespace pf {
namespace {

// An image ready to draw, row 0 first: colour (4 floats a pixel), depth (1 float) or stencil
// indices (1 a pixel, as floats: exact up to 2^24, past the 8 bits they are masked to). Before
// pixel transfer also colour indices (4 floats a pixel, the index in the first: its low 8 bits,
// all that the tables' at most 256 entries look at).
struct PixelImage {
  GLenum kind = GL_COLOR;  // GL_COLOR, GL_COLOR_INDEX, GL_DEPTH or GL_STENCIL
  int width = 0, height = 0;
  bool bytes = false;      // colours of 8-bit components (GL_UNSIGNED_BYTE, or copied)
  std::vector<float> values;
  int components() const { return kind == GL_COLOR || kind == GL_COLOR_INDEX ? 4 : 1; }
};

// The kind of image a format gives.
GLenum kindOf(GLenum format) {
  switch (format) {
    case GL_DEPTH_COMPONENT: return GL_DEPTH;
    case GL_STENCIL_INDEX: return GL_STENCIL;
    case GL_COLOR_INDEX: return GL_COLOR_INDEX;
    default: return GL_COLOR;
  }
}

// Reads the client image into `image` (sized already), before pixel transfer.
void unpackImage(const PixelStore& store, GLenum format, GLenum type, const void* data, PixelImage& image) {
  const int w = image.width, h = image.height;
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  if (format == GL_COLOR_INDEX) {
    std::vector<uint32_t> indices(n);
    unpackIndices(store, type, w, h, data, indices.data());
    std::fill(image.values.begin(), image.values.end(), 0.0f);
    for (size_t i = 0; i < n; ++i) image.values[i * 4] = static_cast<float>(indices[i] & 0xffu);
  } else if (format == GL_STENCIL_INDEX) {
    std::vector<uint32_t> indices(n);
    unpackIndices(store, type, w, h, data, indices.data());
    for (size_t i = 0; i < n; ++i) image.values[i] = static_cast<float>(indices[i] & 0xffu);
  } else if (format == GL_DEPTH_COMPONENT) {
    std::vector<float> rgba(n * 4);
    unpackColors(store, format, type, w, h, data, rgba.data());
    for (size_t i = 0; i < n; ++i) image.values[i] = rgba[i * 4];
  } else {
    unpackColors(store, format, type, w, h, data, image.values.data());
  }
}

// A transferred colour component as OSMesa's shader hands it to the 8-bit colour buffer: clamped
// and rounded to the nearest 8-bit value, halves to even (its conversion; primflow's renderer
// rounds its own way, 0.7 -- 178.49999 -- to 179), NaN as 0.
float colourByte(float c) {
  const float clamped = c > 0.0f ? std::min(c, 1.0f) : 0.0f;
  return std::nearbyint(clamped * 255.0f) / 255.0f;
}

// Pixel transfer as OSMesa applies it to an image about to be drawn (`copied`: glCopyPixels'):
// colours through scale, bias and the colour maps, indexed as OSMesa's 256-texel texture of the
// maps is; colour indices to colours through the index-to-RGBA maps (no shift or offset);
// glDrawPixels' depth values through depth scale and bias; stencil indices unchanged.
void transferImage(const PFcontextRec& ctx, PixelImage& image, bool copied) {
  const PixelTransferModes& modes = ctx.pixel_mode.transfer;
  const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
  if (image.kind == GL_COLOR && !modes.colorIdentity()) {
    if (image.bytes) byteColorsAsMesa(image.values.data(), n);  // (as llvmpipe samples them)
    transferColors(modes, ctx.pixel_maps, ColorMapIndex::kTexel256, image.values.data(), n);
    for (float& c : image.values) c = colourByte(c);
  } else if (image.kind == GL_COLOR_INDEX) {
    for (size_t i = 0; i < n; ++i) {
      const uint32_t index = static_cast<uint32_t>(image.values[i * 4]);
      indicesToColors(modes, ctx.pixel_maps, false, &index, 1, image.values.data() + i * 4);
    }
    for (float& c : image.values) c = colourByte(c);
    image.kind = GL_COLOR;
  } else if (image.kind == GL_DEPTH && !copied) {
    for (size_t i = 0; i < n; ++i) image.values[i] = transferDepth(modes, image.values[i]);
  }
}

// A window coordinate as an integer: clamped far outside any framebuffer, NaN too.
int windowInt(double v) { return v == v ? static_cast<int>(std::clamp(v, -1e9, 1e9)) : -1000000000; }

// The window rows or columns [lo, hi) whose centres lie between e0 and e1 (in either order): the
// half-open span [min, max) of the two edges.
void coveredSpan(double e0, double e1, double& lo, double& hi) {
  lo = std::min(e0, e1);
  hi = std::max(e0, e1);
}

// Writes a stencil image: each fragment's index through the scissor test and the write mask.
void drawStencil(PFcontextRec& ctx, const PixelImage& image, int x, int y, double zx, double zy) {
  if (ctx.stencil_bits <= 0 || !ctx.color) return;
  ctx.finish();  // the stencil buffer as drawn so far
  int clip[4] = {0, 0, ctx.width, ctx.height};
  if (ctx.fragment.scissor_test) {
    const int* s = ctx.fragment.scissor;
    clip[0] = std::max(clip[0], s[0]);
    clip[1] = std::max(clip[1], s[1]);
    clip[2] = static_cast<int>(std::min<int64_t>(clip[2], int64_t{s[0]} + s[2]));
    clip[3] = static_cast<int>(std::min<int64_t>(clip[3], int64_t{s[1]} + s[3]));
  }
  const uint8_t mask = static_cast<uint8_t>(ctx.fragment.stencil_write_mask & 0xffu);
  for (int j = 0; j < image.height; ++j) {
    double lo_y, hi_y;
    coveredSpan(y + zy * j, y + zy * (j + 1), lo_y, hi_y);
    const int r0 = std::max(clip[1], windowInt(std::ceil(lo_y - 0.5)));
    const int r1 = std::min(clip[3], windowInt(std::ceil(hi_y - 0.5)));
    for (int r = r0; r < r1; ++r)
      for (int i = 0; i < image.width; ++i) {
        double lo_x, hi_x;
        coveredSpan(x + zx * i, x + zx * (i + 1), lo_x, hi_x);
        const int c0 = std::max(clip[0], windowInt(std::ceil(lo_x - 0.5)));
        const int c1 = std::min(clip[2], windowInt(std::ceil(hi_x - 0.5)));
        const uint8_t v = static_cast<uint8_t>(image.values[static_cast<size_t>(j) * image.width + i]);
        for (int c = c0; c < c1; ++c) {
          uint8_t& s = ctx.stencil[static_cast<size_t>(r) * static_cast<size_t>(ctx.width) + static_cast<size_t>(c)];
          s = static_cast<uint8_t>((s & ~mask) | (v & mask));
        }
      }
  }
}

// Draws `image` at the raster position with the zoom; nothing when the position is invalid.
void drawImage(PFcontextRec& ctx, const PixelImage& image) {
  const RasterPosState& r = ctx.raster;
  if (!r.valid || image.width <= 0 || image.height <= 0) return;
  const auto round = [](float v) {  // Mesa's IROUND: halves away from zero
    return windowInt(v >= 0.0f ? std::floor(v + 0.5f) : std::ceil(v - 0.5f));
  };
  const int x = round(r.position.x), y = round(r.position.y);
  const double zx = ctx.pixel_mode.zoom_x, zy = ctx.pixel_mode.zoom_y;
  if (image.kind == GL_STENCIL) return drawStencil(ctx, image, x, y, zx, zy);
  PixelRectangles draw(ctx, r.position.z);
  for (int j = 0; j < image.height && draw.drawing(); ++j) {
    double lo_y, hi_y;
    coveredSpan(y + zy * j, y + zy * (j + 1), lo_y, hi_y);
    if (hi_y <= 0.0 || lo_y >= ctx.height || lo_y == hi_y) continue;  // (no row of the window)
    const float* row = image.values.data() + static_cast<size_t>(j) * image.width * image.components();
    // One rectangle per run of equal pixels.
    for (int i = 0; i < image.width;) {
      const float* p = row + static_cast<size_t>(i) * image.components();
      int end = i + 1;
      while (end < image.width &&
             std::memcmp(row + static_cast<size_t>(end) * image.components(), p, sizeof(float) * image.components()) == 0)
        ++end;
      double lo_x, hi_x;
      coveredSpan(x + zx * i, x + zx * end, lo_x, hi_x);
      if (hi_x > 0.0 && lo_x < ctx.width) {
        const float x0 = static_cast<float>(std::max(lo_x, -1.0)), x1 = static_cast<float>(std::min(hi_x, ctx.width + 1.0));
        const float y0 = static_cast<float>(std::max(lo_y, -1.0)), y1 = static_cast<float>(std::min(hi_y, ctx.height + 1.0));
        if (image.kind == GL_DEPTH)
          draw.add(x0, y0, x1, y1, r.color, std::clamp(p[0], 0.0f, 1.0f));
        else
          draw.add(x0, y0, x1, y1, glm::vec4(p[0], p[1], p[2], p[3]));
      }
      i = end;
    }
  }
}

// glDrawPixels' checks (Mesa's order); GL_NO_ERROR when it may draw.
GLenum drawPixelsError(const PFcontextRec& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type) {
  if (ctx.in_begin) return GL_INVALID_OPERATION;
  if (width < 0 || height < 0) return GL_INVALID_VALUE;
  if (const GLenum e = checkDrawFormatAndType(format, type); e != GL_NO_ERROR) return e;
  if ((format == GL_STENCIL_INDEX && ctx.stencil_bits <= 0) || (format == GL_DEPTH_COMPONENT && ctx.depth_bits <= 0))
    return GL_INVALID_OPERATION;
  return GL_NO_ERROR;
}

// A recorded glDrawPixels: these words, then (values) the image unpacked, its floats.
struct RecordedDrawPixels {
  GLsizei width, height;
  GLenum format, type;
  uint32_t values;  // how many floats follow: 0 for an image not read (an error, NULL, empty)
};
constexpr uint32_t kRecordedWords = (sizeof(RecordedDrawPixels) + 3) / 4;

// The largest image primflow takes, in pixels (2^26: 1 GiB of RGBA floats); a larger one is
// GL_OUT_OF_MEMORY rather than an allocation the system might grant and then not back.
constexpr int64_t kMaxImagePixels = int64_t{1} << 26;

// Allocates the image's values; false (GL_OUT_OF_MEMORY) if they do not fit.
bool sizeImage(PFcontextRec& ctx, PixelImage& image, const char* command) {
  if (int64_t{image.width} * image.height > kMaxImagePixels) {  // (nothing else dropped)
    std::fprintf(stderr, "primflow: %s: an image of more than 2^26 pixels: GL_OUT_OF_MEMORY\n", command);
    ctx.setError(GL_OUT_OF_MEMORY);
    return false;
  }
  try {
    image.values.resize(static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                        static_cast<size_t>(image.components()));
  } catch (const std::bad_alloc&) {
    ctx.outOfMemory(command);
    return false;
  } catch (const std::length_error&) {
    ctx.outOfMemory(command);
    return false;
  }
  return true;
}

}  // namespace

uint32_t replayDrawPixels(PFcontextRec& ctx, const uint32_t* args) {
  RecordedDrawPixels d;
  std::memcpy(&d, args, sizeof d);
  if (const GLenum e = drawPixelsError(ctx, d.width, d.height, d.format, d.type); e != GL_NO_ERROR) {
    ctx.setError(e);
  } else if (d.values > 0 && ctx.raster.valid) {
    PixelImage image;
    image.kind = kindOf(d.format);
    image.bytes = d.type == GL_UNSIGNED_BYTE;
    image.width = d.width;
    image.height = d.height;
    if (sizeImage(ctx, image, "glCallList")) {
      std::memcpy(image.values.data(), args + kRecordedWords, sizeof(float) * d.values);
      transferImage(ctx, image, false);
      drawImage(ctx, image);
    }
  }
  return kRecordedWords + d.values;
}

namespace cmd {

void pixelZoom(PFcontextRec& ctx, GLfloat xfactor, GLfloat yfactor) {
  if (!outsideBegin(ctx)) return;
  ctx.pixel_mode.zoom_x = xfactor;
  ctx.pixel_mode.zoom_y = yfactor;
}

void copyPixels(PFcontextRec& ctx, GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  if (!outsideBegin(ctx)) return;
  if (width < 0 || height < 0) return ctx.setError(GL_INVALID_VALUE);
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) return ctx.setError(GL_INVALID_ENUM);
  if ((type == GL_DEPTH && ctx.depth_bits <= 0) || (type == GL_STENCIL && ctx.stencil_bits <= 0))
    return ctx.setError(GL_INVALID_OPERATION);
  if (!ctx.raster.valid || width == 0 || height == 0 || !ctx.color) return;
  // The source clipped to the framebuffer (pixels outside it give no fragments), the
  // destination moved with it; read whole before anything is drawn, so that overlapping
  // rectangles copy what was there.
  const int64_t sx0 = std::max<int64_t>(x, 0), sy0 = std::max<int64_t>(y, 0);
  const int64_t sx1 = std::min<int64_t>(int64_t{x} + width, ctx.width), sy1 = std::min<int64_t>(int64_t{y} + height, ctx.height);
  if (sx0 >= sx1 || sy0 >= sy1) return;
  PixelImage image;
  image.kind = type;
  image.bytes = true;
  image.width = static_cast<int>(sx1 - sx0);
  image.height = static_cast<int>(sy1 - sy0);
  if (!sizeImage(ctx, image, "glCopyPixels")) return;
  ctx.finish();  // the buffers as drawn so far
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      const size_t at = static_cast<size_t>(sy0 + j) * static_cast<size_t>(ctx.width) + static_cast<size_t>(sx0 + i);
      float* out = image.values.data() + (static_cast<size_t>(j) * image.width + i) * image.components();
      if (type == GL_COLOR)
        for (int c = 0; c < 4; ++c) out[c] = ctx.color[at * 4 + c] / 255.0f;
      else if (type == GL_DEPTH)
        out[0] = ctx.depth[at];
      else
        out[0] = ctx.stencil[at];
    }
  // (The raster position moved by the clipped part: the source pixel (sx0, sy0) lands where
  // pixel (x, y) would have, offset by the zoom.)
  RasterPosState& r = ctx.raster;
  const RasterPosState saved = r;
  r.position.x += static_cast<float>((sx0 - x) * static_cast<double>(ctx.pixel_mode.zoom_x));
  r.position.y += static_cast<float>((sy0 - y) * static_cast<double>(ctx.pixel_mode.zoom_y));
  transferImage(ctx, image, true);
  drawImage(ctx, image);
  r = saved;
}

}  // namespace cmd
}  // namespace pf

void pfglDrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type, const GLvoid* pixels) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  const GLenum error = pf::drawPixelsError(*ctx, width, height, format, type);
  const bool readable = pixels && width > 0 && height > 0 && pf::checkDrawFormatAndType(format, type) == GL_NO_ERROR;
  pf::PixelImage image;
  image.kind = pf::kindOf(format);
  image.bytes = type == GL_UNSIGNED_BYTE;
  image.width = std::max(width, 0);
  image.height = std::max(height, 0);
  if (ctx->lists.compiling) {
    // The image unpacked now, when GL would accept its format; the checks run when the list does.
    if (readable && !pf::sizeImage(*ctx, image, "glDrawPixels")) return;
    if (readable) pf::unpackImage(ctx->unpack, format, type, pixels, image);
    const pf::RecordedDrawPixels d{width, height, format, type, static_cast<uint32_t>(image.values.size())};
    uint32_t* at = pf::record(*ctx, pf::GlOp::DrawPixels, pf::kRecordedWords + image.values.size());
    if (!at) return;
    std::memcpy(at, &d, sizeof d);
    if (!image.values.empty()) std::memcpy(at + pf::kRecordedWords, image.values.data(), sizeof(float) * image.values.size());
    if (!ctx->lists.execute) return;
  }
  if (error != GL_NO_ERROR) return ctx->setError(error);
  if (!readable || !ctx->raster.valid) return;
  if (image.values.empty()) {
    if (!pf::sizeImage(*ctx, image, "glDrawPixels")) return;
    pf::unpackImage(ctx->unpack, format, type, pixels, image);
  }
  pf::transferImage(*ctx, image, false);
  pf::drawImage(*ctx, image);
}

void pfglPixelZoom(GLfloat xfactor, GLfloat yfactor) { pf::dispatch<pf::GlOp::PixelZoom>(xfactor, yfactor); }
void pfglCopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  pf::dispatch<pf::GlOp::CopyPixels>(x, y, width, height, type);
}
