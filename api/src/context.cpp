// Context creation, binding to the caller's buffer, the depth buffer, destruction.
// Built-in primitives are compiled here from their embedded source (primitives/*.pfl).
#include <cstdio>
#include <mutex>
#include <new>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include "api/src/context_state.h"
#include "api/src/frame_hook.h"
#include "compiler/builtin_primitives.h"
#include "raster/limits.h"
#include "raster/worker_pool.h"

namespace pf {

namespace {
thread_local PFcontextRec* g_current = nullptr;

// The glBegin modes that map to built-in primitives, by primitive name.
struct ModeName {
  GLenum mode;
  const char* primitive;
};
constexpr ModeName kModes[] = {
    {GL_TRIANGLES, "triangles"},         {GL_TRIANGLE_STRIP, "triangle_strip"},
    {GL_TRIANGLE_FAN, "triangle_fan"},   {GL_QUADS, "quads"},
    {GL_QUAD_STRIP, "quad_strip"},       {GL_POLYGON, "polygon"},
    {GL_POINTS, "points"},               {GL_LINES, "lines"},
    {GL_LINE_STRIP, "line_strip"},       {GL_LINE_LOOP, "line_loop"}};

bool registerBuiltins(PFcontextRec& ctx) {
  const BuiltinPrimitives& builtins = builtinPrimitives();
  if (!builtins.errors.empty()) {
    std::fprintf(stderr, "primflow: built-in primitive failed to compile:\n%s", builtins.errors.c_str());
    return false;
  }
  for (const auto& p : builtins.in_order) {
    GLenum mode = PrimitiveRegistry::kAnyMode;
    for (const ModeName& m : kModes)
      if (p->name == m.primitive) mode = m.mode;
    ctx.primitives.add(p, mode);
  }
  for (const auto& p : builtins.interpolators) ctx.primitives.addInterpolator(p);
  return true;
}

}  // namespace

PFcontextRec* currentContext() { return g_current; }

void setFrameHook(PFcontextRec* ctx, FrameHook hook, void* user) {
  if (!ctx) return;
  ctx->frame_hook = hook;
  ctx->frame_hook_user = user;
}

void shareDisplayLists(PFcontextRec* ctx, PFcontextRec* with) {
  if (ctx && with) ctx->lists.names = with->lists.names;
}

void unsupportedEntryPoint(const char* name) {
  if (PFcontextRec* ctx = g_current) ctx->setError(GL_INVALID_OPERATION);
  static std::mutex reported_mutex;
  static std::set<std::string> reported;
  std::lock_guard<std::mutex> lock(reported_mutex);
  try {
    if (name && reported.insert(name).second)
      std::fprintf(stderr, "primflow: %s is not implemented (GL_INVALID_OPERATION)\n", name);
  } catch (const std::bad_alloc&) {  // the line is a courtesy; the error is recorded
  }
}

PFcontextRec* contextOutsideBegin() {
  PFcontextRec* ctx = g_current;
  if (ctx && ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return nullptr;
  }
  return ctx;
}

void PrimitiveRegistry::addInterpolator(std::shared_ptr<const CompiledPrimitive> p) {
  auto known = interpolator_ids.find(p->name);
  if (known == interpolator_ids.end()) {
    // Ids stop below the primitive modes' range: past it, the table is full (GL_OUT_OF_MEMORY).
    if (interpolators.size() >= kMaxInterpolators) throw std::bad_alloc();
    interpolator_ids[p->name] = GL_FIRST_INTERPOLATOR_EXT + static_cast<GLuint>(interpolators.size());
    interpolators.push_back(std::move(p));
    return;
  }
  auto& slot = interpolators[known->second - GL_FIRST_INTERPOLATOR_EXT];
  replaced.push_back(slot);
  slot = std::move(p);
}

void PrimitiveRegistry::add(std::shared_ptr<const CompiledPrimitive> p, GLenum mode) {
  auto known = mode_of.find(p->name);
  // Modes stop below the parameter names' range: past it, the table is full (GL_OUT_OF_MEMORY).
  if (mode == kAnyMode && known == mode_of.end() && next_mode >= GL_FIRST_PARAM_NAME_EXT) throw std::bad_alloc();
  if (mode == kAnyMode) mode = known != mode_of.end() ? known->second : next_mode++;
  if (known != mode_of.end()) {
    replaced.push_back(by_name[p->name]);
    if (known->second != mode) by_mode.erase(known->second);
  }
  mode_of[p->name] = mode;
  by_mode[mode] = p;
  by_name[p->name] = std::move(p);
}

}  // namespace pf

extern "C" {

PFcontext pfCreateContextAttribs(const int* attribs) {
  GLenum format = GL_RGBA;
  int depth_bits = 0, stencil_bits = 0, accum_bits = 0;
  int threads = 0;
  int cap = 0;
  int native = -1;  // PF_JIT: -1 the environment's choice
  for (const int* a = attribs; a && a[0] != 0; a += 2) {
    switch (a[0]) {
      case PF_FORMAT: format = static_cast<GLenum>(a[1]); break;
      case PF_DEPTH_BITS: depth_bits = a[1]; break;
      case PF_STENCIL_BITS: stencil_bits = a[1]; break;
      case PF_ACCUM_BITS: accum_bits = a[1]; break;
      case PF_THREADS: threads = a[1]; break;
      case PF_ITERATION_CAP: cap = a[1]; break;
      case PF_JIT: native = a[1]; break;
      default: return nullptr;  // unknown attribute
    }
  }
  if (format != GL_RGBA || depth_bits < 0 || stencil_bits < 0 || accum_bits < 0 || threads < 0 || threads > 256 || cap < 0 || native < -1 || native > 1)
    return nullptr;
  if (threads == 0) threads = pf::defaultThreadCount();
  try {
    auto* ctx = new PFcontextRec(threads);
    ctx->format = format;
    // The names glVertex, glNormal, glTexCoord and glEdgeFlag set, with GL's initial values.
    ctx->vertex_param = ctx->paramId("vertex");
    ctx->normal_param = ctx->paramId("normal");
    ctx->texcoord_param = ctx->paramId("texcoord");
    ctx->color_param = ctx->paramId("color");
    ctx->edge_flag_param = ctx->paramId("edge_flag");
    ctx->param(ctx->normal_param) = pf::ParamValue{{0, 0, 1}, 3};
    ctx->param(ctx->texcoord_param) = pf::ParamValue{{0, 0, 0, 1}, 4};
    ctx->param(ctx->edge_flag_param) = pf::ParamValue{{1}, 1};
    ctx->depth_bits = depth_bits;
    ctx->stencil_bits = stencil_bits > 0 ? 8 : 0;
    ctx->accum_bits = accum_bits > 0 ? 16 : 0;
    if (native >= 0) ctx->renderer.setNativeCode(native == 1);
    ctx->iteration_cap = cap > 0 ? static_cast<unsigned>(cap) : pf::kDefaultIterationCap;
    if (!pf::registerBuiltins(*ctx)) {
      delete ctx;
      return nullptr;
    }
    return ctx;
  } catch (const std::bad_alloc&) {
    return nullptr;
  } catch (const std::system_error&) {  // a resource the system refuses (the pool itself copes with threads)
    return nullptr;
  }
}

PFcontext pfCreateContext(GLenum format, GLint depthBits) {
  const int attribs[] = {PF_FORMAT, static_cast<int>(format), PF_DEPTH_BITS, depthBits, 0};
  return pfCreateContextAttribs(attribs);
}

GLboolean pfMakeCurrent(PFcontext ctx, void* buffer, GLenum type, GLsizei width, GLsizei height) {
  if (!ctx) {
    if (pf::g_current) pf::g_current->flush();
    pf::g_current = nullptr;
    return GL_TRUE;
  }
  if (!buffer || type != GL_UNSIGNED_BYTE || width < 1 || height < 1 ||
      width > pf::kMaxFramebufferSize || height > pf::kMaxFramebufferSize)
    return GL_FALSE;
  ctx->flush();
  // The new depth buffer and bins first: if they cannot be allocated, the context keeps its
  // previous drawable, whole.
  std::vector<float> depth;
  std::vector<uint8_t> stencil;
  std::vector<int16_t> accum;
  try {
    if (ctx->depth_bits > 0) depth.assign(static_cast<size_t>(width) * height, 1.0f);
    if (ctx->stencil_bits > 0) stencil.assign(static_cast<size_t>(width) * height, 0);
    if (ctx->accum_bits > 0) accum.assign(static_cast<size_t>(width) * height * 4, 0);
    ctx->renderer.setTarget(static_cast<uint8_t*>(buffer), ctx->depth_bits > 0 ? depth.data() : nullptr, width, height,
                            ctx->stencil_bits > 0 ? stencil.data() : nullptr);
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    std::fprintf(stderr, "primflow: pfMakeCurrent: out of memory for a %dx%d drawable: the context keeps its previous one\n",
                 static_cast<int>(width), static_cast<int>(height));
    return GL_FALSE;
  }
  ctx->depth.swap(depth);  // the storage moves with the swap: the renderer's pointer stays valid
  ctx->stencil.swap(stencil);
  ctx->accum.swap(accum);
  ctx->color = static_cast<uint8_t*>(buffer);
  ctx->width = width;
  ctx->height = height;
  if (!ctx->ever_bound) {
    // As in GL, the viewport starts as the whole first drawable.
    ctx->viewport[0] = 0;
    ctx->viewport[1] = 0;
    ctx->viewport[2] = width;
    ctx->viewport[3] = height;
    ctx->fragment.scissor[2] = width;  // and so does the scissor box
    ctx->fragment.scissor[3] = height;
    ctx->ever_bound = true;
  }
  pf::g_current = ctx;
  return GL_TRUE;
}

PFcontext pfGetCurrentContext(void) { return pf::g_current; }

GLboolean pfGetDepthBuffer(PFcontext ctx, GLint* width, GLint* height, GLint* bytesPerValue, void** buffer) {
  if (!ctx || ctx->depth_bits <= 0 || !ctx->color) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (bytesPerValue) *bytesPerValue = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  ctx->finish();
  if (width) *width = ctx->width;
  if (height) *height = ctx->height;
  if (bytesPerValue) *bytesPerValue = static_cast<GLint>(sizeof(float));
  if (buffer) *buffer = ctx->depth.data();
  return GL_TRUE;
}

GLboolean pfGetColorBuffer(PFcontext ctx, GLint* width, GLint* height, GLint* format, void** buffer) {
  if (!ctx || !ctx->color) {
    if (width) *width = 0;
    if (height) *height = 0;
    if (format) *format = 0;
    if (buffer) *buffer = nullptr;
    return GL_FALSE;
  }
  ctx->finish();
  if (width) *width = ctx->width;
  if (height) *height = ctx->height;
  if (format) *format = GL_RGBA;
  if (buffer) *buffer = ctx->color;
  return GL_TRUE;
}

GLint pfGetThreadCount(PFcontext ctx) { return ctx ? ctx->renderer.threadCount() : 0; }

void pfDestroyContext(PFcontext ctx) {
  if (!ctx) return;
  if (pf::g_current == ctx) pf::g_current = nullptr;
  delete ctx;
}

}  // extern "C"
