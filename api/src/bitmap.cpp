// glBitmap (GL 1.5 section 3.7): a bitmap unpacked by glPixelStore's unpack modes, drawn at the
// current raster position -- its origin at floor(raster position - (xorig, yorig)), as Mesa
// rounds (with Mesa's 1e-4 nudge, so that a position that lands a float's error short of a
// pixel boundary is not a pixel off) -- as fragments of the raster colour, depth, texture
// coordinates and distance where its bits are set; then the raster position moves by (xmove,
// ymove). An invalid raster position draws and moves nothing. In a display list the bitmap is
// unpacked when the list is compiled, as GL says (section 5.4).
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
#include "api/src/pixel_rectangles.h"
#include "api/src/pixel_transfer.h"

namespace pf {
namespace {

// A recorded glBitmap: these words, then (has_bits) the bitmap unpacked, a byte a pixel.
struct RecordedBitmap {
  GLsizei width, height;
  GLfloat xorig, yorig, xmove, ymove;
  uint32_t has_bits;
};
constexpr uint32_t kRecordedWords = (sizeof(RecordedBitmap) + 3) / 4;

// A window coordinate as an integer, clamped far outside any framebuffer (NaN too).
int windowInt(double v) { return v == v ? static_cast<int>(std::clamp(std::floor(v), -1e9, 1e9)) : -1000000000; }

// glBitmap after its arguments are read: `bits` one byte a pixel (null: nothing to draw).
void bitmap(PFcontextRec& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
            GLfloat ymove, const unsigned char* bits) {
  if (!outsideBegin(ctx)) return;
  if (width < 0 || height < 0) return ctx.setError(GL_INVALID_VALUE);
  RasterPosState& r = ctx.raster;
  if (!r.valid) return;
  if (bits && width > 0 && height > 0) {
    const float epsilon = 0.0001f;
    const int x = windowInt(r.position.x + epsilon - xorig);
    const int y = windowInt(r.position.y + epsilon - yorig);
    PixelRectangles draw(ctx, r.position.z);
    // Only the rows and columns inside the window: one rectangle per run of set bits.
    const int j0 = std::max(0, -y), j1 = static_cast<int>(std::min<int64_t>(height, int64_t{ctx.height} - y));
    const int i0 = std::max(0, -x), i1 = static_cast<int>(std::min<int64_t>(width, int64_t{ctx.width} - x));
    for (int j = j0; j < j1 && draw.drawing(); ++j) {
      const unsigned char* row = bits + static_cast<size_t>(j) * static_cast<size_t>(width);
      for (int i = i0; i < i1;) {
        if (!row[i]) {
          ++i;
          continue;
        }
        int end = i;
        while (end < i1 && row[end]) ++end;
        draw.add(static_cast<float>(x + i), static_cast<float>(y + j), static_cast<float>(x + end),
                 static_cast<float>(y + j + 1), r.color);
        i = end;
      }
    }
  }
  r.position.x += xmove;
  r.position.y += ymove;
}

}  // namespace

uint32_t replayBitmap(PFcontextRec& ctx, const uint32_t* args) {
  RecordedBitmap b;
  std::memcpy(&b, args, sizeof b);
  const size_t bytes = b.has_bits ? static_cast<size_t>(b.width) * static_cast<size_t>(b.height) : 0;
  bitmap(ctx, b.width, b.height, b.xorig, b.yorig, b.xmove, b.ymove,
         b.has_bits ? reinterpret_cast<const unsigned char*>(args + kRecordedWords) : nullptr);
  return kRecordedWords + static_cast<uint32_t>((bytes + 3) / 4);
}

}  // namespace pf

void pfglBitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                const GLubyte* data) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  const bool compiling = ctx->lists.compiling;
  if (!compiling && (!pf::outsideBegin(*ctx) || !ctx->raster.valid || width < 0 || height < 0)) {
    // Nothing to unpack: the errors, or nothing done.
    pf::bitmap(*ctx, width, height, xorig, yorig, xmove, ymove, nullptr);
    return;
  }
  // The bitmap unpacked, a byte a pixel, into the list being compiled or for drawing now.
  const bool readable = data && width > 0 && height > 0;
  // (At most 2^28 bits, a GiB unpacked: a larger bitmap is GL_OUT_OF_MEMORY rather than an
  // allocation the system might grant and then not back.)
  if (readable && int64_t{width} * height > (int64_t{1} << 28)) {  // (nothing else dropped)
    std::fprintf(stderr, "primflow: glBitmap: a bitmap of more than 2^28 pixels: GL_OUT_OF_MEMORY\n");
    ctx->setError(GL_OUT_OF_MEMORY);
    return;
  }
  const size_t bytes = readable ? static_cast<size_t>(width) * static_cast<size_t>(height) : 0;
  std::vector<unsigned char> scratch;
  unsigned char* bits = nullptr;
  try {
    if (compiling) {
      pf::RecordedBitmap b{width, height, xorig, yorig, xmove, ymove, readable ? 1u : 0u};
      uint32_t* at = pf::record(*ctx, pf::GlOp::Bitmap, pf::kRecordedWords + (bytes + 3) / 4);
      if (!at) return;  // (GL_OUT_OF_MEMORY, the command left out)
      std::memcpy(at, &b, sizeof b);
      bits = reinterpret_cast<unsigned char*>(at + pf::kRecordedWords);
    } else if (readable) {
      scratch.resize(bytes);
      bits = scratch.data();
    }
  } catch (const std::bad_alloc&) {
    ctx->outOfMemory("glBitmap");
    return;
  } catch (const std::length_error&) {
    ctx->outOfMemory("glBitmap");
    return;
  }
  if (readable) pf::unpackBitmap(ctx->unpack, width, height, data, bits);
  if (compiling && !ctx->lists.execute) return;
  pf::bitmap(*ctx, width, height, xorig, yorig, xmove, ymove, readable ? bits : nullptr);
}
