// libFuzzer target for sequences of API calls (docs/reliability.md): the bytes are a program of
// GL-1.x and extension calls -- glBegin of every mode (and of no mode), vertices and values that
// are NaN, infinite or huge, matrix stacks pushed and popped past their ends, degenerate
// projections, bad enums and names, sequence points, compiles, clears and finishes, the
// per-fragment operations' state with any values (scissor, alpha test, blending, logic op,
// stencil), the raster position and pixel rectangles, point sizes, line widths, stipples, polygon modes, offsets and stipples, edge flags, a glBegin of very many vertices -- run on a small context. Nothing may crash, hang or trip ASan/UBSan, and
// GL's rules are checked (the checks trap, which libFuzzer reports): a glBegin whose only erring
// command is one GL does not allow there leaves exactly GL_INVALID_OPERATION at glEnd, and the
// glBegin of very many vertices leaves no error.
//
// Build and run locally: as fuzz_compile.cpp says, with --target fuzz_api and the corpus
// tests/fuzz/corpus/api.
#include <fuzzer/FuzzedDataProvider.h>
#include <primflow/gl.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "adversarial.h"

namespace {

constexpr int kSize = 24;
constexpr size_t kIterationCap = 256;  // the context's

float aFloat(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 7)) {
    case 0: return std::numeric_limits<float>::quiet_NaN();
    case 1: return std::numeric_limits<float>::infinity();
    case 2: return -1e30f;
    case 3: return 1e-30f;
    default: return in.ConsumeFloatingPointInRange<float>(-3.0f, 3.0f);
  }
}

GLenum aMode(FuzzedDataProvider& in) {
  static const GLenum kModes[] = {GL_POINTS, GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_STRIP,
                                  GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  return kModes[in.ConsumeIntegralInRange<size_t>(0, 9)];
}

GLenum aCapability(FuzzedDataProvider& in) {
  static const GLenum kCaps[] = {GL_DEPTH_TEST, GL_CULL_FACE,   GL_LIGHTING,   GL_LIGHT0,         GL_LIGHT7,
                                 GL_NORMALIZE,  GL_COLOR_MATERIAL, GL_SCISSOR_TEST, GL_TEXTURE_2D,  0x1234,  GL_TEXTURE_1D,
                                 GL_BLEND,      GL_ALPHA_TEST,  GL_STENCIL_TEST, GL_COLOR_LOGIC_OP, GL_DITHER,
                                 GL_FOG,        GL_CLIP_PLANE0, GL_CLIP_PLANE0 + 7,  GL_CLIP_PLANE0 + 8};
  return kCaps[in.ConsumeIntegralInRange<size_t>(0, sizeof(kCaps) / sizeof(kCaps[0]) - 1)];
}

// A command GL forbids between glBegin and glEnd.
void forbiddenInBegin(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 5)) {
    case 0: pfglEnable(GL_DEPTH_TEST); break;
    case 1: pfglViewport(0, 0, kSize, kSize); break;
    case 2: pfglClear(GL_COLOR_BUFFER_BIT); break;
    case 3: pfglMatrixMode(GL_MODELVIEW); break;
    case 4: pfglPushMatrix(); break;
    default: pfglBegin(GL_TRIANGLES); break;
  }
}

// One glBegin / glEnd of a GL mode; with `forbidden`, a command GL does not allow there.
void oneBegin(FuzzedDataProvider& in, bool forbidden) {
  // Out of any glBegin left open, the recorded drawing done (a flush at glEnd could raise an
  // earlier primitive's error) and the flag clear: the check below sees this glBegin's only.
  pfglEnd();
  pfglFinish();
  (void)pfglGetError();
  pfglBegin(aMode(in));
  const size_t n = in.ConsumeIntegralInRange<size_t>(0, 12);
  const size_t bad_at = forbidden ? in.ConsumeIntegralInRange<size_t>(0, n) : n + 1;
  for (size_t i = 0; i <= n; ++i) {
    if (i == bad_at) forbiddenInBegin(in);
    if (i == n) break;
    switch (in.ConsumeIntegralInRange<int>(0, 3)) {
      case 0: pfglColor4f(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
      case 1: pfglNormal3f(aFloat(in), aFloat(in), aFloat(in)); break;
      case 2: pfglEdgeFlag(in.ConsumeIntegral<GLboolean>()); break;  // any value, 0 false
      default: break;
    }
    pfglVertex3f(aFloat(in), aFloat(in), aFloat(in));
  }
  pfglEnd();
  const GLenum err = pfglGetError();
  if (err != static_cast<GLenum>(forbidden ? GL_INVALID_OPERATION : GL_NO_ERROR)) __builtin_trap();
}

// One glBegin / glEnd of any mode with about as many vertices as the calls a submission may
// make (32 times the iteration cap, where the triangles of a strip once stopped, reported as a
// runaway loop): drawn whole, no error. All but the last three vertices sit at one point. At
// most one an input.
void hugeBegin(FuzzedDataProvider& in, bool& drawn_one) {
  if (drawn_one) return;
  drawn_one = true;
  pfglEnd();
  pfglFinish();
  (void)pfglGetError();
  const GLenum mode = aMode(in);
  const size_t n = 32 * kIterationCap + in.ConsumeIntegralInRange<size_t>(0, 12) - 4;
  const float at = in.ConsumeFloatingPointInRange<float>(-1.0f, 1.0f);
  pfglBegin(mode);
  for (size_t i = 0; i + 3 < n; ++i) pfglVertex2f(at, at);
  pfglVertex2f(-0.5f, -0.5f);
  pfglVertex2f(0.5f, -0.5f);
  pfglVertex2f(0.0f, 0.5f);
  pfglEnd();
  pfglFinish();
  if (pfglGetError() != static_cast<GLenum>(GL_NO_ERROR)) __builtin_trap();
}

// The per-fragment operations' state, any values: the scissor box (extreme positions and
// sizes), the alpha test, blending, the logic op, the stencil test, the masks.
void fragmentState(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 6)) {
    case 0:
      pfglScissor(in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLsizei>(),
                  in.ConsumeIntegral<GLsizei>());
      break;
    case 1: pfglAlphaFunc(in.ConsumeIntegralInRange<GLenum>(GL_NEVER - 1, GL_ALWAYS + 1), aFloat(in)); break;
    case 2:
      pfglBlendFuncSeparate(in.ConsumeIntegralInRange<GLenum>(0, 0x8004), in.ConsumeIntegralInRange<GLenum>(0, 0x8004),
                            in.ConsumeIntegralInRange<GLenum>(0, 0x308), in.ConsumeIntegralInRange<GLenum>(0, 0x308));
      break;
    case 3:
      pfglBlendEquation(in.ConsumeIntegralInRange<GLenum>(0x8005, 0x800C));
      pfglBlendColor(aFloat(in), aFloat(in), aFloat(in), aFloat(in));
      break;
    case 4: pfglLogicOp(in.ConsumeIntegralInRange<GLenum>(GL_CLEAR - 1, GL_SET + 1)); break;
    case 5:
      pfglStencilFunc(in.ConsumeIntegralInRange<GLenum>(GL_NEVER - 1, GL_ALWAYS + 1), in.ConsumeIntegral<GLint>(),
                      in.ConsumeIntegral<GLuint>());
      pfglStencilOp(in.ConsumeIntegralInRange<GLenum>(0, GL_DECR_WRAP), in.ConsumeIntegralInRange<GLenum>(0, GL_DECR_WRAP),
                    in.ConsumeIntegralInRange<GLenum>(0, GL_DECR_WRAP));
      break;
    default:
      pfglStencilMask(in.ConsumeIntegral<GLuint>());
      pfglClearStencil(in.ConsumeIntegral<GLint>());
      pfglColorMask(in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool(), in.ConsumeBool());
      pfglDepthMask(in.ConsumeBool());
      break;
  }
}

// Texturing, any values: images of random sizes, levels, formats and types from a small buffer
// (the sizes kept within it, or a NULL image), sub-images anywhere, copies, parameters,
// environment and generation, bindings and deletions, texture coordinates.
void textureState(FuzzedDataProvider& in) {
  static std::vector<unsigned char> image(4096);
  for (size_t i = 0; i < image.size(); i += 61) image[i] = static_cast<unsigned char>(i * 13);
  const GLenum target = in.ConsumeBool() ? GL_TEXTURE_2D : in.ConsumeBool() ? GL_TEXTURE_1D : in.ConsumeIntegral<GLenum>();
  const GLenum formats[] = {GL_RGBA, GL_RGB, GL_BGRA, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA, GL_DEPTH_COMPONENT, 0x1234};
  const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_INT_2_10_10_10_REV,
                          GL_BITMAP, 0x1234};
  const GLenum format = formats[in.ConsumeIntegralInRange<size_t>(0, 7)];
  const GLenum type = types[in.ConsumeIntegralInRange<size_t>(0, 6)];
  // At most 8 x 8 texels of 16 bytes with unpack skips below: within the buffer.
  const GLsizei w = in.ConsumeIntegralInRange<GLsizei>(-2, 8), h = in.ConsumeIntegralInRange<GLsizei>(-2, 8);
  const GLint level = in.ConsumeIntegralInRange<GLint>(-1, 16);
  const void* data = in.ConsumeBool() ? image.data() : nullptr;
  switch (in.ConsumeIntegralInRange<int>(0, 9)) {
    case 0:
      pfglPixelStorei(GL_UNPACK_SKIP_PIXELS, in.ConsumeIntegralInRange<int>(0, 4));
      pfglPixelStorei(GL_UNPACK_ALIGNMENT, 1 << in.ConsumeIntegralInRange<int>(0, 3));
      pfglTexImage2D(target, level, in.ConsumeBool() ? GL_RGBA : in.ConsumeIntegralInRange<GLint>(0, 0x8100), w, h,
                     in.ConsumeIntegralInRange<GLint>(-1, 2), format, type, data);
      break;
    case 1: pfglTexImage1D(target, level, GL_RGB, w, in.ConsumeIntegralInRange<GLint>(0, 1), format, type, data); break;
    case 2:
      pfglTexSubImage2D(target, level, in.ConsumeIntegralInRange<GLint>(-3, 10), in.ConsumeIntegralInRange<GLint>(-3, 10), w,
                        h, format, type, data);
      break;
    case 3:
      pfglCopyTexImage2D(target, level, GL_RGBA, in.ConsumeIntegralInRange<GLint>(-100, 100),
                         in.ConsumeIntegralInRange<GLint>(-100, 100), w, h, 0);
      pfglCopyTexSubImage2D(target, level, 0, 0, in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLint>(), w, h);
      break;
    case 4: {
      const GLenum pnames[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
                               GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD};
      const GLenum values[] = {GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_LINEAR, GL_REPEAT,
                               GL_CLAMP, GL_CLAMP_TO_EDGE, GL_MIRRORED_REPEAT, GL_CLAMP_TO_BORDER, 0x1234};
      pfglTexParameteri(target, pnames[in.ConsumeIntegralInRange<size_t>(0, 7)], in.ConsumeBool()
                        ? static_cast<GLint>(values[in.ConsumeIntegralInRange<size_t>(0, 9)]) : in.ConsumeIntegral<GLint>());
      const float border[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
      pfglTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, border);
      break;
    }
    case 5: {
      const GLenum modes[] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD, GL_COMBINE};
      pfglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, static_cast<GLint>(modes[in.ConsumeIntegralInRange<size_t>(0, 5)]));
      const float c[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
      pfglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
      break;
    }
    case 6: {
      const GLenum coord = GL_S + in.ConsumeIntegralInRange<GLenum>(0, 4);
      const GLint gen_modes[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, 0};
      pfglTexGeni(coord, GL_TEXTURE_GEN_MODE, gen_modes[in.ConsumeIntegralInRange<size_t>(0, 3)]);
      const float plane[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
      pfglTexGenfv(coord, in.ConsumeBool() ? GL_OBJECT_PLANE : GL_EYE_PLANE, plane);
      (in.ConsumeBool() ? pfglEnable : pfglDisable)(GL_TEXTURE_GEN_S + in.ConsumeIntegralInRange<GLenum>(0, 3));
      break;
    }
    case 7: {
      GLuint names[3] = {in.ConsumeIntegralInRange<GLuint>(0, 5), 0, 0};
      if (in.ConsumeBool()) pfglGenTextures(in.ConsumeIntegralInRange<GLsizei>(-1, 3), names);
      pfglBindTexture(target, names[0]);
      if (in.ConsumeBool()) pfglDeleteTextures(in.ConsumeIntegralInRange<GLsizei>(-1, 3), names);
      break;
    }
    case 8: {
      std::vector<unsigned char> back(8 * 8 * 16 * 2);
      pfglGetTexImage(target, level, format, type, in.ConsumeBool() ? back.data() : nullptr);
      GLint v;
      pfglGetTexLevelParameteriv(target, level, in.ConsumeIntegralInRange<GLenum>(0x1000, 0x1006), &v);
      break;
    }
    default: pfglTexCoord4f(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
  }
}

// Fog and clip planes, any values: every fog pname (and others) with any floats or integers, the
// vector forms with a NULL pointer too; planes in and out of range, any equations (NaN, inf,
// zero), read back.
void fogClipState(FuzzedDataProvider& in) {
  const GLenum pname = in.ConsumeBool() ? in.ConsumeIntegralInRange<GLenum>(GL_FOG_INDEX, GL_FOG_MODE)
                                        : in.ConsumeIntegral<GLenum>();
  const float v[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
  const GLint iv[4] = {in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLint>(),
                       in.ConsumeIntegral<GLint>()};
  const GLenum plane = GL_CLIP_PLANE0 + in.ConsumeIntegralInRange<GLenum>(0, 9) - 1;
  const double eq[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
  double back[4];
  switch (in.ConsumeIntegralInRange<int>(0, 6)) {
    case 0: pfglFogf(pname, v[0]); break;
    case 1: pfglFogi(pname, iv[0]); break;
    case 2: pfglFogfv(pname, in.ConsumeBool() ? v : nullptr); break;
    case 3: pfglFogiv(pname, in.ConsumeBool() ? iv : nullptr); break;
    case 4: pfglFogi(GL_FOG_MODE, static_cast<GLint>(in.ConsumeBool() ? GL_LINEAR : GL_EXP2)); break;
    case 5: pfglClipPlane(plane, in.ConsumeBool() ? eq : nullptr); break;
    default: pfglGetClipPlane(plane, in.ConsumeBool() ? back : nullptr); break;
  }
}

// The accumulation buffer: any op (a known one mostly) with any value (NaN, inf, huge: the
// integer arithmetic wraps as Mesa's), any clear value, a clear of it, under whatever scissor box
// and colour mask the other calls left.
void accumulation(FuzzedDataProvider& in) {
  const GLenum op = in.ConsumeBool() ? in.ConsumeIntegralInRange<GLenum>(GL_ACCUM, GL_ADD) : in.ConsumeIntegral<GLenum>();
  switch (in.ConsumeIntegralInRange<int>(0, 2)) {
    case 0: pfglAccum(op, aFloat(in)); break;
    case 1: pfglClearAccum(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
    default: pfglClear(GL_ACCUM_BUFFER_BIT); break;
  }
}

// The raster position and pixel rectangles, any values: glRasterPos of NaN, infinite and huge
// coordinates (culled or not) and glWindowPos anywhere, then bitmaps of any size (negative too)
// and origin and move, with or without data, possibly compiled into a list and called.
void pixelRectangles(FuzzedDataProvider& in) {
  static std::vector<unsigned char> image(4096);
  for (size_t i = 0; i < image.size(); i += 7) image[i] = static_cast<unsigned char>(i * 29);
  // At most 40 x 40 bits with unpack skips of at most 4 pixels and alignment 8: within the buffer.
  const GLsizei w = in.ConsumeIntegralInRange<GLsizei>(-2, 40), h = in.ConsumeIntegralInRange<GLsizei>(-2, 40);
  const unsigned char* data = in.ConsumeBool() ? image.data() : nullptr;
  static const GLenum kFormats[] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX,
                                    GL_COLOR_INDEX, 0x1234};
  static const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_SHORT, GL_UNSIGNED_SHORT_5_6_5, GL_BITMAP, 0x1234};
  // (At most 40 x 40 pixels of 16 bytes would not fit: images at most 12 x 12, 16 bytes a pixel,
  // with skips of at most 4 pixels, alignment 8: within the buffer.)
  const GLsizei iw = std::min<GLsizei>(w, 12), ih = std::min<GLsizei>(h, 12);
  switch (in.ConsumeIntegralInRange<int>(0, 8)) {
    case 5:
      pfglDrawPixels(iw, ih, kFormats[in.ConsumeIntegralInRange<size_t>(0, 7)],
                     kTypes[in.ConsumeIntegralInRange<size_t>(0, 5)], data);
      break;
    case 6:
      pfglCopyPixels(in.ConsumeIntegralInRange<GLint>(-30, 30), in.ConsumeIntegralInRange<GLint>(-30, 30), w, h,
                     in.ConsumeBool() ? GL_COLOR : in.ConsumeBool() ? GL_DEPTH : in.ConsumeBool() ? GL_STENCIL : 0x1234);
      break;
    case 7: pfglPixelZoom(aFloat(in), aFloat(in)); break;
    case 8: pfglPixelZoom(in.ConsumeFloatingPointInRange<float>(-3.0f, 3.0f), in.ConsumeFloatingPointInRange<float>(-3.0f, 3.0f)); break;
    case 0: pfglRasterPos4f(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
    case 1: pfglRasterPos2i(in.ConsumeIntegralInRange<GLint>(-30, 30), in.ConsumeIntegralInRange<GLint>(-30, 30)); break;
    case 2: pfglWindowPos3f(aFloat(in) * 10.0f, aFloat(in) * 10.0f, aFloat(in)); break;
    case 3:
      pfglBitmap(w, h, aFloat(in), aFloat(in), aFloat(in) * 10.0f, aFloat(in) * 10.0f, data);
      break;
    default: {
      const bool execute = in.ConsumeBool();
      pfglNewList(7, execute ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
      pfglBitmap(w, h, aFloat(in), aFloat(in), aFloat(in), aFloat(in), data);
      pfglEndList();
      pfglCallList(7);
      break;
    }
  }
}

// Points, lines and polygon modes, any values: sizes and widths NaN, infinite, huge, zero or
// negative, any line stipple factor and pattern, polygon modes and offsets (bad enums too), any
// polygon stipple (or NULL), read back; then a glBegin of any mode drawn with them.
void rasterModeState(FuzzedDataProvider& in) {
  switch (in.ConsumeIntegralInRange<int>(0, 6)) {
    case 5: {
      // (512 bytes: the pattern under any unpack or pack mode this fuzzer sets, skips included.)
      std::vector<unsigned char> pattern(512);
      for (unsigned char& b : pattern) b = in.ConsumeIntegral<unsigned char>();
      pfglPolygonStipple(in.ConsumeBool() ? pattern.data() : nullptr);
      (in.ConsumeBool() ? pfglEnable : pfglDisable)(GL_POLYGON_STIPPLE);
      pfglGetPolygonStipple(in.ConsumeBool() ? pattern.data() : nullptr);
      break;
    }
    case 3:
      pfglPolygonMode(in.ConsumeBool() ? GL_FRONT_AND_BACK : in.ConsumeIntegralInRange<GLenum>(GL_FRONT - 1, GL_BACK + 1),
                      in.ConsumeIntegralInRange<GLenum>(GL_POINT - 1, GL_FILL + 1));
      break;
    case 4:
      pfglPolygonOffset(aFloat(in), aFloat(in));
      (in.ConsumeBool() ? pfglEnable : pfglDisable)(in.ConsumeBool() ? GL_POLYGON_OFFSET_FILL : GL_POLYGON_OFFSET_LINE);
      break;
    case 0: pfglPointSize(in.ConsumeBool() ? aFloat(in) : in.ConsumeFloatingPointInRange<float>(0.0f, 300.0f)); break;
    case 2:
      pfglLineStipple(in.ConsumeIntegral<GLint>(), in.ConsumeIntegral<GLushort>());
      (in.ConsumeBool() ? pfglEnable : pfglDisable)(GL_LINE_STIPPLE);
      break;
    case 1: pfglLineWidth(in.ConsumeBool() ? aFloat(in) : in.ConsumeFloatingPointInRange<float>(0.0f, 300.0f)); break;
    default:
      pfglBegin(aMode(in));
      for (int k = in.ConsumeIntegralInRange<int>(0, 4); k > 0; --k) pfglVertex2f(aFloat(in), aFloat(in));
      pfglEnd();
      break;
  }
}

// Pixel transfer, any values: glPixelTransfer of any mode (bad names too) and any float or
// integer (NaN, huge shifts and offsets), glPixelMap of any table, size (0, too large, not a power
// of two) and entries (NaN, inf), a NULL table too, possibly compiled into a list and called;
// tables read back; pixels read, drawn and copied under whatever the modes are.
void pixelTransferState(FuzzedDataProvider& in) {
  static std::vector<float> entries(300);
  static std::vector<GLuint> words(300);
  for (size_t i = 0; i < entries.size(); i += 3) entries[i] = static_cast<float>(i) * 0.01f - 0.5f;
  for (size_t i = 0; i < words.size(); i += 5) words[i] = static_cast<GLuint>(i * 2654435761u);
  const GLenum pname = in.ConsumeBool() ? in.ConsumeIntegralInRange<GLenum>(GL_MAP_COLOR - 1, GL_DEPTH_BIAS + 1)
                                        : in.ConsumeIntegral<GLenum>();
  const GLenum map = in.ConsumeIntegralInRange<GLenum>(GL_PIXEL_MAP_I_TO_I - 1, GL_PIXEL_MAP_A_TO_A + 1);
  const GLsizei size = in.ConsumeIntegralInRange<GLsizei>(-2, 300);
  const bool null = in.ConsumeBool();
  static GLfloat back_f[256];
  static GLuint back_ui[256];
  static GLushort back_us[256];
  static unsigned char pixels[4096];
  switch (in.ConsumeIntegralInRange<int>(0, 9)) {
    case 0: pfglPixelTransferf(pname, aFloat(in)); break;
    case 1: pfglPixelTransferi(pname, in.ConsumeIntegral<GLint>()); break;
    case 2: pfglPixelMapfv(map, size, null ? nullptr : entries.data()); break;
    case 3: pfglPixelMapuiv(map, size, null ? nullptr : words.data()); break;
    case 4: pfglPixelMapusv(map, size, null ? nullptr : reinterpret_cast<const GLushort*>(words.data())); break;
    case 5:
      pfglGetPixelMapfv(map, null ? nullptr : back_f);
      pfglGetPixelMapuiv(map, null ? nullptr : back_ui);
      pfglGetPixelMapusv(map, null ? nullptr : back_us);
      break;
    case 6: {
      const bool execute = in.ConsumeBool();
      pfglNewList(8, execute ? GL_COMPILE_AND_EXECUTE : GL_COMPILE);
      pfglPixelTransferf(pname, aFloat(in));
      pfglPixelMapfv(map, size, null ? nullptr : entries.data());
      pfglEndList();
      pfglCallList(8);
      break;
    }
    case 7: {
      static const GLenum kFormats[] = {GL_RGBA, GL_RGB, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX};
      static const GLenum kTypes[] = {GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT};
      pfglReadPixels(in.ConsumeIntegralInRange<GLint>(-4, 60), in.ConsumeIntegralInRange<GLint>(-4, 60), 8, 8,
                     kFormats[in.ConsumeIntegralInRange<size_t>(0, 3)], kTypes[in.ConsumeIntegralInRange<size_t>(0, 3)],
                     pixels);
      break;
    }
    case 8: {  // (8 x 8 pixels of at most 16 bytes, with the unpack skips textureState sets -- at most 4
               // rows and 4 pixels -- and alignment 8: within the buffer)
      static const GLenum kFormats[] = {GL_RGBA, GL_COLOR_INDEX, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX};
      pfglRasterPos2i(in.ConsumeIntegralInRange<GLint>(-10, 40), in.ConsumeIntegralInRange<GLint>(-10, 40));
      pfglDrawPixels(8, 8, kFormats[in.ConsumeIntegralInRange<size_t>(0, 3)], in.ConsumeBool() ? GL_FLOAT : GL_UNSIGNED_BYTE,
                     pixels);
      break;
    }
    default:
      pfglCopyPixels(in.ConsumeIntegralInRange<GLint>(-10, 40), in.ConsumeIntegralInRange<GLint>(-10, 40), 8, 8,
                     in.ConsumeBool() ? GL_COLOR : in.ConsumeBool() ? GL_DEPTH : GL_STENCIL);
      break;
  }
}

void oneCall(FuzzedDataProvider& in, bool& huge_drawn) {
  switch (in.ConsumeIntegralInRange<int>(0, 27)) {
    case 0: oneBegin(in, in.ConsumeBool()); break;
    case 19: hugeBegin(in, huge_drawn); break;
    case 1: pfglBegin(in.ConsumeIntegral<GLenum>()); break;  // any enum, a primitive's mode or none
    case 2: pfglEnd(); break;
    case 3: pfglVertex4f(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
    case 4: (in.ConsumeBool() ? pfglEnable : pfglDisable)(aCapability(in)); break;
    case 5: pfglMatrixMode(in.ConsumeBool() ? GL_PROJECTION : in.ConsumeBool() ? GL_MODELVIEW : 0x1234); break;
    case 6: for (int k = in.ConsumeIntegralInRange<int>(0, 40); k > 0; --k) pfglPushMatrix(); break;
    case 7: for (int k = in.ConsumeIntegralInRange<int>(0, 40); k > 0; --k) pfglPopMatrix(); break;
    case 8: pfglRotatef(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
    case 9: pfglScalef(aFloat(in), aFloat(in), aFloat(in)); break;
    case 10:
      pfglFrustum(aFloat(in), aFloat(in), aFloat(in), aFloat(in), aFloat(in), aFloat(in));
      break;
    case 11: pfglOrtho(aFloat(in), aFloat(in), aFloat(in), aFloat(in), aFloat(in), aFloat(in)); break;
    case 12:
      pfglViewport(in.ConsumeIntegralInRange<int>(-100, 100), in.ConsumeIntegralInRange<int>(-100, 100),
                   in.ConsumeIntegralInRange<int>(-10, 100), in.ConsumeIntegralInRange<int>(-10, 100));
      break;
    case 13: pfglClearColor(aFloat(in), aFloat(in), aFloat(in), aFloat(in)); pfglClearDepth(aFloat(in)); break;
    case 14: pfglClear(in.ConsumeIntegral<GLbitfield>()); break;
    case 15: pfglDepthFunc(in.ConsumeIntegralInRange<GLenum>(GL_NEVER - 1, GL_ALWAYS + 1)); break;
    case 16: {
      const float v[4] = {aFloat(in), aFloat(in), aFloat(in), aFloat(in)};
      pfglLightfv(GL_LIGHT0 + in.ConsumeIntegralInRange<GLenum>(0, 8), in.ConsumeIntegralInRange<GLenum>(0x1200, 0x1209), v);
      pfglMaterialfv(GL_FRONT_AND_BACK, in.ConsumeIntegralInRange<GLenum>(0x1200, 0x1602), v);
      break;
    }
    case 17: {  // a named parameter (a known one, a new one, or no id at all) and a sequence point
      const GLuint name = in.ConsumeBool() ? pfglGetParamNameEXT(in.ConsumeBool() ? "radius" : "center")
                                           : in.ConsumeIntegral<GLuint>();
      pfglRastParamfEXT(name, aFloat(in));
      pfglSequencePointEXT();
      break;
    }
    case 18: {  // a sphere, of random parameters
      pfglBegin(pfglGetPrimitiveEXT("sphere"));
      pfglRastParam3fEXT(pfglGetParamNameEXT("center"), aFloat(in), aFloat(in), aFloat(in));
      pfglRastParamfEXT(pfglGetParamNameEXT("radius"), aFloat(in));
      pfglSequencePointEXT();
      pfglEnd();
      break;
    }
    case 20: fragmentState(in); break;
    case 21: textureState(in); break;
    case 22: fogClipState(in); break;
    case 23: accumulation(in); break;
    case 24: pixelRectangles(in); break;
    case 25: rasterModeState(in); break;
    case 26: pixelTransferState(in); break;
    default: pfglFinish(); break;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static std::vector<unsigned char> pixels(kSize * kSize * 4);
  const int attribs[] = {PF_FORMAT,  GL_RGBA, PF_DEPTH_BITS,    24, PF_STENCIL_BITS, 8, PF_ACCUM_BITS, 16, PF_THREADS, 2,
                         PF_ITERATION_CAP, static_cast<int>(kIterationCap), 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) return 0;
  // The calls on a 1 MB stack, an application's worker thread's (the current context is the
  // calling thread's: made current there).
  pf::fuzz::onSmallStack([&] {
    if (pfMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
      FuzzedDataProvider in(data, size);
      bool huge_drawn = false;
      for (int calls = 0; calls < 400 && in.remaining_bytes() > 0; ++calls) oneCall(in, huge_drawn);
      pfglEnd();  // (a glBegin left open)
      pfglFinish();
      (void)pfglGetError();
    }
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  });
  pfDestroyContext(ctx);
  return 0;
}
