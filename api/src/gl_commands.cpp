// The GL-1.x entry points of the spine subset: errors, clears, viewport, matrices, enables,
// and immediate mode. glVertex binds the current values as a sequence point (paper section
// 3.1); glEnd groups the sequence points into instances of the mode's primitive and hands each
// to the renderer. Nothing here knows what a triangle is: the primitive's declaration says how
// many sequence points an instance takes and which parameters it wants.
#include <bit>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include <primflow/gl.h>

#include "api/src/context_state.h"
#include "raster/limits.h"

using pf::currentContext;

namespace {

// Commands that GL forbids between glBegin and glEnd report GL_INVALID_OPERATION.
PFcontextRec* outsideBegin() {
  PFcontextRec* ctx = currentContext();
  if (ctx && ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return ctx;
}

glm::mat4& currentMatrix(PFcontextRec& ctx) {
  return ctx.matrix_mode == GL_PROJECTION ? ctx.projection : ctx.modelview;
}

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

float clamp01(double v) { return v < 0 ? 0.0f : v > 1 ? 1.0f : static_cast<float>(v); }

// Hands the sequence points gathered since glBegin to the renderer: for a primitive with a
// fixed count, one instance per `sequence_points` of them (a trailing incomplete group is
// dropped, as GL drops it); for one with parameter-sized arrays, one instance holding them all.
void submitInstances(PFcontextRec& ctx) {
  const pf::CompiledPrimitive& prim = *ctx.begin_primitive;
  const size_t total = ctx.sequence_points.size();
  const bool sized = prim.sequence_points == 0;
  const size_t per = sized ? total : static_cast<size_t>(prim.sequence_points);
  if (per == 0) return;
  const int count = static_cast<int>(per);
  const pf::ParamInfo* vertex = prim.findParam("vertex");
  // The colour is the one per-vertex shading parameter so far: 4 channels, interpolated
  // perspective-correct (GL's default), in G-buffer slots 0-3.
  pf::ChannelLayout layout;
  if (prim.has_interp_data) layout = pf::ChannelLayout::ofKind(4, pf::InterpKind::PerspectiveLinear);
  pf::ShadeState shade;
  if (prim.has_interp_data) {
    shade.color_slot = 0;
  } else {
    for (int k = 0; k < 4; ++k) shade.constant_color[k] = ctx.current_color[k];
  }
  const pf::RasterState state = ctx.rasterState();
  ctx.param_block.assign(static_cast<size_t>(prim.paramFloats(count)), 0u);
  if (sized) ctx.param_block[static_cast<size_t>(prim.count_slot)] = static_cast<uint32_t>(count);
  ctx.vertex_channels.assign(per * static_cast<size_t>(layout.count), 0.0f);
  for (size_t first = 0; first + per <= total; first += per) {
    for (size_t i = 0; i < per; ++i) {
      const pf::SequencePoint& sp = ctx.sequence_points[first + i];
      if (vertex) {
        const size_t at = static_cast<size_t>(prim.paramOffset(*vertex, count, static_cast<int>(i)));
        for (int c = 0; c < 4; ++c) ctx.param_block[at + c] = std::bit_cast<uint32_t>(sp.position[c]);
      }
      for (int c = 0; c < layout.count; ++c) ctx.vertex_channels[i * layout.count + c] = sp.color[c];
    }
    ctx.renderer.submit(prim, ctx.param_block.data(), ctx.vertex_channels.data(), layout, state, shade, count);
  }
}

// The parameters this API can feed so far: a per-sequence-point point `vertex`, the count of
// a parameter-sized one, and the interpolator_data. A primitive wanting others cannot be drawn
// through glBegin yet.
bool feedable(const pf::CompiledPrimitive& prim) {
  for (const pf::ParamInfo& p : prim.params) {
    bool is_vertex = p.name == "vertex" && p.per_sequence_point && p.type.base == pf::BaseType::Point;
    bool is_count = prim.sequence_points == 0 && !p.per_sequence_point && p.offset == prim.count_slot;
    if (!is_vertex && !is_count) return false;
  }
  return true;
}

}  // namespace

void PFcontextRec::finish() {
  renderer.flush();
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
  s.vp_x0 = viewport[0];
  s.vp_y0 = viewport[1];
  s.vp_x1 = viewport[0] + viewport[2];
  s.vp_y1 = viewport[1] + viewport[3];
  s.depth_test = depth_test && depth_bits > 0;
  s.depth_write = depth_write;
  s.depth_func = toDepthFunc(depth_func);
  s.iteration_cap = iteration_cap;
  return s;
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
  PFcontextRec* ctx = outsideBegin();
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
  if (PFcontextRec* ctx = outsideBegin()) ctx->finish();
}

void pfglFlush(void) {
  if (PFcontextRec* ctx = outsideBegin()) ctx->finish();
}

void pfglClear(GLbitfield mask) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  constexpr GLbitfield kKnown = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;
  if (mask & ~kKnown) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  bool depth = (mask & GL_DEPTH_BUFFER_BIT) && ctx->depth_bits > 0 && ctx->depth_write;
  ctx->renderer.clear((mask & GL_COLOR_BUFFER_BIT) != 0, depth, ctx->clear_color, ctx->clear_depth);
}

void pfglClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  ctx->clear_color[0] = clamp01(r);
  ctx->clear_color[1] = clamp01(g);
  ctx->clear_color[2] = clamp01(b);
  ctx->clear_color[3] = clamp01(a);
}

void pfglClearDepth(GLclampd depth) {
  if (PFcontextRec* ctx = outsideBegin()) ctx->clear_depth = clamp01(depth);
}

void pfglViewport(GLint x, GLint y, GLsizei width, GLsizei height) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (width < 0 || height < 0) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  ctx->viewport[0] = x;
  ctx->viewport[1] = y;
  ctx->viewport[2] = width > pf::kMaxFramebufferSize ? pf::kMaxFramebufferSize : width;
  ctx->viewport[3] = height > pf::kMaxFramebufferSize ? pf::kMaxFramebufferSize : height;
}

void pfglDepthFunc(GLenum func) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (func < GL_NEVER || func > GL_ALWAYS) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  ctx->depth_func = func;
}

void pfglDepthMask(GLboolean flag) {
  if (PFcontextRec* ctx = outsideBegin()) ctx->depth_write = flag != GL_FALSE;
}

void pfglDepthRange(GLclampd zNear, GLclampd zFar) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  ctx->depth_range[0] = clamp01(zNear);
  ctx->depth_range[1] = clamp01(zFar);
}

void pfglEnable(GLenum cap) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (cap == GL_DEPTH_TEST) ctx->depth_test = true;
  else ctx->setError(GL_INVALID_ENUM);
}

void pfglDisable(GLenum cap) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (cap == GL_DEPTH_TEST) ctx->depth_test = false;
  else ctx->setError(GL_INVALID_ENUM);
}

GLboolean pfglIsEnabled(GLenum cap) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return GL_FALSE;
  if (cap == GL_DEPTH_TEST) return ctx->depth_test ? GL_TRUE : GL_FALSE;
  ctx->setError(GL_INVALID_ENUM);
  return GL_FALSE;
}

void pfglMatrixMode(GLenum mode) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  ctx->matrix_mode = mode;
}

void pfglLoadIdentity(void) {
  if (PFcontextRec* ctx = outsideBegin()) currentMatrix(*ctx) = glm::mat4(1.0f);
}

void pfglOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (l == r || b == t || n == f) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  glm::mat4& m = currentMatrix(*ctx);
  m = m * glm::mat4(glm::ortho(l, r, b, t, n, f));
}

void pfglFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  PFcontextRec* ctx = outsideBegin();
  if (!ctx) return;
  if (n <= 0 || f <= 0 || l == r || b == t || n == f) {
    ctx->setError(GL_INVALID_VALUE);
    return;
  }
  glm::mat4& m = currentMatrix(*ctx);
  m = m * glm::mat4(glm::frustum(l, r, b, t, n, f));
}

void pfglBegin(GLenum mode) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return;
  if (ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return;
  }
  auto it = ctx->primitives.by_mode.find(mode);
  if (it == ctx->primitives.by_mode.end()) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  if (!feedable(*it->second)) {
    ctx->setError(GL_INVALID_OPERATION);
    return;
  }
  ctx->in_begin = true;
  ctx->begin_primitive = it->second.get();
  ctx->sequence_points.clear();
}

void pfglEnd(void) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return;
  if (!ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return;
  }
  ctx->in_begin = false;
  if (ctx->color) submitInstances(*ctx);
  ctx->sequence_points.clear();
  ctx->begin_primitive = nullptr;
}

void pfglVertex3f(GLfloat x, GLfloat y, GLfloat z) {
  PFcontextRec* ctx = currentContext();
  if (!ctx || !ctx->in_begin) return;  // outside Begin/End a vertex has no effect (GL: undefined)
  pf::SequencePoint sp;
  sp.position = ctx->projection * (ctx->modelview * glm::vec4(x, y, z, 1.0f));
  sp.color = ctx->current_color;
  ctx->sequence_points.push_back(sp);
}

void pfglVertex2f(GLfloat x, GLfloat y) { pfglVertex3f(x, y, 0.0f); }

void pfglColor4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) {
  PFcontextRec* ctx = currentContext();
  if (ctx) ctx->current_color = glm::vec4(r, g, b, a);
}

void pfglColor3f(GLfloat r, GLfloat g, GLfloat b) { pfglColor4f(r, g, b, 1.0f); }

}  // extern "C"
