// Points, lines and polygons' rasterization (GL 1.5 sections 3.4 - 3.5.6): glPointSize,
// glLineWidth, glLineStipple, glPolygonMode, glPolygonOffset and glPolygonStipple /
// glGetPolygonStipple with OSMesa's errors, their glGet values, and what a draw rasterizes
// (raster_modes.h). The primitives that draw them are primitives/points.pfl,
// primitives/lines.pfl and primitives/triangles.pfl (point_size(), line_width(),
// polygon_ztest()); the attribute groups are in attrib_stack.cpp.
#include <algorithm>
#include <cmath>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/pixel_transfer.h"
#include "api/src/raster_modes.h"

namespace pf {

namespace cmd {

// As Mesa: a width or size of 0 or less is GL_INVALID_VALUE; any other (NaN, 1000) is kept
// as given, and clamped only where drawn.
void lineWidth(PFcontextRec& ctx, GLfloat width) {
  if (!outsideBegin(ctx)) return;
  if (width <= 0.0f) return ctx.setError(GL_INVALID_VALUE);
  ctx.raster_modes.line_width = width;
}

void pointSize(PFcontextRec& ctx, GLfloat size) {
  if (!outsideBegin(ctx)) return;
  if (size <= 0.0f) return ctx.setError(GL_INVALID_VALUE);
  ctx.raster_modes.point_size = size;
}

// As Mesa: the factor clamped to [1, 256]; no error but inside glBegin.
void lineStipple(PFcontextRec& ctx, GLint factor, GLushort pattern) {
  if (!outsideBegin(ctx)) return;
  ctx.raster_modes.stipple_factor = factor < 1 ? 1 : factor > 256 ? 256 : factor;
  ctx.raster_modes.stipple_pattern = pattern;
}

void polygonMode(PFcontextRec& ctx, GLenum face, GLenum mode) {
  if (!outsideBegin(ctx)) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return ctx.setError(GL_INVALID_ENUM);
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return ctx.setError(GL_INVALID_ENUM);
  if (face != GL_BACK) ctx.raster_modes.polygon_mode[0] = mode;
  if (face != GL_FRONT) ctx.raster_modes.polygon_mode[1] = mode;
}

void polygonOffset(PFcontextRec& ctx, GLfloat factor, GLfloat units) {
  if (!outsideBegin(ctx)) return;
  ctx.raster_modes.offset_factor = factor;
  ctx.raster_modes.offset_units = units;
}

// A NULL pattern changes nothing, without an error (as Mesa, which reads no pattern then).
void polygonStipple(PFcontextRec& ctx, StipplePattern pattern) {
  if (!outsideBegin(ctx)) return;
  if (!pattern.given) return;
  std::copy(std::begin(pattern.rows), std::end(pattern.rows), ctx.raster_modes.stipple_rows);
}

}  // namespace cmd

namespace {

// glPolygonStipple's 32 x 32 bitmap at `data`, read by the unpack modes as glBitmap's is
// (unpackBitmap), as rows of 32 bits (the first pixel the most significant).
StipplePattern unpackStipple(const PixelStore& unpack, const GLubyte* data) {
  StipplePattern p{};
  if (!data) return p;
  unsigned char bits[32 * 32];
  unpackBitmap(unpack, 32, 32, data, bits);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if (bits[y * 32 + x]) p.rows[y] |= 1u << (31 - x);
  p.given = 1;
  return p;
}

// The pattern as a 32 x 32 bitmap written by the pack modes (packBitmap).
void packStipple(const PixelStore& pack, const uint32_t rows[32], GLubyte* data) {
  unsigned char bits[32 * 32];
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) bits[y * 32 + x] = static_cast<unsigned char>((rows[y] >> (31 - x)) & 1u);
  packBitmap(pack, 32, 32, bits, data);
}

}  // namespace

bool rasterModeQuery(const RasterModes& m, GLenum pname, Query& q) {
  switch (pname) {
    case GL_POINT_SIZE: q.set({m.point_size}); return true;
    case GL_LINE_WIDTH: q.set({m.line_width}); return true;
    case GL_LINE_STIPPLE: q.set({m.line_stipple ? 1.0 : 0.0}); return true;
    case GL_POLYGON_MODE: q.set({double(m.polygon_mode[0]), double(m.polygon_mode[1])}); return true;
    case GL_POLYGON_OFFSET_FACTOR: q.set({m.offset_factor}); return true;
    case GL_POLYGON_OFFSET_UNITS: q.set({m.offset_units}); return true;
    case GL_POLYGON_OFFSET_FILL: q.set({m.offset_fill ? 1.0 : 0.0}); return true;
    case GL_POLYGON_OFFSET_LINE: q.set({m.offset_line ? 1.0 : 0.0}); return true;
    case GL_POLYGON_OFFSET_POINT: q.set({m.offset_point ? 1.0 : 0.0}); return true;
    case GL_LINE_STIPPLE_PATTERN: q.set({double(m.stipple_pattern)}); return true;
    case GL_LINE_STIPPLE_REPEAT: q.set({double(m.stipple_factor)}); return true;
    case GL_POLYGON_STIPPLE: q.set({m.polygon_stipple ? 1.0 : 0.0}); return true;
    case GL_ALIASED_POINT_SIZE_RANGE: case GL_SMOOTH_POINT_SIZE_RANGE: q.set({1.0, kMaxPointSize}); return true;
    case GL_ALIASED_LINE_WIDTH_RANGE: case GL_SMOOTH_LINE_WIDTH_RANGE: q.set({1.0, kMaxLineWidth}); return true;
    case GL_SMOOTH_POINT_SIZE_GRANULARITY: case GL_SMOOTH_LINE_WIDTH_GRANULARITY:
      q.set({kWidthGranularity});
      return true;
    default: return false;
  }
}

float rasterLineWidth(float width) {
  if (!(width >= 1.0f)) return 1.0f;
  return std::round(std::fmin(width, kMaxLineWidth));
}

float rasterPointSize(float size) {
  if (!(size >= 1.0f)) return 1.0f;
  const float fixed = std::round(std::fmin(size, kMaxPointSize) * 256.0f);  // 1/256 pixel
  return std::floor((fixed + 127.0f) / 256.0f);
}

void applyRasterModes(const RasterModes& m, RasterState& s) {
  s.line_width = rasterLineWidth(m.line_width);
  s.point_size = rasterPointSize(m.point_size);
  s.line_stipple = m.line_stipple;
  s.line_stipple_pattern = static_cast<float>(m.stipple_pattern);
  s.line_stipple_factor = static_cast<float>(m.stipple_factor);
  auto mode = [](GLenum e) { return e == GL_LINE ? 1.0f : e == GL_POINT ? 2.0f : 0.0f; };
  s.polygon_mode_front = mode(m.polygon_mode[0]);
  s.polygon_mode_back = mode(m.polygon_mode[1]);
  s.offset_factor = m.offset_factor;
  s.offset_units = m.offset_units * kOffsetUnit;
  s.offset_fill = m.offset_fill;
  s.offset_line = m.offset_line;
  s.offset_point = m.offset_point;
  // (Off: every row stays 0, so that draws with the stipple off share one state.)
  s.polygon_stipple = m.polygon_stipple;
  if (m.polygon_stipple) std::copy(std::begin(m.stipple_rows), std::end(m.stipple_rows), s.stipple_rows);
}

}  // namespace pf

extern "C" {

void pfglLineWidth(GLfloat width) { pf::dispatch<pf::GlOp::LineWidth>(width); }
void pfglPointSize(GLfloat size) { pf::dispatch<pf::GlOp::PointSize>(size); }
void pfglLineStipple(GLint factor, GLushort pattern) { pf::dispatch<pf::GlOp::LineStipple>(factor, pattern); }
void pfglPolygonMode(GLenum face, GLenum mode) { pf::dispatch<pf::GlOp::PolygonMode>(face, mode); }
void pfglPolygonOffset(GLfloat factor, GLfloat units) { pf::dispatch<pf::GlOp::PolygonOffset>(factor, units); }

// The pattern is unpacked when the command is issued: into the list being compiled, as GL says
// (section 5.4), or for the context now.
void pfglPolygonStipple(const GLubyte* mask) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return;
  pf::issue<pf::GlOp::PolygonStipple>(*ctx, pf::unpackStipple(ctx->unpack, mask));
}

// Executed at once, also while a list is compiled; NULL: nothing written (as Mesa).
void pfglGetPolygonStipple(GLubyte* mask) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx || !mask) return;
  pf::packStipple(ctx->pack, ctx->raster_modes.stipple_rows, mask);
}

}  // extern "C"
