// The per-fragment operations' commands (GL 1.5 section 4.1): glScissor, glAlphaFunc, the
// stencil commands, the blending commands and glLogicOp, with OSMesa's errors; their enables are in gl_commands.cpp,
// their queries in state_queries.cpp, and rasterState() hands them to the renderer
// (raster/fragment_ops.h) with each draw.
#include <algorithm>
#include <cstdint>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf {
namespace {

// GL's clamp to [0, 1] of a reference value or a constant colour (Mesa's CLAMP: NaN stays NaN,
// which no comparison passes and which 8 bits store as 0).
float clampUnit(GLfloat v) { return v < 0.0f ? 0.0f : v > 1.0f ? 1.0f : v; }

// A blend factor OSMesa takes as a source; as a destination also, except that
// GL_SRC_ALPHA_SATURATE is a destination too (ARB_blend_func_extended, which llvmpipe has).
// The dual-source factors (GL_SRC1_*) are not taken: no primitive has a second colour.
bool blendFactor(GLenum f) {
  switch (f) {
    case GL_ZERO: case GL_ONE:
    case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_DST_COLOR: case GL_ONE_MINUS_DST_COLOR:
    case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA: case GL_ONE_MINUS_DST_ALPHA:
    case GL_SRC_ALPHA_SATURATE:
    case GL_CONSTANT_COLOR: case GL_ONE_MINUS_CONSTANT_COLOR:
    case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
      return true;
    default:
      return false;
  }
}

// glStencilOp's operations.
bool stencilOperation(GLenum op) {
  switch (op) {
    case GL_KEEP: case GL_ZERO: case GL_REPLACE: case GL_INCR: case GL_DECR: case GL_INVERT:
    case GL_INCR_WRAP: case GL_DECR_WRAP:
      return true;
    default:
      return false;
  }
}

}  // namespace

namespace cmd {

void scissor(PFcontextRec& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (!outsideBegin(ctx)) return;
  if (width < 0 || height < 0) return ctx.setError(GL_INVALID_VALUE);
  int* box = ctx.fragment.scissor;
  box[0] = x, box[1] = y, box[2] = width, box[3] = height;
}

void alphaFunc(PFcontextRec& ctx, GLenum func, GLfloat ref) {
  if (!outsideBegin(ctx)) return;
  if (func < GL_NEVER || func > GL_ALWAYS) return ctx.setError(GL_INVALID_ENUM);
  ctx.fragment.alpha_func = func;
  ctx.fragment.alpha_ref = clampUnit(ref);
}

void blendFuncSeparate(PFcontextRec& ctx, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha) {
  if (!outsideBegin(ctx)) return;
  if (!blendFactor(src_rgb) || !blendFactor(dst_rgb) || !blendFactor(src_alpha) || !blendFactor(dst_alpha))
    return ctx.setError(GL_INVALID_ENUM);
  FragmentState& f = ctx.fragment;
  f.blend_src_rgb = src_rgb, f.blend_dst_rgb = dst_rgb, f.blend_src_alpha = src_alpha, f.blend_dst_alpha = dst_alpha;
}

void blendEquation(PFcontextRec& ctx, GLenum mode) {
  if (!outsideBegin(ctx)) return;
  switch (mode) {
    case GL_FUNC_ADD: case GL_FUNC_SUBTRACT: case GL_FUNC_REVERSE_SUBTRACT: case GL_MIN: case GL_MAX:
      ctx.fragment.blend_equation = mode;
      return;
    default:
      return ctx.setError(GL_INVALID_ENUM);
  }
}

void blendColor(PFcontextRec& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  if (!outsideBegin(ctx)) return;
  const GLfloat v[4] = {r, g, b, a};
  for (int k = 0; k < 4; ++k) ctx.fragment.blend_color[k] = clampUnit(v[k]);
}

void stencilFunc(PFcontextRec& ctx, GLenum func, GLint ref, GLuint mask) {
  if (!outsideBegin(ctx)) return;
  if (func < GL_NEVER || func > GL_ALWAYS) return ctx.setError(GL_INVALID_ENUM);
  FragmentState& f = ctx.fragment;
  f.stencil_func = func, f.stencil_ref = ref, f.stencil_value_mask = mask;
}

void stencilOp(PFcontextRec& ctx, GLenum fail, GLenum depth_fail, GLenum depth_pass) {
  if (!outsideBegin(ctx)) return;
  if (!stencilOperation(fail) || !stencilOperation(depth_fail) || !stencilOperation(depth_pass))
    return ctx.setError(GL_INVALID_ENUM);
  FragmentState& f = ctx.fragment;
  f.stencil_fail = fail, f.stencil_depth_fail = depth_fail, f.stencil_depth_pass = depth_pass;
}

void stencilMask(PFcontextRec& ctx, GLuint mask) {
  if (outsideBegin(ctx)) ctx.fragment.stencil_write_mask = mask;
}

void clearStencil(PFcontextRec& ctx, GLint s) {
  if (outsideBegin(ctx)) ctx.fragment.stencil_clear = s;
}

void logicOp(PFcontextRec& ctx, GLenum opcode) {
  if (!outsideBegin(ctx)) return;
  if (opcode < GL_CLEAR || opcode > GL_SET) return ctx.setError(GL_INVALID_ENUM);
  ctx.fragment.logic_mode = opcode;
}

}  // namespace cmd

// The snapshot a draw takes (PFcontextRec::rasterState).
FragmentOps fragmentOps(const FragmentState& f, bool has_stencil) {
  FragmentOps ops;
  if (f.stencil_test && has_stencil) {
    StencilOps& s = ops.stencil;
    s.test = true;
    s.func = static_cast<CompareFunc>(f.stencil_func - GL_NEVER);
    s.ref = static_cast<uint8_t>(std::clamp(f.stencil_ref, 0, 255));
    s.value_mask = static_cast<uint8_t>(f.stencil_value_mask);
    s.write_mask = static_cast<uint8_t>(f.stencil_write_mask);
    s.fail = f.stencil_fail, s.depth_fail = f.stencil_depth_fail, s.depth_pass = f.stencil_depth_pass;
  }
  if (f.scissor_test) {
    // (In 64 bits, clamped: a box reaching past INT_MAX must not overflow.)
    auto end = [](int origin, int size) {
      return static_cast<int>(std::min<int64_t>(int64_t{origin} + size, INT32_MAX));
    };
    ops.scissor = true;
    ops.scissor_x0 = f.scissor[0];
    ops.scissor_y0 = f.scissor[1];
    ops.scissor_x1 = end(f.scissor[0], f.scissor[2]);
    ops.scissor_y1 = end(f.scissor[1], f.scissor[3]);
  }
  if (f.alpha_test) {
    ops.alpha_test = true;
    ops.alpha_func = static_cast<CompareFunc>(f.alpha_func - GL_NEVER);
    ops.alpha_ref = toUnorm8Even(f.alpha_ref);
  }
  if (f.logic_op) {
    ops.logic_op = true;
    ops.logic_mode = f.logic_mode;
  } else if (f.blend) {
    ops.blend = true;
    ops.src_rgb = f.blend_src_rgb, ops.dst_rgb = f.blend_dst_rgb;
    ops.src_alpha = f.blend_src_alpha, ops.dst_alpha = f.blend_dst_alpha;
    ops.equation_rgb = ops.equation_alpha = f.blend_equation;
    for (int k = 0; k < 4; ++k) ops.blend_color[k] = toUnorm8Even(f.blend_color[k]);
  }
  return ops;
}

}  // namespace pf

extern "C" {

void pfglScissor(GLint x, GLint y, GLsizei width, GLsizei height) { pf::dispatch<pf::GlOp::Scissor>(x, y, width, height); }
void pfglAlphaFunc(GLenum func, GLclampf ref) { pf::dispatch<pf::GlOp::AlphaFunc>(func, ref); }
void pfglBlendFunc(GLenum sfactor, GLenum dfactor) {
  pf::dispatch<pf::GlOp::BlendFuncSeparate>(sfactor, dfactor, sfactor, dfactor);
}
void pfglBlendFuncSeparate(GLenum sfactorRGB, GLenum dfactorRGB, GLenum sfactorAlpha, GLenum dfactorAlpha) {
  pf::dispatch<pf::GlOp::BlendFuncSeparate>(sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha);
}
void pfglBlendEquation(GLenum mode) { pf::dispatch<pf::GlOp::BlendEquation>(mode); }
void pfglBlendColor(GLclampf red, GLclampf green, GLclampf blue, GLclampf alpha) {
  pf::dispatch<pf::GlOp::BlendColor>(red, green, blue, alpha);
}
void pfglLogicOp(GLenum opcode) { pf::dispatch<pf::GlOp::LogicOp>(opcode); }
void pfglStencilFunc(GLenum func, GLint ref, GLuint mask) { pf::dispatch<pf::GlOp::StencilFunc>(func, ref, mask); }
void pfglStencilOp(GLenum fail, GLenum zfail, GLenum zpass) { pf::dispatch<pf::GlOp::StencilOp>(fail, zfail, zpass); }
void pfglStencilMask(GLuint mask) { pf::dispatch<pf::GlOp::StencilMask>(mask); }
void pfglClearStencil(GLint s) { pf::dispatch<pf::GlOp::ClearStencil>(s); }

}  // extern "C"
