// The rasterization state of points, lines and polygons (GL 1.5 sections 3.4 - 3.5, table 6.12
// - 6.14) as a context keeps it: glPointSize, glLineWidth, glLineStipple, glPolygonMode,
// glPolygonOffset, glPolygonStipple, their glGet values and attribute groups, and what a draw
// takes of them (RasterState's line_width and point_size, in whole pixels as OSMesa rasterizes
// them, the stipples, the modes). Commands and queries: raster_mode_commands.cpp.
#pragma once

#include <GL/gl.h>

#include "api/src/query.h"
#include "raster/raster_state.h"

namespace pf {

// OSMesa's (llvmpipe's) limits: aliased and smooth widths and sizes from 1 to 255, in steps of
// 0.1 (GL_*_RANGE, GL_*_GRANULARITY).
constexpr float kMaxLineWidth = 255.0f;
constexpr float kMaxPointSize = 255.0f;
constexpr float kWidthGranularity = 0.1f;

// The state glPushAttrib's GL_POINT_BIT and GL_LINE_BIT save (the enables: GL_ENABLE_BIT
// too), OSMesa's initial values. Sizes are kept as given (glGet reads them back); a draw rounds.
struct RasterModes {
  float point_size = 1.0f;  // GL_POINT_BIT
  float line_width = 1.0f;  // GL_LINE_BIT, with the stipple and its enable
  bool line_stipple = false;
  GLint stipple_factor = 1;  // clamped to [1, 256] when set, as Mesa keeps it
  GLushort stipple_pattern = 0xffff;
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL};  // GL_POLYGON_BIT: front, back
  float offset_factor = 0.0f, offset_units = 0.0f;
  bool offset_fill = false, offset_line = false, offset_point = false;  // (GL_ENABLE_BIT too)
  // glPolygonStipple's pattern, GL_POLYGON_STIPPLE_BIT (initially all 1s), as RasterState's
  // stipple_rows holds it: row k's first byte in bits 31 - 24, its first bit the most
  // significant; and its enable (GL_ENABLE_BIT).
  uint32_t stipple_rows[32] = {
      ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u,
      ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u, ~0u};
  bool polygon_stipple = false;
};

// glPolygonStipple's pattern as a command takes it (and a display list records it): the 32 rows
// unpacked when the command was issued, or nothing for a NULL pattern (given 0).
struct StipplePattern {
  uint32_t rows[32];
  GLint given;
};

// The depth buffer's resolution r that glPolygonOffset's units multiply, as OSMesa's 24-bit
// buffer takes it: 2^-23 (measured: 100 units move a polygon by 100 x 2^-23).
constexpr float kOffsetUnit = 1.0f / 8388608.0f;

// The glGet* values (GL_POINT_SIZE, GL_LINE_WIDTH, the ranges and granularities, the line
// stipple and its enable); false for another pname.
bool rasterModeQuery(const RasterModes& m, GLenum pname, Query& q);

// The line width a draw rasterizes: the width clamped to [1, 255] and rounded to the nearest
// whole pixel, a half up (llvmpipe's round()); NaN draws 1.
float rasterLineWidth(float width);
// The point size a draw rasterizes: the size clamped to [1, 255], taken to 1/256 pixel, then
// rounded to the nearest whole pixel, a half down (llvmpipe's fixed-point rounding: 1.5 and
// 2.5 draw 1 and 2, 1.51 draws 2); NaN draws 1.
float rasterPointSize(float size);

// Sets the draw's line_width, point_size, line stipple, polygon modes, offset and stipple.
void applyRasterModes(const RasterModes& m, RasterState& s);

}  // namespace pf
