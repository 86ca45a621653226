// The GL-1.x state commands: errors, strings, synchronisation, clears, viewport, depth state,
// enables. (Matrices: matrix_commands.cpp; glBegin / glEnd and what comes between them:
// immediate_mode.cpp.)
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <new>

#include <glm/gtc/matrix_transform.hpp>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/query.h"
#include "raster/limits.h"

using pf::currentContext;

namespace {

pf::DepthFunc toDepthFunc(GLenum f) {
  switch (f) {
    case GL_NEVER: return pf::DepthFunc::Never;
    case GL_LESS: return pf::DepthFunc::Less;
    case GL_EQUAL: return pf::DepthFunc::Equal;
    case GL_LEQUAL: return pf::DepthFunc::LessEqual;
    case GL_GREATER: return pf::DepthFunc::Greater;
    case GL_NOTEQUAL: return pf::DepthFunc::NotEqual;
    case GL_GEQUAL: return pf::DepthFunc::GreaterEqual;
    default: return pf::DepthFunc::Always;
  }
}

// GL's clamp to [0, 1], NaN to 0 as Mesa stores it (glClearColor, glClearDepth, glDepthRange).
float clamp01(double v) { return v > 0 ? (v < 1 ? static_cast<float>(v) : 1.0f) : 0.0f; }

// The capabilities primflow has: depth test, face culling, lighting and its lights, colour
// material, normalising and rescaling normals, per-pixel lighting of vertex primitives, the
// per-fragment operations and dithering (kept, nothing dithered), 1D and 2D texturing and
// texture coordinate generation, fog, clip planes, the line and polygon stipples, the polygon
// offsets.
bool* capability(PFcontextRec& ctx, GLenum cap) {
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + pf::kMaxLights) return &ctx.lighting.lights[cap - GL_LIGHT0].enabled;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + pf::kMaxClipPlanes) return &ctx.clip.enabled[cap - GL_CLIP_PLANE0];
  switch (cap) {
    case GL_DEPTH_TEST: return &ctx.depth_test;
    case GL_CULL_FACE: return &ctx.cull;
    case GL_LIGHTING: return &ctx.lighting.enabled;
    case GL_COLOR_MATERIAL: return &ctx.lighting.color_material;
    case GL_NORMALIZE: return &ctx.lighting.normalize;
    case GL_RESCALE_NORMAL: return &ctx.lighting.rescale_normal;
    case GL_PER_PIXEL_LIGHTING_EXT: return &ctx.lighting.per_pixel_vertices;
    case GL_SCISSOR_TEST: return &ctx.fragment.scissor_test;
    case GL_ALPHA_TEST: return &ctx.fragment.alpha_test;
    case GL_BLEND: return &ctx.fragment.blend;
    case GL_COLOR_LOGIC_OP: return &ctx.fragment.logic_op;
    case GL_DITHER: return &ctx.fragment.dither;
    case GL_STENCIL_TEST: return &ctx.fragment.stencil_test;
    case GL_FOG: return &ctx.fog.enabled;
    case GL_LINE_STIPPLE: return &ctx.raster_modes.line_stipple;
    case GL_POLYGON_OFFSET_FILL: return &ctx.raster_modes.offset_fill;
    case GL_POLYGON_OFFSET_LINE: return &ctx.raster_modes.offset_line;
    case GL_POLYGON_OFFSET_POINT: return &ctx.raster_modes.offset_point;
    case GL_POLYGON_STIPPLE: return &ctx.raster_modes.polygon_stipple;
    case GL_TEXTURE_1D: return &ctx.textures.a.enabled_1d;
    case GL_TEXTURE_2D: return &ctx.textures.a.enabled_2d;
    case GL_TEXTURE_GEN_S: return &ctx.textures.a.gen[0].enabled;
    case GL_TEXTURE_GEN_T: return &ctx.textures.a.gen[1].enabled;
    case GL_TEXTURE_GEN_R: return &ctx.textures.a.gen[2].enabled;
    case GL_TEXTURE_GEN_Q: return &ctx.textures.a.gen[3].enabled;
    default: ctx.setError(GL_INVALID_ENUM); return nullptr;
  }
}

}  // namespace

void PFcontextRec::outOfMemory(const char* command) {
  setError(GL_OUT_OF_MEMORY);
  if (in_begin) {
    begin_out_of_memory = true;
    rows = {};
    row_shading = {};
    rows_count = 0;
    vertex_lighting.clear();
  } else {
    renderer.discardPending();
  }
  std::fprintf(stderr, "primflow: %s: out of memory: %s dropped\n", command,
               in_begin ? "the glBegin in progress" : "the drawing recorded since the last flush");
}

void PFcontextRec::flush() {
  if (renderer.pending()) frame_changed = true;
  try {
    renderer.flush();
  } catch (const std::bad_alloc&) {  // the renderer has dropped the frame
    outOfMemory("drawing");
  }
}

void PFcontextRec::finish() {
  flush();
  primitives.replaced.clear();  // nothing pending refers to replaced programs any more
  pf::IterationCapReport r = renderer.takeIterationCapReport();
  if (r.pixels == 0 && r.instances == 0) return;
  setError(GL_TOO_MANY_ITERATIONS_EXT);
  std::fprintf(stderr,
               "primflow: primitive '%s' ran a loop past the iteration cap (%u): %llu pixel(s) and "
               "%llu instance(s) stopped and not drawn\n",
               r.primitive.c_str(), iteration_cap, static_cast<unsigned long long>(r.pixels),
               static_cast<unsigned long long>(r.instances));
}

pf::RasterState PFcontextRec::rasterState() const {
  pf::RasterState s;
  const float x = static_cast<float>(viewport[0]), y = static_cast<float>(viewport[1]);
  const float w = static_cast<float>(viewport[2]), h = static_cast<float>(viewport[3]);
  s.vp_scale_x = w * 0.5f;
  s.vp_offset_x = x + w * 0.5f;
  s.vp_scale_y = h * 0.5f;
  s.vp_offset_y = y + h * 0.5f;
  s.depth_scale = (depth_range[1] - depth_range[0]) * 0.5f;
  s.depth_offset = (depth_range[1] + depth_range[0]) * 0.5f;
  s.depth_near = depth_range[0];
  s.depth_far = depth_range[1];
  // (In 64 bits, clamped: a viewport at INT_MAX must not overflow.)
  auto end = [](int origin, int size) {
    return static_cast<int>(std::clamp<int64_t>(int64_t{origin} + size, INT32_MIN, INT32_MAX));
  };
  s.vp_x0 = viewport[0];
  s.vp_y0 = viewport[1];
  s.vp_x1 = end(viewport[0], viewport[2]);
  s.vp_y1 = end(viewport[1], viewport[3]);
  s.depth_test = depth_test && depth_bits > 0;
  s.depth_write = depth_write;
  s.depth_func = toDepthFunc(depth_func);
  s.iteration_cap = iteration_cap;
  s.fields = &fields;
  s.cull_front = cull && (cull_face == GL_FRONT || cull_face == GL_FRONT_AND_BACK);
  s.cull_back = cull && (cull_face == GL_BACK || cull_face == GL_FRONT_AND_BACK);
  s.front_ccw = front_face == GL_CCW;
  s.flat_shading = shade_model == GL_FLAT;
  s.color_mask = color_mask;
  s.fragment = pf::fragmentOps(fragment, stencil_bits > 0);
  const glm::mat4 inv = glm::inverse(projection.top);
  const glm::mat4 inv_mv = glm::inverse(modelview.top);
  // A singular matrix (glScalef(1, 1, 0), planar shadows) has no inverse: its inf and NaN become
  // 0, so that states still compare equal and the primitives that need the inverse see zeros.
  auto finite = [](float v) { return std::isfinite(v) ? v : 0.0f; };
  for (int k = 0; k < 16; ++k) {
    s.inv_projection[k] = finite(inv[k / 4][k % 4]);
    s.projection[k] = projection.top[k / 4][k % 4];
    s.inv_modelview[k] = finite(inv_mv[k / 4][k % 4]);
    s.modelview[k] = modelview.top[k / 4][k % 4];
  }
  pf::windowClipPlanes(clip, s.projection, s);
  pf::applyRasterModes(raster_modes, s);
  return s;
}

// ---- The recorded commands (commands.h): what each does once the context is known ----------

namespace pf::cmd {

void clear(PFcontextRec& ctx, GLbitfield mask) {
  if (!outsideBegin(ctx)) return;
  constexpr GLbitfield kKnown = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~kKnown) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  bool depth = (mask & GL_DEPTH_BUFFER_BIT) && ctx.depth_bits > 0 && ctx.depth_write;
  try {  // a clear after drawing draws first
    const pf::FragmentOps ops = pf::fragmentOps(ctx.fragment, false);  // the scissor box limits a clear
    pf::PixelRect rect;
    if (ops.scissor) rect = pf::PixelRect{ops.scissor_x0, ops.scissor_y0, ops.scissor_x1, ops.scissor_y1};
    ctx.renderer.clear((mask & GL_COLOR_BUFFER_BIT) != 0 && ctx.color_mask != 0, depth, ctx.clear_color,
                       ctx.clear_depth, ctx.color_mask, rect);
    if ((mask & GL_STENCIL_BUFFER_BIT) && ctx.stencil_bits > 0 && (ctx.fragment.stencil_write_mask & 0xff) != 0)
      ctx.renderer.clearStencil(static_cast<uint8_t>(ctx.fragment.stencil_clear),
                                static_cast<uint8_t>(ctx.fragment.stencil_write_mask), rect);
    if (mask & GL_ACCUM_BUFFER_BIT) pf::clearAccumBuffer(ctx);  // (drawing never touches it: no wait)
  } catch (const std::bad_alloc&) {
    ctx.outOfMemory("glClear");
  }
}

void clearColor(PFcontextRec& ctx, GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  if (!outsideBegin(ctx)) return;
  ctx.clear_color[0] = clamp01(r);
  ctx.clear_color[1] = clamp01(g);
  ctx.clear_color[2] = clamp01(b);
  ctx.clear_color[3] = clamp01(a);
}

void clearDepth(PFcontextRec& ctx, GLdouble depth) {
  if (outsideBegin(ctx)) ctx.clear_depth = clamp01(depth);
}

void viewport(PFcontextRec& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (!outsideBegin(ctx)) return;
  if (width < 0 || height < 0) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  ctx.viewport[0] = x;
  ctx.viewport[1] = y;
  ctx.viewport[2] = width > kMaxFramebufferSize ? kMaxFramebufferSize : width;
  ctx.viewport[3] = height > kMaxFramebufferSize ? kMaxFramebufferSize : height;
}

void depthFunc(PFcontextRec& ctx, GLenum func) {
  if (!outsideBegin(ctx)) return;
  if (func < GL_NEVER || func > GL_ALWAYS) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  ctx.depth_func = func;
}

void depthMask(PFcontextRec& ctx, GLboolean flag) {
  if (outsideBegin(ctx)) ctx.depth_write = flag != GL_FALSE;
}

void depthRange(PFcontextRec& ctx, GLdouble zNear, GLdouble zFar) {
  if (!outsideBegin(ctx)) return;
  ctx.depth_range[0] = clamp01(zNear);
  ctx.depth_range[1] = clamp01(zFar);
}

void enable(PFcontextRec& ctx, GLenum cap) {
  if (!outsideBegin(ctx)) return;
  if (bool* c = capability(ctx, cap)) *c = true;
  if (cap == GL_TEXTURE_1D || cap == GL_TEXTURE_2D) ctx.textures.dirty = true;
  if (cap == GL_COLOR_MATERIAL) ctx.lighting.trackColor(ctx.current_color);  // tracks from now on
}

void disable(PFcontextRec& ctx, GLenum cap) {
  if (!outsideBegin(ctx)) return;
  if (bool* c = capability(ctx, cap)) *c = false;
  if (cap == GL_TEXTURE_1D || cap == GL_TEXTURE_2D) ctx.textures.dirty = true;
}

void colorMask(PFcontextRec& ctx, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  if (!outsideBegin(ctx)) return;
  ctx.color_mask = static_cast<uint8_t>((r ? 1 : 0) | (g ? 2 : 0) | (b ? 4 : 0) | (a ? 8 : 0));
}

// glCullFace, glFrontFace, glShadeModel: one of a few modes into `field`, else GL_INVALID_ENUM.
static void setMode(PFcontextRec& ctx, GLenum& field, GLenum mode, std::initializer_list<GLenum> allowed) {
  if (!outsideBegin(ctx)) return;
  if (std::find(allowed.begin(), allowed.end(), mode) == allowed.end()) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  field = mode;
}

void cullFace(PFcontextRec& ctx, GLenum mode) {
  setMode(ctx, ctx.cull_face, mode, {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK});
}
void frontFace(PFcontextRec& ctx, GLenum mode) { setMode(ctx, ctx.front_face, mode, {GL_CW, GL_CCW}); }
void shadeModel(PFcontextRec& ctx, GLenum mode) { setMode(ctx, ctx.shade_model, mode, {GL_FLAT, GL_SMOOTH}); }

// glHint: kept and read back; nothing primflow draws depends on a hint. A bad mode or target:
// GL_INVALID_ENUM.
void hint(PFcontextRec& ctx, GLenum target, GLenum mode) {
  if (!outsideBegin(ctx)) return;
  const int index = hintIndex(target);
  if (index < 0 || (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  ctx.hints[index] = mode;
}

}  // namespace pf::cmd

int pf::hintIndex(GLenum target) {
  static constexpr GLenum kTargets[kHintCount] = {GL_PERSPECTIVE_CORRECTION_HINT, GL_POINT_SMOOTH_HINT,
                                                  GL_LINE_SMOOTH_HINT,            GL_POLYGON_SMOOTH_HINT,
                                                  GL_FOG_HINT,                    GL_GENERATE_MIPMAP_HINT,
                                                  GL_TEXTURE_COMPRESSION_HINT};
  for (int k = 0; k < kHintCount; ++k)
    if (kTargets[k] == target) return k;
  return -1;
}

extern "C" {

GLenum pfglGetError(void) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return GL_NO_ERROR;
  if (ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return GL_NO_ERROR;
  }
  GLenum e = ctx->error;
  ctx->error = GL_NO_ERROR;
  return e;
}

const GLubyte* pfglGetString(GLenum name) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return nullptr;
  const char* s = nullptr;
  switch (name) {
    case GL_VENDOR: s = "primflow"; break;
    case GL_RENDERER: s = "primflow tiled SIMD rasterizer"; break;
    case GL_VERSION: s = "1.1 primflow 0.1.0"; break;
    case GL_EXTENSIONS: s = ""; break;
    default: ctx->setError(GL_INVALID_ENUM); return nullptr;
  }
  return reinterpret_cast<const GLubyte*>(s);
}

void pfglFinish(void) {
  if (PFcontextRec* ctx = pf::contextOutsideBegin()) {
    ctx->finish();
    // The hook only when something was drawn since it last ran, as OSMesa copies its frame
    // only when it has changed.
    if (ctx->frame_hook && ctx->frame_changed) {
      ctx->frame_changed = false;
      ctx->frame_hook(ctx->frame_hook_user);
    }
  }
}

void pfglFlush(void) { pfglFinish(); }

void pfglClear(GLbitfield mask) { pf::dispatch<pf::GlOp::Clear>(mask); }
void pfglClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { pf::dispatch<pf::GlOp::ClearColor>(r, g, b, a); }
void pfglClearDepth(GLclampd depth) { pf::dispatch<pf::GlOp::ClearDepth>(depth); }
void pfglViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  pf::dispatch<pf::GlOp::Viewport>(x, y, width, height);
}
void pfglDepthFunc(GLenum func) { pf::dispatch<pf::GlOp::DepthFunc>(func); }
void pfglDepthMask(GLboolean flag) { pf::dispatch<pf::GlOp::DepthMask>(flag); }
void pfglDepthRange(GLclampd zNear, GLclampd zFar) { pf::dispatch<pf::GlOp::DepthRange>(zNear, zFar); }
void pfglEnable(GLenum cap) { pf::dispatch<pf::GlOp::Enable>(cap); }
void pfglDisable(GLenum cap) { pf::dispatch<pf::GlOp::Disable>(cap); }

GLboolean pfglIsEnabled(GLenum cap) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return GL_FALSE;
  if (cap == GL_VERTEX_ARRAY) return ctx->vertex_array.enabled ? GL_TRUE : GL_FALSE;
  if (cap == GL_COLOR_ARRAY) return ctx->color_array.enabled ? GL_TRUE : GL_FALSE;
  if (cap == GL_NORMAL_ARRAY) return ctx->normal_array.enabled ? GL_TRUE : GL_FALSE;
  if (cap == GL_TEXTURE_COORD_ARRAY) return ctx->texcoord_array.enabled ? GL_TRUE : GL_FALSE;
  if (cap == GL_EDGE_FLAG_ARRAY) return ctx->edge_flag_array.enabled ? GL_TRUE : GL_FALSE;
  bool fixed = false;  // a capability primflow does not have: its constant state, no error
  if (pf::constantCapability(cap, fixed)) return fixed ? GL_TRUE : GL_FALSE;
  bool* c = capability(*ctx, cap);
  return c && *c ? GL_TRUE : GL_FALSE;
}

void pfglColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a) { pf::dispatch<pf::GlOp::ColorMask>(r, g, b, a); }
void pfglCullFace(GLenum mode) { pf::dispatch<pf::GlOp::CullFace>(mode); }
void pfglFrontFace(GLenum mode) { pf::dispatch<pf::GlOp::FrontFace>(mode); }
void pfglShadeModel(GLenum mode) { pf::dispatch<pf::GlOp::ShadeModel>(mode); }
void pfglHint(GLenum target, GLenum mode) { pf::dispatch<pf::GlOp::Hint>(target, mode); }

}  // extern "C"
