// The PixelFlow extensions for primitives compiled at run time (paper section 4: every
// primitive, built-in or not, registers itself the same way): compile, read the log, look up
// the glBegin mode of a primitive by name.
#include <algorithm>
#include <cstring>
#include <new>
#include <set>

#include <primflow/gl.h>

#include "api/src/context_state.h"

using pf::currentContext;

namespace pf {

void copyInfoLog(PFcontextRec& ctx, const std::string* text, GLsizei bufSize, GLsizei* length, GLchar* out) {
  if (!text || bufSize < 0) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  GLsizei n = 0;
  if (out && bufSize > 0) {
    n = static_cast<GLsizei>(std::min<size_t>(text->size(), static_cast<size_t>(bufSize - 1)));
    std::memcpy(out, text->data(), static_cast<size_t>(n));
    out[n] = '\0';
  }
  if (length) *length = n;
}

}  // namespace pf

extern "C" {

GLuint pfglCompilePrimitivesEXT(const GLchar* source) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  if (ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return 0;
  }
  if (!source) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  pf::CompiledModule module;
  pf::DiagnosticLog log;
  std::string name = "module" + std::to_string(ctx->primitives.module_logs.size() + 1) + ".pfl";
  std::set<std::string> interpolators;  // the context's, for interpolation labels
  for (const auto& [known, id] : ctx->primitives.interpolator_ids) interpolators.insert(known);
  try {
    if (!pf::compileSource(name, source, module, log, pf::EmitStage::None, nullptr, true, &ctx->primitives.by_name,
                           &interpolators)) {
      ctx->primitives.failed_log = log.format();
      return 0;
    }
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    ctx->primitives.failed_log = name + ": error: out of memory while compiling";
    return 0;
  }
  // Instances already recorded keep the programs they were submitted with (the registry keeps
  // replaced programs alive), so replacing a primitive never changes pending drawing.
  try {
    for (auto& p : module.primitives) ctx->primitives.add(p);
    for (auto& p : module.interpolators) ctx->primitives.addInterpolator(p);
    ctx->primitives.module_logs.push_back(log.format());
  } catch (const std::bad_alloc&) {  // (primitives registered before it stay usable)
    ctx->setError(GL_OUT_OF_MEMORY);
    ctx->primitives.failed_log = name + ": error: out of memory registering its units, or the context's table of "
                                        "primitive modes (26,624) or shared interpolators (1,024) is full";
    return 0;
  }
  return static_cast<GLuint>(ctx->primitives.module_logs.size());
}

void pfglGetCompileLogEXT(GLuint module, GLsizei bufSize, GLsizei* length, GLchar* out) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return;
  const std::string* text = nullptr;
  if (module == 0) text = &ctx->primitives.failed_log;
  else if (module <= ctx->primitives.module_logs.size()) text = &ctx->primitives.module_logs[module - 1];
  pf::copyInfoLog(*ctx, text, bufSize, length, out);
}

GLenum pfglGetInterpolatorEXT(const GLchar* name) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  auto it = name ? ctx->primitives.interpolator_ids.find(name) : ctx->primitives.interpolator_ids.end();
  if (it == ctx->primitives.interpolator_ids.end()) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  return it->second;
}

GLenum pfglGetPrimitiveEXT(const GLchar* name) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  auto it = name ? ctx->primitives.mode_of.find(name) : ctx->primitives.mode_of.end();
  if (it == ctx->primitives.mode_of.end()) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  return it->second;
}

}  // extern "C"
