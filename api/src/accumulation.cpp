// The accumulation buffer (GL 1.5 section 4.2.4): glAccum, glClearAccum and the buffer's part of
// glClear, with OSMesa's arithmetic. The buffer holds 16 signed bits per channel (Mesa's
// RGBA_SNORM16: 32767 is 1.0), and every operation works on the integers as Mesa's does, so that
// an accumulated image comes out as OSMesa's to the bit:
//   - a value scaled into the buffer is truncated toward zero to 32 bits and kept modulo 2^16
//     (x86's conversion, which Mesa's C cast compiles to), and sums wrap the same way -- GL leaves
//     results outside [-1, 1] undefined, and Mesa lets them wrap;
//   - GL_RETURN scales back in single precision and writes bytes rounded to nearest even, under
//     the colour mask.
// Every operation, and the buffer's clear, is limited to the scissor box when the scissor test is
// on. The buffer is not touched by drawing, so only glAccum waits for the frame to finish (it
// reads or writes the colour buffer).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf {
namespace {

// A float truncated to a 32-bit integer as x86's cvttss2si does it, which Mesa's C casts compile
// to: NaN and anything out of range give INT32_MIN ("integer indefinite").
int32_t truncateX86(float f) {
  return f >= -2147483648.0f && f < 2147483648.0f ? static_cast<int32_t>(f) : INT32_MIN;
}

// The low 16 bits of `i`, as a C cast to a short keeps them.
int16_t low16(int32_t i) { return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(i))); }

// A float converted to a 16-bit accumulation value as Mesa's `(GLshort) f` does on x86.
int16_t toAccum(float f) { return low16(truncateX86(f)); }

// a + b kept modulo 2^16 (Mesa's `short += short`).
int16_t wrapAdd(int16_t a, int16_t b) {
  return static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint16_t>(a) + static_cast<uint16_t>(b)));
}

// A colour in [0, 1] as a byte: rounded to nearest, a half to even, as Mesa packs floats into
// unsigned bytes (NaN: 0).
uint8_t toByte(float f) {
  if (!(f >= 0.0f)) return 0;
  if (f > 1.0f) return 255;
  return static_cast<uint8_t>(std::nearbyint(f * 255.0f));  // (the default rounding: to even)
}

// Mesa's FLOAT_TO_SHORT for the clear value in [-1, 1]: (trunc(65535 c) - 1) / 2, the division
// truncating toward zero (a NaN clear value wraps as it does there: to -1).
int16_t clearValue(float c) {
  const auto less_one = static_cast<int32_t>(static_cast<uint32_t>(truncateX86(65535.0f * c)) - 1u);
  return low16(less_one / 2);
}

// The pixels an operation covers: the framebuffer, cut to the scissor box under the scissor test.
PixelRect accumRect(const PFcontextRec& ctx) {
  PixelRect r{0, 0, ctx.width, ctx.height};
  const FragmentOps ops = fragmentOps(ctx.fragment, false);
  if (ops.scissor) {
    r.x0 = std::max(r.x0, ops.scissor_x0);
    r.y0 = std::max(r.y0, ops.scissor_y0);
    r.x1 = std::min(r.x1, ops.scissor_x1);
    r.y1 = std::min(r.y1, ops.scissor_y1);
  }
  return r;
}

// Calls f(accum, color) with the four channels of each pixel of the rectangle.
template <class F>
void forEachPixel(PFcontextRec& ctx, const PixelRect& r, F f) {
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) {
      const size_t at = (static_cast<size_t>(y) * ctx.width + static_cast<size_t>(x)) * 4;
      f(ctx.accum.data() + at, ctx.color + at);
    }
}

}  // namespace

// glClear's GL_ACCUM_BUFFER_BIT: the clear value into the buffer, within the scissor box. No
// buffer: nothing, as GL says.
void clearAccumBuffer(PFcontextRec& ctx) {
  if (ctx.accum.empty()) return;
  int16_t v[4];
  for (int k = 0; k < 4; ++k) v[k] = clearValue(ctx.accum_clear[k]);
  const PixelRect r = accumRect(ctx);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      std::copy(v, v + 4, ctx.accum.data() + (static_cast<size_t>(y) * ctx.width + static_cast<size_t>(x)) * 4);
}

namespace cmd {

void clearAccum(PFcontextRec& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  if (!outsideBegin(ctx)) return;
  const GLfloat v[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) ctx.accum_clear[k] = std::clamp(v[k], -1.0f, 1.0f);  // (NaN stays NaN, as Mesa's CLAMP)
}

// GL_INVALID_ENUM for another op, GL_INVALID_OPERATION without an accumulation buffer (the
// enum checked first, as Mesa).
void accum(PFcontextRec& ctx, GLenum op, GLfloat value) {
  if (!outsideBegin(ctx)) return;
  if (op != GL_ACCUM && op != GL_LOAD && op != GL_RETURN && op != GL_MULT && op != GL_ADD)
    return ctx.setError(GL_INVALID_ENUM);
  if (ctx.accum_bits == 0) return ctx.setError(GL_INVALID_OPERATION);
  if (!ctx.color || ctx.accum.empty()) return;  // no drawable yet
  // Mesa skips the identities; their results are the same but for NaN, which they keep out.
  if ((op == GL_ADD || op == GL_ACCUM) && value == 0.0f) return;
  if (op == GL_MULT && value == 1.0f) return;
  const PixelRect r = accumRect(ctx);
  if (op == GL_ADD) {
    const int16_t step = toAccum(value * 32767.0f);
    return forEachPixel(ctx, r, [&](int16_t* acc, const uint8_t*) {
      for (int k = 0; k < 4; ++k) acc[k] = wrapAdd(acc[k], step);
    });
  }
  if (op == GL_MULT) {
    return forEachPixel(ctx, r, [&](int16_t* acc, const uint8_t*) {
      for (int k = 0; k < 4; ++k) acc[k] = toAccum(static_cast<float>(acc[k]) * value);
    });
  }
  ctx.finish();  // the rest read or write the colour buffer: the frame so far lands first
  if (op == GL_LOAD || op == GL_ACCUM) {
    const float scale = value * 32767.0f;
    const bool load = op == GL_LOAD;
    return forEachPixel(ctx, r, [&](int16_t* acc, const uint8_t* rgba) {
      for (int k = 0; k < 4; ++k) {
        const int16_t v = toAccum(static_cast<float>(rgba[k]) * (1.0f / 255.0f) * scale);
        acc[k] = load ? v : wrapAdd(acc[k], v);
      }
    });
  }
  // GL_RETURN: the buffer times `value` into the colour buffer, the masked channels kept.
  const float scale = value / 32767.0f;
  const uint8_t mask = ctx.color_mask;
  forEachPixel(ctx, r, [&](const int16_t* acc, uint8_t* rgba) {
    for (int k = 0; k < 4; ++k)
      if (mask & (1u << k)) rgba[k] = toByte(static_cast<float>(acc[k]) * scale);
  });
  ctx.frame_changed = true;  // (OSMesa's frame hook copies it out at the next glFinish / glFlush)
}

}  // namespace cmd
}  // namespace pf

extern "C" {

void pfglAccum(GLenum op, GLfloat value) { pf::dispatch<pf::GlOp::Accum>(op, value); }
void pfglClearAccum(GLfloat red, GLfloat green, GLfloat blue, GLfloat alpha) {
  pf::dispatch<pf::GlOp::ClearAccum>(red, green, blue, alpha);
}

}  // extern "C"
