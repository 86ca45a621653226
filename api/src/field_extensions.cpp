// The extension's fields for implicit surfaces: compile a field from a model's source into the
// context's field table (its id is what the `implicit` primitive's `field` parameter names),
// and read the diagnostics. See docs/api.md, "Fields".
#include <cmath>
#include <new>

#include <primflow/gl.h>

#include "api/src/context_state.h"
#include "compiler/field/field_source.h"

using pf::currentContext;

extern "C" {

GLuint pfglCompileFieldParamsEXT(GLenum format, const GLchar* name, const GLchar* source, GLfloat lipschitz,
                                 GLdouble time, GLsizei count, const GLdouble* params) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  if (ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return 0;
  }
  if (format != GL_FIELD_FIDGET_EXT && format != GL_FIELD_HYPERFUN_EXT && format != GL_FIELD_LANGUAGE_EXT) {
    ctx->setError(GL_INVALID_ENUM);
    return 0;
  }
  if (!source || !name || !(lipschitz >= 0.0f) || !std::isfinite(lipschitz) || !std::isfinite(time) || count < 0 ||
      (count > 0 && !params) || (format == GL_FIELD_FIDGET_EXT && (time != 0.0 || count != 0)) ||
      (format == GL_FIELD_LANGUAGE_EXT && time != 0.0)) {
    ctx->setError(GL_INVALID_VALUE);
    return 0;
  }
  pf::DiagnosticLog log;
  using pf::field::FieldFormat;
  const FieldFormat f = format == GL_FIELD_FIDGET_EXT     ? FieldFormat::Fidget
                        : format == GL_FIELD_HYPERFUN_EXT ? FieldFormat::HyperFun
                                                          : FieldFormat::Language;
  std::optional<pf::field::FieldTape> tape;
  std::vector<pf::field::FieldTape> attributes;
  try {
    tape = pf::field::compileFieldSource(f, name, source, std::vector<double>(params, params + count), time, log, "",
                                         &attributes);
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    ctx->field_failed_log = std::string(name) + ": error: out of memory while compiling";
    return 0;
  }
  if (!tape) {
    ctx->field_failed_log = log.format();
    return 0;
  }
  try {
    // Both lists grow together (an id names its field and its log) or neither does.
    ctx->field_logs.reserve(ctx->field_logs.size() + 1);
    ctx->fields.reserve(ctx->fields.size() + 1);
    auto field = std::make_unique<const pf::field::ImplicitField>(name, std::move(*tape), lipschitz,
                                                                  std::move(attributes));
    std::string field_log = log.format();
    ctx->fields.push_back(std::move(field));
    ctx->field_logs.push_back(std::move(field_log));
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    return 0;
  }
  return static_cast<GLuint>(ctx->fields.size());
}

GLuint pfglCompileFieldEXT(GLenum format, const GLchar* name, const GLchar* source, GLfloat lipschitz) {
  return pfglCompileFieldParamsEXT(format, name, source, lipschitz, 0.0, 0, nullptr);
}

void pfglGetFieldLogEXT(GLuint field, GLsizei bufSize, GLsizei* length, GLchar* out) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return;
  const std::string* text = nullptr;
  if (field == 0) text = &ctx->field_failed_log;
  else if (field <= ctx->field_logs.size()) text = &ctx->field_logs[field - 1];
  pf::copyInfoLog(*ctx, text, bufSize, length, out);
}

GLuint pfglGetFieldEXT(const GLchar* name) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  for (size_t i = name ? ctx->fields.size() : 0; i-- > 0;)
    if (ctx->fields[i]->name == name) return static_cast<GLuint>(i + 1);
  ctx->setError(GL_INVALID_VALUE);
  return 0;
}

}  // extern "C"
