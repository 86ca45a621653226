// Vertex arrays (GL 1.5 section 2.8): glDrawArrays and glDrawElements are, by GL's own
// definition, glBegin, then glArrayElement for each index (the enabled arrays' values set as
// the current ones, the vertex last), then glEnd -- and are implemented exactly so, through
// the same sequence points as immediate mode. In a display list they are recorded so: the
// glBegin, glColor, glNormal, glEdgeFlag, glVertex and glEnd they issue, with the arrays' values read when
// the list is compiled (GL 1.5 section 5.4), and their errors raised when it executes.
#include <cstring>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/normalized.h"

namespace {

size_t typeSize(GLenum type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

template <class T>
double component(const unsigned char* p, bool normalize) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return normalize ? pf::normalized(v) : static_cast<double>(v);
}

// Component k of element i, as a double; `normalize`: integer types map to [0, 1] / [-1, 1]
// as GL does for colours and normals.
double fetch(const pf::ClientArray& a, GLint i, int k, bool normalize) {
  const size_t size = typeSize(a.type);
  const size_t stride = a.stride ? static_cast<size_t>(a.stride) : size * static_cast<size_t>(a.size);
  const unsigned char* p = static_cast<const unsigned char*>(a.pointer) + stride * static_cast<size_t>(i) + size * k;
  switch (a.type) {
    case GL_BYTE: return component<int8_t>(p, normalize);
    case GL_UNSIGNED_BYTE: return component<uint8_t>(p, normalize);
    case GL_SHORT: return component<int16_t>(p, normalize);
    case GL_UNSIGNED_SHORT: return component<uint16_t>(p, normalize);
    case GL_INT: return component<int32_t>(p, normalize);
    case GL_UNSIGNED_INT: return component<uint32_t>(p, normalize);
    case GL_FLOAT: return component<float>(p, normalize);
    default: return component<double>(p, normalize);
  }
}

using pf::issue;
using pf::GlOp;

// glArrayElement's work: the enabled arrays' element i as the current values, the vertex last.
void arrayElement(PFcontextRec& ctx, GLint i) {
  if (ctx.texcoord_array.enabled && ctx.texcoord_array.pointer) {  // (s, t, r, q), missing (0, 0, 1)
    const pf::ClientArray& a = ctx.texcoord_array;
    float t[4] = {0, 0, 0, 1};
    for (int k = 0; k < a.size; ++k) t[k] = static_cast<float>(fetch(a, i, k, false));
    issue<GlOp::TexCoord>(ctx, t[0], t[1], t[2], t[3]);
  }
  if (ctx.color_array.enabled && ctx.color_array.pointer) {
    const pf::ClientArray& a = ctx.color_array;
    issue<GlOp::Color>(ctx, static_cast<float>(fetch(a, i, 0, true)), static_cast<float>(fetch(a, i, 1, true)),
                     static_cast<float>(fetch(a, i, 2, true)),
                     a.size == 4 ? static_cast<float>(fetch(a, i, 3, true)) : 1.0f);
  }
  if (ctx.edge_flag_array.enabled && ctx.edge_flag_array.pointer) {  // GLbooleans, any non-zero true
    const pf::ClientArray& a = ctx.edge_flag_array;
    const size_t stride = a.stride ? static_cast<size_t>(a.stride) : sizeof(GLboolean);
    issue<GlOp::EdgeFlag>(ctx, static_cast<const GLboolean*>(a.pointer)[stride * static_cast<size_t>(i)]);
  }
  if (ctx.normal_array.enabled && ctx.normal_array.pointer) {
    const pf::ClientArray& a = ctx.normal_array;
    issue<GlOp::Normal>(ctx, static_cast<float>(fetch(a, i, 0, true)), static_cast<float>(fetch(a, i, 1, true)),
                      static_cast<float>(fetch(a, i, 2, true)));
  }
  if (ctx.vertex_array.enabled && ctx.vertex_array.pointer) {
    const pf::ClientArray& a = ctx.vertex_array;
    double v[4] = {0, 0, 0, 1};
    for (int k = 0; k < a.size; ++k) v[k] = fetch(a, i, k, false);
    issue<GlOp::Vertex>(ctx, v[0], v[1], v[2], v[3], a.size);
  }
}

pf::ClientArray* clientArray(PFcontextRec& ctx, GLenum array) {
  switch (array) {
    case GL_VERTEX_ARRAY: return &ctx.vertex_array;
    case GL_COLOR_ARRAY: return &ctx.color_array;
    case GL_NORMAL_ARRAY: return &ctx.normal_array;
    case GL_TEXTURE_COORD_ARRAY: return &ctx.texcoord_array;
    case GL_EDGE_FLAG_ARRAY: return &ctx.edge_flag_array;
    default: return nullptr;
  }
}

// Sets a pointer after GL's checks: the sizes and types each array takes, stride >= 0.
void pointer(GLenum which, GLint size, GLenum type, GLsizei stride, const GLvoid* ptr, bool size_ok, bool type_ok) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (!size_ok || stride < 0) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  if (!type_ok) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  pf::ClientArray& a = *clientArray(*ctx, which);
  a.size = size;
  a.type = type;
  a.stride = stride;
  a.pointer = ptr;
}

// An error of glDrawArrays or glDrawElements: raised, or recorded into the list being compiled
// (raised when it executes), as GL does for commands compiled into a list.
void fail(PFcontextRec& ctx, GLenum error) { issue<GlOp::Error>(ctx, error); }

// Checks shared by glDrawArrays and glDrawElements; the context to draw with, or null.
PFcontextRec* drawable(GLenum mode, GLsizei count) {
  PFcontextRec* ctx = pf::currentContext();
  if (!ctx) return nullptr;
  GLenum error = GL_NO_ERROR;
  if (ctx->in_begin) error = GL_INVALID_OPERATION;
  else if (mode > GL_POLYGON) error = GL_INVALID_ENUM;
  else if (count < 0) error = GL_INVALID_VALUE;
  if (error == GL_NO_ERROR) return ctx;
  fail(*ctx, error);
  return nullptr;
}

// glInterleavedArrays' formats (GL 1.5 table 2.5): which arrays each enables, their sizes, the
// colour's type, the offsets of texture coordinates (0), colour, normal and vertex in bytes, and
// the stride when 0 is given.
struct Interleaved {
  GLenum format;
  int texcoords, colors, normals, vertices;  // components; 0: that array disabled
  GLenum color_type;
  int color_at, normal_at, vertex_at, stride;
};
constexpr int kF = sizeof(GLfloat), kUb4 = 4 * sizeof(GLubyte);
constexpr Interleaved kInterleaved[] = {
    {GL_V2F, 0, 0, 0, 2, GL_FLOAT, 0, 0, 0, 2 * kF},
    {GL_V3F, 0, 0, 0, 3, GL_FLOAT, 0, 0, 0, 3 * kF},
    {GL_C4UB_V2F, 0, 4, 0, 2, GL_UNSIGNED_BYTE, 0, 0, kUb4, kUb4 + 2 * kF},
    {GL_C4UB_V3F, 0, 4, 0, 3, GL_UNSIGNED_BYTE, 0, 0, kUb4, kUb4 + 3 * kF},
    {GL_C3F_V3F, 0, 3, 0, 3, GL_FLOAT, 0, 0, 3 * kF, 6 * kF},
    {GL_N3F_V3F, 0, 0, 3, 3, GL_FLOAT, 0, 0, 3 * kF, 6 * kF},
    {GL_C4F_N3F_V3F, 0, 4, 3, 3, GL_FLOAT, 0, 4 * kF, 7 * kF, 10 * kF},
    {GL_T2F_V3F, 2, 0, 0, 3, GL_FLOAT, 0, 0, 2 * kF, 5 * kF},
    {GL_T4F_V4F, 4, 0, 0, 4, GL_FLOAT, 0, 0, 4 * kF, 8 * kF},
    {GL_T2F_C4UB_V3F, 2, 4, 0, 3, GL_UNSIGNED_BYTE, 2 * kF, 0, kUb4 + 2 * kF, kUb4 + 5 * kF},
    {GL_T2F_C3F_V3F, 2, 3, 0, 3, GL_FLOAT, 2 * kF, 0, 5 * kF, 8 * kF},
    {GL_T2F_N3F_V3F, 2, 0, 3, 3, GL_FLOAT, 0, 2 * kF, 5 * kF, 8 * kF},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, 3, GL_FLOAT, 2 * kF, 6 * kF, 9 * kF, 12 * kF},
    {GL_T4F_C4F_N3F_V4F, 4, 4, 3, 4, GL_FLOAT, 4 * kF, 8 * kF, 11 * kF, 15 * kF},
};

}  // namespace

extern "C" {

void pfglEnableClientState(GLenum array) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (pf::ClientArray* a = clientArray(*ctx, array)) a->enabled = true;
  else ctx->setError(GL_INVALID_ENUM);
}

void pfglDisableClientState(GLenum array) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (pf::ClientArray* a = clientArray(*ctx, array)) a->enabled = false;
  else ctx->setError(GL_INVALID_ENUM);
}

void pfglVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  pointer(GL_VERTEX_ARRAY, size, type, stride, ptr, size >= 2 && size <= 4,
          type == GL_SHORT || type == GL_INT || type == GL_FLOAT || type == GL_DOUBLE);
}

void pfglColorPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  pointer(GL_COLOR_ARRAY, size, type, stride, ptr, size == 3 || size == 4, typeSize(type) != 0);
}

void pfglNormalPointer(GLenum type, GLsizei stride, const GLvoid* ptr) {
  pointer(GL_NORMAL_ARRAY, 3, type, stride, ptr, true,
          type == GL_BYTE || type == GL_SHORT || type == GL_INT || type == GL_FLOAT || type == GL_DOUBLE);
}

void pfglTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* ptr) {
  pointer(GL_TEXTURE_COORD_ARRAY, size, type, stride, ptr, size >= 1 && size <= 4,
          type == GL_SHORT || type == GL_INT || type == GL_FLOAT || type == GL_DOUBLE);
}

// An array of GLboolean edge flags (GL 1.5 section 2.8).
void pfglEdgeFlagPointer(GLsizei stride, const GLvoid* ptr) {
  pointer(GL_EDGE_FLAG_ARRAY, 1, GL_UNSIGNED_BYTE, stride, ptr, true, true);
}

// Sets the arrays of one of GL's interleaved layouts and enables exactly those (the vertex
// array always; the edge flag array is disabled, as GL 1.5 section 2.8 says). Executed at once
// in a display list, as the pointer commands are.
void pfglInterleavedArrays(GLenum format, GLsizei stride, const GLvoid* ptr) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (stride < 0) return ctx->setError(GL_INVALID_VALUE);
  const Interleaved* f = nullptr;
  for (const Interleaved& candidate : kInterleaved)
    if (candidate.format == format) f = &candidate;
  if (!f) return ctx->setError(GL_INVALID_ENUM);
  const GLsizei step = stride ? stride : f->stride;
  const auto* base = static_cast<const unsigned char*>(ptr);
  auto set = [&](pf::ClientArray& a, int size, GLenum type, int offset) {
    a.enabled = size > 0;
    if (size == 0) return;
    a.size = size;
    a.type = type;
    a.stride = step;
    a.pointer = base ? base + offset : nullptr;
  };
  set(ctx->texcoord_array, f->texcoords, GL_FLOAT, 0);
  set(ctx->color_array, f->colors, f->color_type, f->color_at);
  set(ctx->normal_array, f->normals, GL_FLOAT, f->normal_at);
  set(ctx->vertex_array, f->vertices, GL_FLOAT, f->vertex_at);
  ctx->edge_flag_array.enabled = false;
}

// The arrays' pointers; those of arrays and buffers primflow does not have are NULL.
void pfglGetPointerv(GLenum pname, GLvoid** params) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  const void* p = nullptr;
  switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: p = ctx->vertex_array.pointer; break;
    case GL_COLOR_ARRAY_POINTER: p = ctx->color_array.pointer; break;
    case GL_NORMAL_ARRAY_POINTER: p = ctx->normal_array.pointer; break;
    case GL_TEXTURE_COORD_ARRAY_POINTER: p = ctx->texcoord_array.pointer; break;
    case GL_EDGE_FLAG_ARRAY_POINTER: p = ctx->edge_flag_array.pointer; break;
    case GL_INDEX_ARRAY_POINTER: case GL_FOG_COORD_ARRAY_POINTER:
    case GL_SECONDARY_COLOR_ARRAY_POINTER: case GL_FEEDBACK_BUFFER_POINTER: case GL_SELECTION_BUFFER_POINTER: break;
    default: return ctx->setError(GL_INVALID_ENUM);
  }
  if (params) *params = const_cast<void*>(p);
}

void pfglArrayElement(GLint i) {
  PFcontextRec* ctx = pf::currentContext();
  if (ctx) arrayElement(*ctx, i);
}

void pfglDrawArrays(GLenum mode, GLint first, GLsizei count) {
  PFcontextRec* ctx = drawable(mode, count);
  if (!ctx) return;
  if (first < 0) return fail(*ctx, GL_INVALID_VALUE);
  issue<GlOp::Begin>(*ctx, mode);
  // (first + i in 64 bits: the last index a GLint can name is the last one drawn.)
  for (int64_t i = first; i < int64_t{first} + count && i <= INT32_MAX; ++i) arrayElement(*ctx, static_cast<GLint>(i));
  issue<GlOp::End>(*ctx);
}

void pfglDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid* indices) {
  PFcontextRec* ctx = drawable(mode, count);
  if (!ctx) return;
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) {
    return fail(*ctx, GL_INVALID_ENUM);
  }
  if (!indices) return;
  issue<GlOp::Begin>(*ctx, mode);
  for (GLsizei i = 0; i < count; ++i) {
    GLint index;
    if (type == GL_UNSIGNED_BYTE) {
      index = static_cast<const GLubyte*>(indices)[i];
    } else if (type == GL_UNSIGNED_SHORT) {
      index = static_cast<const GLushort*>(indices)[i];
    } else {
      GLuint u = static_cast<const GLuint*>(indices)[i];
      index = u > 0x7fffffffu ? 0x7fffffff : static_cast<GLint>(u);
    }
    arrayElement(*ctx, index);
  }
  issue<GlOp::End>(*ctx);
}

}  // extern "C"
