// The GL commands a display list records, in one table, and the machinery every entry point
// goes through so that a command is executed, recorded, or both (GL 1.5 section 5.4).
//
// Each recorded command has an internal function pf::cmd::NAME(ctx, args...) holding everything
// the command does after the current context is found: its errors, its "not between glBegin and
// glEnd" check, its effect. The gl* entry point calls dispatch<GlOp::X>(args...); a replayed list
// calls the same function with the recorded arguments, so a list does exactly what its commands
// issued one by one would -- state, errors and all -- without looking up the context or
// allocating per command. Arguments are stored by value, converted to the function's parameter
// types when recorded (glColor3ub's bytes as floats, glLightiv's integers as GL maps them):
// what the caller's pointers point at is copied then, as GL requires.
#pragma once

#include <cstdint>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "api/src/context_state.h"

namespace pf {

// A vector argument copied out of the caller's memory: `count` is the number of values given
// (the form's own: 1 for glLightf, 4 for glLightfv, 16 for a matrix, n for
// pfglRastParamfvEXT), 0 for a NULL pointer or an invalid count. Entries not given are 0.
// (No member initialisers: it is trivial, copied as bytes into a list and out; make one with {}.)
template <class T, int N>
struct Values {
  T v[N];
  GLint count;
  const T* pointer() const { return count > 0 ? v : nullptr; }
};
using Values4f = Values<GLfloat, 4>;
using Values16f = Values<GLfloat, 16>;
using Values16i = Values<GLint, 16>;
using Values4d = Values<GLdouble, 4>;
using PixelMapValues = Values<GLfloat, kMaxPixelMapTable>;  // a glPixelMap table, as floats

// Copies `n` values (at most N) from `p`, given as `count` (NULL: 0).
template <class T, int N, class U>
Values<T, N> valuesOf(const U* p, int n, GLint count) {
  Values<T, N> out{};
  if (!p) return out;
  for (int i = 0; i < n && i < N; ++i) out.v[i] = static_cast<T>(p[i]);
  out.count = count;
  return out;
}

// X(opcode, function in pf::cmd, argument types...). Every GL command GL compiles into a
// display list, and primflow's extension commands that set state or feed a glBegin. Not here,
// executed at once even while compiling (GL 1.5 section 5.4): glGen/Delete/IsList, glNewList,
// glEndList, queries, glFinish, glFlush, glReadPixels, glPixelStore, glGen/Delete/IsTexture,
// glPrioritizeTextures, glAreTexturesResident, proxy glTexImage*, client state (with
// glPush/PopClientAttrib) and array pointers (glArrayElement, glDrawArrays and glDrawElements record the commands they issue, the
// arrays read when compiled), and the extension's compile and look-up commands.
#define PF_LIST_COMMANDS(X)                                                               \
  /* gl_commands.cpp */                                                                   \
  X(Clear, clear, GLbitfield)                                                             \
  X(ClearColor, clearColor, GLfloat, GLfloat, GLfloat, GLfloat)                           \
  X(ClearDepth, clearDepth, GLdouble)                                                     \
  X(Viewport, viewport, GLint, GLint, GLsizei, GLsizei)                                   \
  X(DepthFunc, depthFunc, GLenum)                                                         \
  X(DepthMask, depthMask, GLboolean)                                                      \
  X(DepthRange, depthRange, GLdouble, GLdouble)                                           \
  X(Enable, enable, GLenum)                                                               \
  X(Disable, disable, GLenum)                                                             \
  X(ColorMask, colorMask, GLboolean, GLboolean, GLboolean, GLboolean)                     \
  X(CullFace, cullFace, GLenum)                                                           \
  X(FrontFace, frontFace, GLenum)                                                         \
  X(ShadeModel, shadeModel, GLenum)                                                       \
  X(Hint, hint, GLenum, GLenum)                                                           \
  /* fragment_commands.cpp */                                                             \
  X(Scissor, scissor, GLint, GLint, GLsizei, GLsizei)                                     \
  X(AlphaFunc, alphaFunc, GLenum, GLfloat)                                                \
  X(BlendFuncSeparate, blendFuncSeparate, GLenum, GLenum, GLenum, GLenum)                 \
  X(BlendEquation, blendEquation, GLenum)                                                 \
  X(BlendColor, blendColor, GLfloat, GLfloat, GLfloat, GLfloat)                           \
  X(LogicOp, logicOp, GLenum)                                                             \
  X(StencilFunc, stencilFunc, GLenum, GLint, GLuint)                                      \
  X(StencilOp, stencilOp, GLenum, GLenum, GLenum)                                         \
  X(StencilMask, stencilMask, GLuint)                                                     \
  X(ClearStencil, clearStencil, GLint)                                                    \
  /* fog_clip_commands.cpp: glFog* as glLight* (count 1 scalar, 4 vector, 0 NULL), */        \
  /* glClipPlane's equation as given                                               */        \
  X(Fog, fog, GLenum, Values4f)                                                           \
  X(ClipPlane, clipPlane, GLenum, Values4d)                                               \
  /* accumulation.cpp */                                                                   \
  X(Accum, accum, GLenum, GLfloat)                                                        \
  X(ClearAccum, clearAccum, GLfloat, GLfloat, GLfloat, GLfloat)                           \
  /* raster_position.cpp: glRasterPos as 4 floats, glWindowPos as 3 */                    \
  X(RasterPos, rasterPos, GLfloat, GLfloat, GLfloat, GLfloat)                             \
  X(WindowPos, windowPos, GLfloat, GLfloat, GLfloat)                                      \
  /* draw_pixels.cpp */                                                                   \
  X(PixelZoom, pixelZoom, GLfloat, GLfloat)                                               \
  X(CopyPixels, copyPixels, GLint, GLint, GLsizei, GLsizei, GLenum)                       \
  /* pixel_map_commands.cpp: glPixelTransferi as its float; glPixelMap as floats */       \
  X(PixelTransfer, pixelTransfer, GLenum, GLfloat)                                        \
  X(PixelMap, pixelMap, GLenum, GLsizei, PixelMapValues)                                  \
  /* raster_mode_commands.cpp */                                                          \
  X(PointSize, pointSize, GLfloat)                                                        \
  X(LineWidth, lineWidth, GLfloat)                                                        \
  X(LineStipple, lineStipple, GLint, GLushort)                                            \
  X(PolygonMode, polygonMode, GLenum, GLenum)                                             \
  X(PolygonOffset, polygonOffset, GLfloat, GLfloat)                                       \
  X(PolygonStipple, polygonStipple, StipplePattern)                                      \
  /* attrib_stack.cpp */                                                                  \
  X(PushAttrib, pushAttrib, GLbitfield)                                                   \
  X(PopAttrib, popAttrib)                                                                 \
  /* lighting_commands.cpp: the values' count is 1 for the scalar forms, 4 for the vector */ \
  /* forms, 0 for a NULL vector */                                                        \
  X(Light, light, GLenum, GLenum, Values4f)                                               \
  X(LightModel, lightModel, GLenum, Values4f)                                             \
  X(Material, material, GLenum, GLenum, Values4f)                                         \
  X(ColorMaterial, colorMaterial, GLenum, GLenum)                                         \
  /* matrix_commands.cpp (glLoadMatrixd / glMultMatrixd: the matrix in float, as GL keeps it) */ \
  X(MatrixMode, matrixMode, GLenum)                                                       \
  X(LoadIdentity, loadIdentity)                                                           \
  X(LoadMatrix, loadMatrix, Values16f)                                                    \
  X(MultMatrix, multMatrix, Values16f)                                                    \
  X(Translate, translate, GLdouble, GLdouble, GLdouble)                                   \
  X(Rotate, rotate, GLdouble, GLdouble, GLdouble, GLdouble)                               \
  X(Scale, scale, GLdouble, GLdouble, GLdouble)                                           \
  X(Ortho, ortho, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble)             \
  X(Frustum, frustum, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble)         \
  X(PushMatrix, pushMatrix)                                                               \
  X(PopMatrix, popMatrix)                                                                 \
  /* immediate_mode.cpp: glBegin / glEnd and what goes between them; the vertex forms in */ \
  /* float as 2 or 3 values, the others as 4 doubles and how many were given */           \
  X(Begin, begin, GLenum)                                                                 \
  X(End, end)                                                                             \
  X(Vertex2f, vertex2f, GLfloat, GLfloat)                                                 \
  X(Vertex3f, vertex3f, GLfloat, GLfloat, GLfloat)                                        \
  X(Vertex, vertex, GLdouble, GLdouble, GLdouble, GLdouble, GLint)                        \
  X(Color, color, GLfloat, GLfloat, GLfloat, GLfloat)                                     \
  X(Normal, normal, GLfloat, GLfloat, GLfloat)                                            \
  X(TexCoord, texCoord, GLfloat, GLfloat, GLfloat, GLfloat)                               \
  X(EdgeFlag, edgeFlag, GLboolean)                                                        \
  X(RastParam1, rastParam1, GLuint, GLdouble)                                             \
  X(RastParam3, rastParam3, GLuint, GLfloat, GLfloat, GLfloat)                            \
  X(RastParam4, rastParam4, GLuint, GLfloat, GLfloat, GLfloat, GLfloat)                   \
  X(RastParamfv, rastParamfv, GLuint, Values16f)                                          \
  X(RastParamiv, rastParamiv, GLuint, Values16i)                                          \
  X(SequencePoint, sequencePoint)                                                         \
  X(MaterialInterp, materialInterp, GLuint, GLenum, GLenum)                               \
  /* vertex_attributes.cpp: glRect, as GL_POLYGON's four vertices */                      \
  X(Rect, rect, GLdouble, GLdouble, GLdouble, GLdouble)                                   \
  /* display_lists.cpp: glCallList as a list executes it (list 0 or an unknown one is     */ \
  /* ignored, without the error a direct glCallList(0) gives, as in Mesa); an error found   */ \
  /* when a command was recorded (glDrawArrays' checks), raised when the list executes   */ \
  X(CallList, callList, GLuint)                                                           \
  X(ListBase, listBase, GLuint)                                                           \
  X(Error, raise, GLenum)                                                                 \
  /* texture_objects.cpp, texture_images.cpp: glTexParameter / glTexEnv / glTexGen as    */ \
  /* glLight's values are; glCopyTexImage*D and glCopyTexSubImage*D with their dimension */ \
  X(BindTexture, bindTexture, GLenum, GLuint)                                             \
  X(TexParameter, texParameter, GLenum, GLenum, Values4f)                                 \
  X(TexEnv, texEnv, GLenum, GLenum, Values4f)                                             \
  X(TexGen, texGen, GLenum, GLenum, Values4f)                                             \
  X(CopyTexImage, copyTexImage, GLint, GLenum, GLint, GLenum, GLint, GLint, GLsizei, GLsizei, GLint) \
  X(CopyTexSubImage, copyTexSubImage, GLint, GLenum, GLint, GLint, GLint, GLint, GLint, GLsizei, GLsizei)

enum class GlOp : uint32_t {
#define PF_OP(name, ...) name,
  PF_LIST_COMMANDS(PF_OP)
#undef PF_OP
  // glCallLists, of variable length: n, type, then n offsets from the list base when the type
  // is valid (display_lists.cpp).
  CallLists,
  // glTexImage*D / glTexSubImage*D, of variable length: the arguments, then the image unpacked
  // to RGBA floats when the list was compiled (texture_images.cpp).
  TexImage,
  // glBitmap, of variable length: the arguments, then the bitmap unpacked when the list was
  // compiled, a byte a pixel (bitmap.cpp).
  Bitmap,
  // glDrawPixels, of variable length: the arguments, then the image unpacked when the list was
  // compiled (draw_pixels.cpp).
  DrawPixels,
};

// Executes a recorded TexImage from the words after its opcode; returns how many it takes.
uint32_t replayTexImage(PFcontextRec& ctx, const uint32_t* args);
uint32_t replayBitmap(PFcontextRec& ctx, const uint32_t* args);
uint32_t replayDrawPixels(PFcontextRec& ctx, const uint32_t* args);

namespace cmd {
#define PF_DECLARE(name, fn, ...) void fn(PFcontextRec& ctx __VA_OPT__(, ) __VA_ARGS__);
PF_LIST_COMMANDS(PF_DECLARE)
#undef PF_DECLARE
}  // namespace cmd

template <GlOp>
struct Command;
#define PF_COMMAND(name, fn, ...)                                                          \
  template <>                                                                              \
  struct Command<GlOp::name> {                                                               \
    static constexpr void (*function)(PFcontextRec& __VA_OPT__(, ) __VA_ARGS__) = &cmd::fn; \
  };
PF_LIST_COMMANDS(PF_COMMAND)
#undef PF_COMMAND

// ---- Arguments as words -----------------------------------------------------------------------

template <class T>
constexpr uint32_t kWords = (sizeof(T) + 3) / 4;
template <class... P>
constexpr uint32_t kArgWords = (0u + ... + kWords<P>);

template <size_t I, class... P>
constexpr uint32_t argOffset() {
  constexpr uint32_t words[] = {kWords<P>..., 0u};
  uint32_t offset = 0;
  for (size_t k = 0; k < I; ++k) offset += words[k];
  return offset;
}

template <class T>
void storeArg(uint32_t*& at, const T& v) {
  static_assert(std::is_trivial_v<T>);
  at[kWords<T> - 1] = 0;  // a partly filled last word is zero, not left over
  std::memcpy(at, &v, sizeof(T));
  at += kWords<T>;
}

template <class T>
T loadArg(const uint32_t* at) {
  T v;
  std::memcpy(&v, at, sizeof(T));
  return v;
}

// A failed allocation while recording: GL_OUT_OF_MEMORY and a line on stderr; the command is
// left out of the list (display_lists.cpp).
void recordOutOfMemory(PFcontextRec& ctx);

// Appends the command and its arguments to the list being compiled. `extra` more words are
// reserved after them (glCallLists' offsets); returns them, or null if out of memory.
template <class... P>
uint32_t* record(PFcontextRec& ctx, GlOp op, size_t extra, const P&... args) {
  std::vector<uint32_t>& list = ctx.lists.building;
  const size_t at = list.size();
  try {
    list.resize(at + 1 + kArgWords<P...> + extra);
  } catch (const std::bad_alloc&) {
    recordOutOfMemory(ctx);
    return nullptr;
  }
  uint32_t* p = list.data() + at;
  *p++ = static_cast<uint32_t>(op);
  (storeArg(p, args), ...);
  return p;
}

template <class... P, class... A>
void recordAs(PFcontextRec& ctx, GlOp op, void (*)(PFcontextRec&, P...), const A&... args) {
  record<std::decay_t<P>...>(ctx, op, 0, static_cast<std::decay_t<P>>(args)...);
}

// Command `op` on `ctx`: executed; while a list is being compiled, recorded instead (and
// executed too under GL_COMPILE_AND_EXECUTE).
template <GlOp op, class... A>
inline void issue(PFcontextRec& ctx, const A&... args) {
  if (ctx.lists.compiling) [[unlikely]] {
    recordAs(ctx, op, Command<op>::function, args...);
    if (!ctx.lists.execute) return;
  }
  Command<op>::function(ctx, args...);
}

// A gl* entry point: issue() on the calling thread's context; nothing without one.
template <GlOp op, class... A>
inline void dispatch(const A&... args) {
  if (PFcontextRec* ctx = currentContext()) issue<op>(*ctx, args...);
}

// Executes a recorded command from its argument words; returns how many words they take.
template <class... P, size_t... I>
inline void invokeRecorded(void (*fn)(PFcontextRec&, P...), PFcontextRec& ctx, [[maybe_unused]] const uint32_t* args,
                           std::index_sequence<I...>) {
  fn(ctx, loadArg<std::decay_t<P>>(args + argOffset<I, std::decay_t<P>...>())...);
}
template <class... P>
inline uint32_t replayRecorded(void (*fn)(PFcontextRec&, P...), PFcontextRec& ctx, const uint32_t* args) {
  invokeRecorded(fn, ctx, args, std::index_sequence_for<P...>{});
  return kArgWords<std::decay_t<P>...>;
}

}  // namespace pf
