// glPixelTransfer, glPixelMap and glGetPixelMap (GL 1.5 sections 3.6.5 and 6.1.3), with Mesa's
// errors in Mesa's order, its conversions of integer table entries and its readings of them
// back, and the transfer modes' glGet* (state_queries.cpp asks here). glPixelTransfer and
// glPixelMap are recorded in display lists (glPixelMapuiv / usv as the floats they convert to,
// as Mesa records them); glGetPixelMap is executed at once. Where the modes and tables apply:
// pixel_maps.h.
#include <cmath>
#include <cstring>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/query.h"

namespace pf {
namespace {

// A float truncated to a 32-bit integer as x86 converts it (Mesa's (GLint) casts): INT_MIN when
// out of range or NaN.
int32_t truncateToInt(double v) {
  return v >= -2147483648.0 && v < 2147483648.0 ? static_cast<int32_t>(v) : INT32_MIN;
}

// The values glPixelMapuiv / glPixelMapusv give as floats (Mesa's conversions): the index
// tables' (I_TO_I, S_TO_S) as they are, the colour tables' mapped from [0, 2^n - 1] to [0, 1].
template <class T>
PixelMapValues convertedValues(GLenum map, GLsizei mapsize, const T* values) {
  PixelMapValues out{};
  if (!values || mapsize < 1 || mapsize > kMaxPixelMapTable) return out;
  const bool index = map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S;
  for (int i = 0; i < mapsize; ++i) {
    if (index) out.v[i] = static_cast<GLfloat>(values[i]);
    else if constexpr (sizeof(T) == 4) out.v[i] = static_cast<GLfloat>(values[i] * (1.0 / 4294967295.0));
    else out.v[i] = static_cast<GLfloat>(values[i]) * (1.0f / 65535.0f);
  }
  out.count = mapsize;
  return out;
}

// glGetPixelMap's table, or null with the error GL sets (GL_INVALID_OPERATION inside glBegin /
// glEnd, GL_INVALID_ENUM for another enum).
const PixelMap* mapToRead(GLenum map, PFcontextRec*& ctx) {
  ctx = contextOutsideBegin();
  if (!ctx) return nullptr;
  const PixelMap* table = ctx->pixel_maps.find(map);
  if (!table) ctx->setError(GL_INVALID_ENUM);
  return table;
}

}  // namespace

namespace cmd {

void pixelTransfer(PFcontextRec& ctx, GLenum pname, GLfloat param) {
  if (!outsideBegin(ctx)) return;
  PixelTransferModes& m = ctx.pixel_mode.transfer;
  switch (pname) {
    case GL_MAP_COLOR: m.map_color = param != 0.0f; return;  // (NaN: true)
    case GL_MAP_STENCIL: m.map_stencil = param != 0.0f; return;
    case GL_INDEX_SHIFT: m.index_shift = truncateToInt(param); return;
    case GL_INDEX_OFFSET: m.index_offset = truncateToInt(param); return;
    case GL_RED_SCALE: case GL_GREEN_SCALE: case GL_BLUE_SCALE: case GL_ALPHA_SCALE:
      m.scale[pname == GL_RED_SCALE ? 0 : pname == GL_GREEN_SCALE ? 1 : pname == GL_BLUE_SCALE ? 2 : 3] = param;
      return;
    case GL_RED_BIAS: case GL_GREEN_BIAS: case GL_BLUE_BIAS: case GL_ALPHA_BIAS:
      m.bias[pname == GL_RED_BIAS ? 0 : pname == GL_GREEN_BIAS ? 1 : pname == GL_BLUE_BIAS ? 2 : 3] = param;
      return;
    case GL_DEPTH_SCALE: m.depth_scale = param; return;
    case GL_DEPTH_BIAS: m.depth_bias = param; return;
    default: return ctx.setError(GL_INVALID_ENUM);
  }
}

// Mesa's order: the size (1 to GL_MAX_PIXEL_MAP_TABLE; a power of two for S_TO_S and I_TO_R ..
// I_TO_A, but not I_TO_I, which Mesa leaves out of the check) before the map; a NULL table is
// then ignored, even of an unknown map.
void pixelMap(PFcontextRec& ctx, GLenum map, GLsizei mapsize, PixelMapValues values) {
  if (!outsideBegin(ctx)) return;
  if (mapsize < 1 || mapsize > kMaxPixelMapTable) return ctx.setError(GL_INVALID_VALUE);
  if (map >= GL_PIXEL_MAP_S_TO_S && map <= GL_PIXEL_MAP_I_TO_A && (mapsize & (mapsize - 1)) != 0)
    return ctx.setError(GL_INVALID_VALUE);
  if (values.count <= 0) return;
  PixelMap* table = ctx.pixel_maps.find(map);
  if (!table) return ctx.setError(GL_INVALID_ENUM);
  table->size = mapsize;
  for (int i = 0; i < mapsize; ++i) {
    const float v = values.v[i];
    if (map == GL_PIXEL_MAP_S_TO_S) table->v[i] = std::round(v);
    else if (map == GL_PIXEL_MAP_I_TO_I) table->v[i] = v;
    else table->v[i] = v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v;  // (NaN kept, as Mesa's CLAMP keeps it)
  }
}

}  // namespace cmd

bool pixelTransferQuery(const PFcontextRec& ctx, GLenum pname, Query& q) {
  const PixelTransferModes& m = ctx.pixel_mode.transfer;
  switch (pname) {
    case GL_MAP_COLOR: q.set({m.map_color ? 1.0 : 0.0}); return true;
    case GL_MAP_STENCIL: q.set({m.map_stencil ? 1.0 : 0.0}); return true;
    case GL_INDEX_SHIFT: q.set({double(m.index_shift)}); return true;
    case GL_INDEX_OFFSET: q.set({double(m.index_offset)}); return true;
    case GL_RED_SCALE: q.set({m.scale[0]}); return true;
    case GL_GREEN_SCALE: q.set({m.scale[1]}); return true;
    case GL_BLUE_SCALE: q.set({m.scale[2]}); return true;
    case GL_ALPHA_SCALE: q.set({m.scale[3]}); return true;
    case GL_RED_BIAS: q.set({m.bias[0]}); return true;
    case GL_GREEN_BIAS: q.set({m.bias[1]}); return true;
    case GL_BLUE_BIAS: q.set({m.bias[2]}); return true;
    case GL_ALPHA_BIAS: q.set({m.bias[3]}); return true;
    case GL_DEPTH_SCALE: q.set({m.depth_scale}); return true;
    case GL_DEPTH_BIAS: q.set({m.depth_bias}); return true;
    case GL_MAX_PIXEL_MAP_TABLE: q.set({double(kMaxPixelMapTable)}); return true;
    default:
      if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE) {
        q.set({double(ctx.pixel_maps.table[pname - GL_PIXEL_MAP_I_TO_I_SIZE].size)});
        return true;
      }
      return false;
  }
}

}  // namespace pf

extern "C" {

void pfglPixelTransferf(GLenum pname, GLfloat param) { pf::dispatch<pf::GlOp::PixelTransfer>(pname, param); }
void pfglPixelTransferi(GLenum pname, GLint param) {
  pf::dispatch<pf::GlOp::PixelTransfer>(pname, static_cast<GLfloat>(param));
}

void pfglPixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values) {
  pf::PixelMapValues v{};
  if (values && mapsize >= 1 && mapsize <= pf::kMaxPixelMapTable) v = pf::valuesOf<GLfloat, pf::kMaxPixelMapTable>(values, mapsize, mapsize);
  pf::dispatch<pf::GlOp::PixelMap>(map, mapsize, v);
}
void pfglPixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values) {
  pf::dispatch<pf::GlOp::PixelMap>(map, mapsize, pf::convertedValues(map, mapsize, values));
}
void pfglPixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values) {
  pf::dispatch<pf::GlOp::PixelMap>(map, mapsize, pf::convertedValues(map, mapsize, values));
}

void pfglGetPixelMapfv(GLenum map, GLfloat* values) {
  PFcontextRec* ctx;
  const pf::PixelMap* t = pf::mapToRead(map, ctx);
  if (!t || !values) return;
  for (int i = 0; i < t->size; ++i) values[i] = t->v[i];
}

// Mesa's readings: S_TO_S's entries are its floats' bits (Mesa copies the float table as
// integers); the others each v * (2^32 - 1) truncated through a 64-bit integer to its low 32
// bits (x86's conversion of Mesa's FLOAT_TO_UINT: an index of 2 reads 2^32 - 2; 0 past 2^63).
void pfglGetPixelMapuiv(GLenum map, GLuint* values) {
  PFcontextRec* ctx;
  const pf::PixelMap* t = pf::mapToRead(map, ctx);
  if (!t || !values) return;
  for (int i = 0; i < t->size; ++i) {
    if (map == GL_PIXEL_MAP_S_TO_S) {
      std::memcpy(&values[i], &t->v[i], sizeof(GLuint));
      continue;
    }
    const double d = static_cast<double>(t->v[i]) * 4294967295.0;
    const bool fits = d > -9223372036854775808.0 && d < 9223372036854775808.0;
    values[i] = fits ? static_cast<GLuint>(static_cast<uint64_t>(static_cast<int64_t>(d))) : 0u;
  }
}

// Mesa's readings: the index tables' entries clamped to [0, 65535] and truncated; the colour
// tables' v * 65535 rounded to nearest, halves to even (in float arithmetic, as Mesa's).
void pfglGetPixelMapusv(GLenum map, GLushort* values) {
  PFcontextRec* ctx;
  const pf::PixelMap* t = pf::mapToRead(map, ctx);
  if (!t || !values) return;
  const bool index = map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S;
  for (int i = 0; i < t->size; ++i) {
    const float v = t->v[i];
    if (v != v) values[i] = 0;  // NaN
    else if (index) values[i] = static_cast<GLushort>(v < 0.0f ? 0.0f : v > 65535.0f ? 65535.0f : v);
    else values[i] = static_cast<GLushort>(std::nearbyint(v * 65535.0f));
  }
}

}  // extern "C"
