// Texture images (GL 1.5 sections 3.8.1-3.8.3, 6.1.4): glTexImage1D/2D (and their proxies),
// glTexSubImage1D/2D, glCopyTexImage1D/2D, glCopyTexSubImage1D/2D, glGetTexImage and
// glGetTexLevelParameter, with GL's errors in Mesa's order. Client images are read by the
// unpack modes (pixel_transfer.h) a row at a time, through pixel transfer (pixel_maps.h, as
// OSMesa applies it: colours through scale, bias and the colour maps; colour indices through
// index shift and offset and the index-to-RGBA maps; glCopyTexImage's colours as client
// colours), into 8-bit RGBA levels; glGetTexImage applies none. A level a recorded draw still
// samples is copied before it changes (textures.h). A display list records glTexImage /
// glTexSubImage with the image already unpacked (GL 1.5 section 5.4: the unpack modes in effect
// when the list is compiled) and transfers it when the list runs.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/pixel_maps.h"
#include "api/src/pixel_transfer.h"

namespace pf {
namespace {

// The base format of an internal format GL 1.x accepts (1-4 and table 3.16's names).
bool baseOf(GLint internal, TextureBase& base) {
  switch (internal) {
    case GL_ALPHA: case GL_ALPHA4: case GL_ALPHA8: case GL_ALPHA12: case GL_ALPHA16:
      base = TextureBase::Alpha; return true;
    case 1: case GL_LUMINANCE: case GL_LUMINANCE4: case GL_LUMINANCE8: case GL_LUMINANCE12: case GL_LUMINANCE16:
      base = TextureBase::Luminance; return true;
    case 2: case GL_LUMINANCE_ALPHA: case GL_LUMINANCE4_ALPHA4: case GL_LUMINANCE6_ALPHA2: case GL_LUMINANCE8_ALPHA8:
    case GL_LUMINANCE12_ALPHA4: case GL_LUMINANCE12_ALPHA12: case GL_LUMINANCE16_ALPHA16:
      base = TextureBase::LuminanceAlpha; return true;
    case GL_INTENSITY: case GL_INTENSITY4: case GL_INTENSITY8: case GL_INTENSITY12: case GL_INTENSITY16:
      base = TextureBase::Intensity; return true;
    case 3: case GL_RGB: case GL_R3_G3_B2: case GL_RGB4: case GL_RGB5: case GL_RGB8: case GL_RGB10: case GL_RGB12:
    case GL_RGB16:
      base = TextureBase::Rgb; return true;
    case 4: case GL_RGBA: case GL_RGBA2: case GL_RGBA4: case GL_RGB5_A1: case GL_RGBA8: case GL_RGB10_A2:
    case GL_RGBA12: case GL_RGBA16:
      base = TextureBase::Rgba; return true;
    default: return false;
  }
}

uint8_t unorm8(float v) { return static_cast<uint8_t>(std::nearbyint((v > 0.0f ? std::min(v, 1.0f) : 0.0f) * 255.0f)); }

// An RGBA colour as a texel of `base` (table 3.15: luminance and intensity from red).
void storeTexel(TextureBase base, const float* c, uint8_t* t) {
  const uint8_t r = unorm8(c[0]), g = unorm8(c[1]), b = unorm8(c[2]), a = unorm8(c[3]);
  switch (base) {
    case TextureBase::Alpha: t[0] = t[1] = t[2] = 0, t[3] = a; break;
    case TextureBase::Luminance: t[0] = t[1] = t[2] = r, t[3] = 255; break;
    case TextureBase::LuminanceAlpha: t[0] = t[1] = t[2] = r, t[3] = a; break;
    case TextureBase::Intensity: t[0] = t[1] = t[2] = t[3] = r; break;
    case TextureBase::Rgb: t[0] = r, t[1] = g, t[2] = b, t[3] = 255; break;
    case TextureBase::Rgba: t[0] = r, t[1] = g, t[2] = b, t[3] = a; break;
  }
}

// Where an image's pixels come from: client memory by the unpack modes, unpacked words
// recorded by a display list, or the colour buffer (glCopyTexImage). Its pixels are colours, or
// colour indices (format GL_COLOR_INDEX), before pixel transfer.
struct ImageSource {
  const PixelStore* store = nullptr;
  GLenum format = GL_RGBA, type = GL_UNSIGNED_BYTE;
  const void* data = nullptr;           // client memory (null: no image, the texels undefined: 0)
  const uint32_t* recorded = nullptr;   // or recorded: 4 floats a pixel, or 1 index a colour index
  const PFcontextRec* frame = nullptr;  // or the colour buffer from (x, y)
  int x = 0, y = 0;
  int width = 0;                        // the source's row length in pixels

  bool indices() const { return format == GL_COLOR_INDEX; }
  bool present() const { return data || recorded || frame; }

  // Row `row`, pixels [first, first + n), of a colour source into out (4 floats a pixel).
  void readColors(int row, int first, int n, float* out, std::vector<float>& scratch) const {
    if (recorded) {
      std::memcpy(out, recorded + (static_cast<size_t>(row) * width + first) * 4, sizeof(float) * 4 * static_cast<size_t>(n));
    } else if (frame) {
      for (int i = 0; i < n; ++i) {
        const long fx = static_cast<long>(x) + first + i, fy = static_cast<long>(y) + row;
        const bool inside = fx >= 0 && fy >= 0 && fx < frame->width && fy < frame->height && frame->color;
        for (int k = 0; k < 4; ++k)
          out[i * 4 + k] = inside ? frame->color[(static_cast<size_t>(fy) * frame->width + fx) * 4 + k] / 255.0f : 0.0f;
      }
    } else {
      PixelStore s = *store;
      s.skip_rows += row;
      scratch.resize(static_cast<size_t>(width) * 4);
      unpackColors(s, format, type, width, 1, data, scratch.data());
      std::copy(scratch.begin() + first * 4, scratch.begin() + (first + n) * 4, out);
    }
  }

  // The same of a colour-index source, into out (1 index a pixel).
  void readIndices(int row, int first, int n, uint32_t* out, std::vector<uint32_t>& scratch) const {
    if (recorded) {
      std::copy(recorded + static_cast<size_t>(row) * width + first, recorded + static_cast<size_t>(row) * width + first + n, out);
      return;
    }
    PixelStore s = *store;
    s.skip_rows += row;
    scratch.resize(static_cast<size_t>(width));
    unpackIndices(s, type, width, 1, data, scratch.data());
    std::copy(scratch.begin() + first, scratch.begin() + first + n, out);
  }
};

// Row `row`, pixels [first, first + n), of `src` into out (4 floats a pixel) through pixel
// transfer: the one place every texture image path converts to RGBA. No image: 0.
void readTransferred(const PFcontextRec& ctx, const ImageSource& src, int row, int first, int n, float* out,
                     std::vector<float>& scratch, std::vector<uint32_t>& indices) {
  if (!src.present()) {
    std::fill(out, out + static_cast<size_t>(n) * 4, 0.0f);
  } else if (src.indices()) {
    std::vector<uint32_t> row_indices(static_cast<size_t>(n));
    src.readIndices(row, first, n, row_indices.data(), indices);
    indicesToColors(ctx.pixel_mode.transfer, ctx.pixel_maps, true, row_indices.data(), static_cast<size_t>(n), out);
  } else {
    src.readColors(row, first, n, out, scratch);
    const PixelTransferModes& modes = ctx.pixel_mode.transfer;
    if (modes.colorIdentity()) return;
    if (src.frame || src.type == GL_UNSIGNED_BYTE) byteColorsAsMesa(out, static_cast<size_t>(n));
    transferColors(modes, ctx.pixel_maps, ColorMapIndex::kNearest, out, static_cast<size_t>(n));
  }
}

bool isProxy(GLenum target) { return target == GL_PROXY_TEXTURE_1D || target == GL_PROXY_TEXTURE_2D; }

// The texture image targets of a glTexImage of `dims` dimensions (proxies with `proxy`).
bool imageTarget(int dims, GLenum target, bool proxy) {
  if (dims == 1) return target == GL_TEXTURE_1D || (proxy && target == GL_PROXY_TEXTURE_1D);
  return target == GL_TEXTURE_2D || (proxy && target == GL_PROXY_TEXTURE_2D);
}

// Mesa's check of the external format and type for a colour texture: a depth or stencil
// format cannot fill one; colour indices can (of a basic type, or bits), through the pixel maps.
GLenum textureFormatError(GLenum format, GLenum type) {
  const bool basic = type != GL_BITMAP && checkColorFormatAndType(GL_RGBA, type) == GL_NO_ERROR;
  if (format == GL_COLOR_INDEX) {
    if (type == GL_BITMAP || (basic && checkColorFormatAndType(GL_LUMINANCE, type) == GL_NO_ERROR)) return GL_NO_ERROR;
    return checkColorFormatAndType(GL_LUMINANCE, type);  // (a packed type: GL_INVALID_OPERATION)
  }
  if ((format == GL_DEPTH_COMPONENT || format == GL_STENCIL_INDEX) && basic) return GL_INVALID_OPERATION;
  return checkColorFormatAndType(format, type);
}

// Whether a level's size (border included) is one GL allows (Mesa's _mesa_legal_texture_dimensions
// with non-power-of-two sizes, as llvmpipe has them).
bool legalSize(int dims, int level, int width, int height, int border) {
  const int max = kMaxTextureSize >> level;
  if (width < 2 * border || width - 2 * border > max) return false;
  if (dims == 2 && (height < 2 * border || height - 2 * border > max)) return false;
  return true;
}

// The level being changed, copied first if a recorded draw still samples it.
TextureLevel* writableLevel(TextureImage& img) {
  if (img.level.use_count() > 1) img.level = std::make_shared<TextureLevel>(*img.level);
  return const_cast<TextureLevel*>(img.level.get());
}

// Fills `level`'s texels [x0, x0 + w) x [y0, y0 + h) from `src` (its pixels from (sx, sy)).
void fill(const PFcontextRec& ctx, TextureLevel& level, TextureBase base, int x0, int y0, int w, int h,
          const ImageSource& src, int sx, int sy) {
  std::vector<float> row(static_cast<size_t>(w) * 4), scratch;
  std::vector<uint32_t> indices;
  for (int j = 0; j < h; ++j) {
    readTransferred(ctx, src, sy + j, sx, w, row.data(), scratch, indices);
    uint8_t* t = level.texels.data() + (static_cast<size_t>(y0 + j) * level.width + x0) * 4;
    for (int i = 0; i < w; ++i) storeTexel(base, row.data() + i * 4, t + i * 4);
  }
}

void texImage(PFcontextRec& ctx, int dims, GLenum target, GLint level, GLint internal, GLsizei width, GLsizei height,
              GLint border, GLenum format, GLenum type, const ImageSource& src, bool copy = false) {
  if (!outsideBegin(ctx)) return;
  if (!imageTarget(dims, target, !copy)) return ctx.setError(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return ctx.setError(GL_INVALID_VALUE);
  if (border < 0 || border > 1) return ctx.setError(GL_INVALID_VALUE);
  if (width < 0 || height < 0) return ctx.setError(GL_INVALID_VALUE);
  TextureBase base;
  if (!copy) {
    if (const GLenum e = textureFormatError(format, type); e != GL_NO_ERROR) return ctx.setError(e);
    if (!baseOf(internal, base)) return ctx.setError(GL_INVALID_VALUE);
  } else if (!baseOf(internal, base)) {
    return ctx.setError(GL_INVALID_ENUM);
  }
  TextureState& t = ctx.textures;
  const bool proxy = isProxy(target);
  TextureImage& img = proxy ? (dims == 1 ? t.proxy_1d : t.proxy_2d)[level] : t.bound(target).images[level];
  if (!legalSize(dims, level, width, height, border)) {
    if (proxy) {
      img = TextureImage{};
      return;
    }
    return ctx.setError(GL_INVALID_VALUE);
  }
  // Mesa keeps no border texels: the image without its border (the border colour stands for them).
  const int w = width - 2 * border, h = dims == 1 ? 1 : height - 2 * border;
  if (proxy) {
    img = TextureImage{nullptr, internal, base, w, h};
    return;
  }
  t.unit.reset();
  t.dirty = true;
  try {
    auto fresh = std::make_shared<TextureLevel>();
    fresh->width = w;
    fresh->height = h;
    fresh->texels.assign(static_cast<size_t>(w) * static_cast<size_t>(h) * 4, 0);
    if (w > 0 && h > 0) fill(ctx, *fresh, base, 0, 0, w, h, src, border, dims == 1 ? 0 : border);
    img = TextureImage{w > 0 && h > 0 ? std::move(fresh) : nullptr, internal, base, w, h};
  } catch (const std::bad_alloc&) {
    ctx.setError(GL_OUT_OF_MEMORY);
  }
}

void texSubImage(PFcontextRec& ctx, int dims, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                 GLsizei height, GLenum format, GLenum type, const ImageSource& src, bool copy = false) {
  if (!outsideBegin(ctx)) return;
  if (!imageTarget(dims, target, false)) return ctx.setError(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return ctx.setError(GL_INVALID_VALUE);
  if (width < 0 || height < 0) return ctx.setError(GL_INVALID_VALUE);
  if (!copy)
    if (const GLenum e = textureFormatError(format, type); e != GL_NO_ERROR) return ctx.setError(e);
  TextureState& t = ctx.textures;
  TextureImage& img = t.bound(target).images[level];
  if (img.width <= 0 && !img.level) return ctx.setError(GL_INVALID_OPERATION);
  if (dims == 1) yoffset = 0, height = 1;
  if (xoffset < 0 || yoffset < 0 || static_cast<long>(xoffset) + width > img.width ||
      static_cast<long>(yoffset) + height > img.height)
    return ctx.setError(GL_INVALID_VALUE);
  if (width == 0 || height == 0 || !img.level) return;
  t.unit.reset();
  t.dirty = true;
  try {
    fill(ctx, *writableLevel(img), img.base, xoffset, yoffset, width, height, src, 0, 0);
  } catch (const std::bad_alloc&) {
    ctx.setError(GL_OUT_OF_MEMORY);
  }
}

// The recorded form of glTexImage / glTexSubImage: these words, then `words` more: the image
// unpacked, before pixel transfer (RGBA floats, or a colour index's one word a pixel).
struct RecordedImage {
  GLint dims, sub;
  GLenum target;
  GLint level, internal, xoffset, yoffset;
  GLsizei width, height;
  GLint border;
  GLenum format, type;
  uint32_t words;  // 0: no image (a NULL pointer, or one GL refuses when the list runs)
};
constexpr uint32_t kRecordedWords = sizeof(RecordedImage) / 4;
static_assert(sizeof(RecordedImage) % 4 == 0);

// glTexImage* / glTexSubImage* from an entry point: executed, recorded, or both. A proxy is
// never recorded (GL 1.5 section 5.4).
void issueImage(RecordedImage r, const void* pixels) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return;
  ImageSource client;
  client.store = &ctx->unpack;
  client.format = r.format;
  client.type = r.type;
  client.data = pixels;
  client.width = std::max(r.width, 0);
  auto run = [&](const ImageSource& src) {
    if (r.sub)
      texSubImage(*ctx, r.dims, r.target, r.level, r.xoffset, r.yoffset, r.width, r.height, r.format, r.type, src);
    else
      texImage(*ctx, r.dims, r.target, r.level, r.internal, r.width, r.height, r.border, r.format, r.type, src);
  };
  if (ctx->lists.compiling && !isProxy(r.target)) {
    // The image unpacked now, when GL would accept it; the command's checks run when the list does.
    const int h = r.dims == 1 ? 1 : r.height;
    // (At most GL_MAX_TEXTURE_SIZE squared texels -- a larger image is an error when the list runs;
    // one past memory leaves the command out with GL_OUT_OF_MEMORY, as any command recorded.)
    const bool readable = pixels && r.width > 0 && h > 0 && textureFormatError(r.format, r.type) == GL_NO_ERROR &&
                          r.width <= kMaxTextureSize + 2 && h <= kMaxTextureSize + 2;
    const uint64_t per_pixel = client.indices() ? 1 : 4;
    r.words = readable ? static_cast<uint32_t>(static_cast<uint64_t>(r.width) * h * per_pixel) : 0;
    uint32_t* at = record(*ctx, GlOp::TexImage, kRecordedWords + r.words);
    if (at) {
      std::memcpy(at, &r, sizeof r);
      uint32_t* out = at + kRecordedWords;
      std::vector<float> scratch, colors(static_cast<size_t>(r.width) * 4);
      std::vector<uint32_t> indices;
      for (int y = 0; y < h && r.words; ++y) {
        if (client.indices()) {
          client.readIndices(y, 0, r.width, out + static_cast<size_t>(y) * r.width, indices);
        } else {
          client.readColors(y, 0, r.width, colors.data(), scratch);
          std::memcpy(out + static_cast<size_t>(y) * r.width * 4, colors.data(), sizeof(float) * colors.size());
        }
      }
    }
    if (!ctx->lists.execute) return;
  }
  run(client);
}

}  // namespace

uint32_t replayTexImage(PFcontextRec& ctx, const uint32_t* args) {
  RecordedImage r;
  std::memcpy(&r, args, sizeof r);
  ImageSource src;
  src.recorded = r.words ? args + kRecordedWords : nullptr;
  src.format = r.format;
  src.type = r.type;
  src.width = r.width;
  // (A recorded image reads as already unpacked: its format and type only for the checks.)
  if (r.sub)
    texSubImage(ctx, r.dims, r.target, r.level, r.xoffset, r.yoffset, r.width, r.height, r.format, r.type, src);
  else
    texImage(ctx, r.dims, r.target, r.level, r.internal, r.width, r.height, r.border, r.format, r.type, src);
  return kRecordedWords + r.words;
}

namespace cmd {

void copyTexImage(PFcontextRec& ctx, GLint dims, GLenum target, GLint level, GLenum internal, GLint x, GLint y,
                  GLsizei width, GLsizei height, GLint border) {
  if (!outsideBegin(ctx)) return;
  ctx.finish();  // the colour buffer as drawn so far
  ImageSource src;
  src.frame = &ctx;
  src.x = x;
  src.y = y;
  texImage(ctx, dims, target, level, static_cast<GLint>(internal), width, dims == 1 ? 1 : height, border, GL_RGBA,
           GL_FLOAT, src, true);
}

void copyTexSubImage(PFcontextRec& ctx, GLint dims, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x,
                     GLint y, GLsizei width, GLsizei height) {
  if (!outsideBegin(ctx)) return;
  ctx.finish();
  ImageSource src;
  src.frame = &ctx;
  src.x = x;
  src.y = y;
  texSubImage(ctx, dims, target, level, xoffset, yoffset, width, dims == 1 ? 1 : height, GL_RGBA, GL_FLOAT, src, true);
}

}  // namespace cmd

namespace {

// A texel of `base` as glGetTexImage returns it (GL 2.1 table 6.1: luminance and intensity to
// red, the missing colour components 0, a missing alpha 1).
void loadTexel(TextureBase base, const uint8_t* t, float* c) {
  const float r = t[0] / 255.0f, g = t[1] / 255.0f, b = t[2] / 255.0f, a = t[3] / 255.0f;
  switch (base) {
    case TextureBase::Alpha: c[0] = c[1] = c[2] = 0, c[3] = a; break;
    case TextureBase::Luminance: c[0] = r, c[1] = c[2] = 0, c[3] = 1; break;
    case TextureBase::LuminanceAlpha: c[0] = r, c[1] = c[2] = 0, c[3] = a; break;
    case TextureBase::Intensity: c[0] = r, c[1] = c[2] = 0, c[3] = 1; break;
    case TextureBase::Rgb: c[0] = r, c[1] = g, c[2] = b, c[3] = 1; break;
    case TextureBase::Rgba: c[0] = r, c[1] = g, c[2] = b, c[3] = a; break;
  }
}

bool hasChannel(TextureBase base, GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_RED_SIZE: case GL_TEXTURE_GREEN_SIZE: case GL_TEXTURE_BLUE_SIZE:
      return base == TextureBase::Rgb || base == TextureBase::Rgba;
    case GL_TEXTURE_ALPHA_SIZE:
      return base == TextureBase::Alpha || base == TextureBase::LuminanceAlpha || base == TextureBase::Rgba;
    case GL_TEXTURE_LUMINANCE_SIZE: return base == TextureBase::Luminance || base == TextureBase::LuminanceAlpha;
    case GL_TEXTURE_INTENSITY_SIZE: return base == TextureBase::Intensity;
    default: return false;
  }
}

template <class T>
void getTexLevelParameter(GLenum target, GLint level, GLenum pname, T* params) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  const int dims = target == GL_TEXTURE_1D || target == GL_PROXY_TEXTURE_1D ? 1 : 2;
  if (!imageTarget(dims, target, true)) return ctx->setError(GL_INVALID_ENUM);
  if (level < 0 || level >= kMaxTextureLevels) return ctx->setError(GL_INVALID_VALUE);
  TextureState& t = ctx->textures;
  const TextureImage& img = isProxy(target) ? (dims == 1 ? t.proxy_1d : t.proxy_2d)[level] : t.bound(target).images[level];
  const bool defined = img.width > 0;
  double v = 0;
  switch (pname) {
    case GL_TEXTURE_WIDTH: v = img.width; break;
    case GL_TEXTURE_HEIGHT: v = img.height; break;
    case GL_TEXTURE_DEPTH: v = defined ? 1 : 0; break;
    case GL_TEXTURE_BORDER: v = 0; break;
    case GL_TEXTURE_INTERNAL_FORMAT: v = defined ? img.internal_format : 1; break;
    case GL_TEXTURE_RED_SIZE: case GL_TEXTURE_GREEN_SIZE: case GL_TEXTURE_BLUE_SIZE: case GL_TEXTURE_ALPHA_SIZE:
    case GL_TEXTURE_LUMINANCE_SIZE: case GL_TEXTURE_INTENSITY_SIZE:
      v = defined && hasChannel(img.base, pname) ? 8 : 0;  // every level is stored with 8 bits a component
      break;
    case GL_TEXTURE_COMPRESSED: v = 0; break;
    default: return ctx->setError(GL_INVALID_ENUM);
  }
  if (params) *params = static_cast<T>(v);
}

}  // namespace
}  // namespace pf

extern "C" {

void pfglTexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border, GLenum format,
                    GLenum type, const GLvoid* pixels) {
  pf::issueImage({1, 0, target, level, internalformat, 0, 0, width, 1, border, format, type, 0}, pixels);
}
void pfglTexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height, GLint border,
                    GLenum format, GLenum type, const GLvoid* pixels) {
  pf::issueImage({2, 0, target, level, internalformat, 0, 0, width, height, border, format, type, 0}, pixels);
}
void pfglTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLenum type,
                       const GLvoid* pixels) {
  pf::issueImage({1, 1, target, level, 0, xoffset, 0, width, 1, 0, format, type, 0}, pixels);
}
void pfglTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width, GLsizei height,
                       GLenum format, GLenum type, const GLvoid* pixels) {
  pf::issueImage({2, 1, target, level, 0, xoffset, yoffset, width, height, 0, format, type, 0}, pixels);
}
void pfglCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width, GLint border) {
  pf::dispatch<pf::GlOp::CopyTexImage>(1, target, level, internalformat, x, y, width, 1, border);
}
void pfglCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y, GLsizei width,
                        GLsizei height, GLint border) {
  pf::dispatch<pf::GlOp::CopyTexImage>(2, target, level, internalformat, x, y, width, height, border);
}
void pfglCopyTexSubImage1D(GLenum target, GLint level, GLint xoffset, GLint x, GLint y, GLsizei width) {
  pf::dispatch<pf::GlOp::CopyTexSubImage>(1, target, level, xoffset, 0, x, y, width, 1);
}
void pfglCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint x, GLint y, GLsizei width,
                           GLsizei height) {
  pf::dispatch<pf::GlOp::CopyTexSubImage>(2, target, level, xoffset, yoffset, x, y, width, height);
}

// The level's texels by the pack modes (nothing written for a level without an image).
void pfglGetTexImage(GLenum target, GLint level, GLenum format, GLenum type, GLvoid* pixels) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (target != GL_TEXTURE_1D && target != GL_TEXTURE_2D) return ctx->setError(GL_INVALID_ENUM);
  if (level < 0 || level >= pf::kMaxTextureLevels) return ctx->setError(GL_INVALID_VALUE);
  if (format == GL_COLOR_INDEX) return ctx->setError(GL_INVALID_ENUM);  // (not a texture's to give)
  if (const GLenum e = pf::textureFormatError(format, type); e != GL_NO_ERROR) return ctx->setError(e);
  const pf::TextureImage& img = ctx->textures.bound(target).images[level];
  if (!img.level || !pixels) return;
  const pf::TextureLevel& l = *img.level;
  try {
    std::vector<float> rgba(static_cast<size_t>(l.width) * 4);
    for (int y = 0; y < l.height; ++y) {
      for (int x = 0; x < l.width; ++x)
        pf::loadTexel(img.base, l.texels.data() + (static_cast<size_t>(y) * l.width + x) * 4, rgba.data() + x * 4);
      pf::PixelStore s = ctx->pack;
      s.skip_rows += y;
      pf::packColors(s, format, type, l.width, 1, rgba.data(), pixels);
    }
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
  }
}

void pfglGetTexLevelParameteriv(GLenum target, GLint level, GLenum pname, GLint* params) {
  pf::getTexLevelParameter(target, level, pname, params);
}
void pfglGetTexLevelParameterfv(GLenum target, GLint level, GLenum pname, GLfloat* params) {
  pf::getTexLevelParameter(target, level, pname, params);
}

}  // extern "C"
