// The extension's fields for implicit surfaces: compile a field from a model's source into the
// context's field table (its id is what the `implicit` primitive's `field` parameter names),
// and read the diagnostics. See docs/api.md, "Fields".
#include <cmath>
#include <new>

#include <primflow/gl.h>

#include "api/src/context_state.h"
#include "compiler/field/field_source.h"
#include "compiler/field/sampled_reader.h"

using pf::currentContext;

namespace {

// Adds a compiled field to the context's table: its id, or 0 with GL_OUT_OF_MEMORY. Both lists
// grow together (an id names its field and its log) or neither does.
GLuint addField(PFcontextRec& ctx, const char* name, pf::field::FieldTape tape, float lipschitz,
                std::vector<pf::field::FieldTape> attributes, std::string field_log) {
  try {
    ctx.field_logs.reserve(ctx.field_logs.size() + 1);
    ctx.fields.reserve(ctx.fields.size() + 1);
    auto field = std::make_unique<const pf::field::ImplicitField>(name, std::move(tape), lipschitz, std::move(attributes));
    ctx.fields.push_back(std::move(field));
    ctx.field_logs.push_back(std::move(field_log));
  } catch (const std::bad_alloc&) {
    ctx.setError(GL_OUT_OF_MEMORY);
    return 0;
  }
  return static_cast<GLuint>(ctx.fields.size());
}

}  // namespace

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
  return addField(*ctx, name, std::move(*tape), lipschitz, std::move(attributes), log.format());
}

GLuint pfglSampledFieldEXT(const GLchar* name, GLsizei nx, GLsizei ny, GLsizei nz, const GLdouble* box,
                           GLenum interpolation, const GLfloat* samples) {
  PFcontextRec* ctx = currentContext();
  if (!ctx) return 0;
  if (ctx->in_begin) {
    ctx->setError(GL_INVALID_OPERATION);
    return 0;
  }
  if (interpolation != GL_FIELD_TRILINEAR_EXT && interpolation != GL_FIELD_TRICUBIC_EXT) {
    ctx->setError(GL_INVALID_ENUM);
    return 0;
  }
  const double no_box[6] = {0, 0, 0, 0, 0, 0};
  const double* b = box ? box : no_box;
  const double lo[3] = {b[0], b[1], b[2]}, hi[3] = {b[3], b[4], b[5]};
  bool too_large = false;
  const std::string wrong = pf::field::SampledGrid::checkGrid(nx, ny, nz, lo, hi, samples, &too_large);
  if (!name || !box || !wrong.empty()) {
    // (Too many samples is the one complaint that is about memory: GL_OUT_OF_MEMORY, as a
    // glTexImage3D larger than the implementation holds.)
    ctx->setError(too_large && name && box ? GL_OUT_OF_MEMORY : GL_INVALID_VALUE);
    ctx->field_failed_log = std::string(name ? name : "(null)") + ": error: " +
                            (wrong.empty() ? std::string("a sampled field needs a name and a box") : wrong);
    return 0;
  }
  const auto interp = interpolation == GL_FIELD_TRILINEAR_EXT ? pf::field::SampleInterpolation::Trilinear
                                                              : pf::field::SampleInterpolation::CubicBSpline;
  try {
    const size_t count = static_cast<size_t>(nx) * static_cast<size_t>(ny) * static_cast<size_t>(nz);
    auto grid = std::make_shared<const pf::field::SampledGrid>(nx, ny, nz, lo, hi, interp,
                                                                std::vector<float>(samples, samples + count));
    // The grid's own bound on |grad f|: `auto` sphere-traces it (none if it is past float's range).
    float lipschitz = static_cast<float>(grid->lipschitz() * (1.0 + 1e-6));
    if (!std::isfinite(lipschitz)) lipschitz = 0.0f;
    return addField(*ctx, name, pf::field::sampledFieldTape(std::move(grid)), lipschitz, {}, "");
  } catch (const std::bad_alloc&) {
    ctx->setError(GL_OUT_OF_MEMORY);
    ctx->field_failed_log = std::string(name) + ": error: out of memory for the sampled field";
    return 0;
  }
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
