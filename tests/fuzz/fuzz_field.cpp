// libFuzzer target for the field front ends and evaluators: the first byte picks the format
// (modulo 3: Fidget .vm, HyperFun .hf, a language field unit -- '0', '1', '2' in the corpus), the
// rest is the model's text. A model that compiles is
// evaluated as floats, intervals (with tape simplification), gradients and ray polynomials at a
// few points and boxes, and one 8x8 block of rays is cast by every method. Nothing may crash,
// hang, or trip ASan/UBSan: a bad model is a diagnostic with file:line:col.
// The same bytes also choose a generated field (adversarial.h: NaN, infinite, very long) and a
// way to draw it through the API -- method, steps from 0 to 10^4 and NaN, an iteration cap from
// 1 -- into a small context, glFinish included (where rays stopped at the cap once crashed it).
//
// Build and run locally: as fuzz_compile.cpp says, with --target fuzz_field and the corpus
// tests/fuzz/corpus/field.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <primflow/gl.h>

#include <cmath>
#include <limits>

#include "adversarial.h"
#include "compiler/field/field_source.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/interval_evaluator.h"
#include "raster/field/ray_caster.h"
#include "raster/field/ray_polynomial.h"

namespace {

// Draws `source` through the API as drawModel does (tools/model): one instance of `implicit`
// over the box [-1, 1]^3, seen from +z, in a 16x16 context with the iteration cap `cap`.
void drawThroughTheApi(int format, const std::string& source, int method, float steps, int cap) {
  const int attribs[] = {PF_FORMAT, GL_RGBA, PF_DEPTH_BITS, 24, PF_ITERATION_CAP, cap, PF_THREADS, 1, 0};
  PFcontext ctx = pfCreateContextAttribs(attribs);
  if (!ctx) return;
  std::vector<unsigned char> px(16 * 16 * 4);
  if (pfMakeCurrent(ctx, px.data(), GL_UNSIGNED_BYTE, 16, 16)) {
    const GLenum formats[] = {GL_FIELD_FIDGET_EXT, GL_FIELD_HYPERFUN_EXT, GL_FIELD_LANGUAGE_EXT};
    const GLuint field = pfglCompileFieldEXT(formats[format], "fuzz", source.c_str(), 0.0f);
    if (field != 0) {
      pfglEnable(GL_DEPTH_TEST);
      pfglMatrixMode(GL_PROJECTION);
      pfglLoadIdentity();
      pfglFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
      pfglMatrixMode(GL_MODELVIEW);
      pfglLoadIdentity();
      pfglTranslatef(0.0f, 0.0f, -4.0f);
      pfglBegin(pfglGetPrimitiveEXT("implicit"));
      pfglRastParamfEXT(pfglGetParamNameEXT("field"), static_cast<GLfloat>(field));
      pfglRastParam3fEXT(pfglGetParamNameEXT("box_min"), -1, -1, -1);
      pfglRastParam3fEXT(pfglGetParamNameEXT("box_max"), 1, 1, 1);
      pfglRastParamfEXT(pfglGetParamNameEXT("method"), static_cast<GLfloat>(method));
      pfglRastParamfEXT(pfglGetParamNameEXT("steps"), steps);
      pfglSequencePointEXT();
      pfglEnd();
      pfglFinish();
    }
    (void)pfglGetError();
    pfMakeCurrent(nullptr, nullptr, 0, 0, 0);
  }
  pfDestroyContext(ctx);
}

void generatedFieldDrawn(pf::fuzz::Choices& in) {
  int format = 0;
  const std::string source = pf::fuzz::fieldSource(in, format);
  const int method = in.ConsumeIntegralInRange<int>(-1, pf::field::kRootMethodCount);
  static const float kSteps[] = {0.0f, 1.0f, 16.0f, 10000.0f, std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::infinity(), -5.0f, 1e30f};
  const float steps = kSteps[in.ConsumeIntegralInRange<size_t>(0, 7)];
  // 0: the default cap (65536). A long tape gets a small one: 256 rays of 65536 steps of 15,000
  // operations would be work the input asked for, not a hang, but past the fuzzer's timeout.
  const int cap = in.ConsumeBool() || source.size() > 2000 ? in.ConsumeIntegralInRange<int>(1, 64) : 0;
  drawThroughTheApi(format, source, method, steps, cap);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  {
    pf::fuzz::Choices in(data, size);
    pf::fuzz::onSmallStack([&] { generatedFieldDrawn(in); });
  }
  if (size < 1 || size > 4 * 1024) return 0;
  using pf::field::FieldFormat;
  std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  // Text starting as a sampled field's file is one (the .pfgrid reader, its data checks, the grid).
  const FieldFormat format = text.rfind("pfgrid", 0) == 0 ? FieldFormat::Sampled
                             : data[0] % 3 == 0         ? FieldFormat::Fidget
                             : data[0] % 3 == 1         ? FieldFormat::HyperFun
                                                        : FieldFormat::Language;
  pf::DiagnosticLog log;
  std::optional<pf::field::FieldTape> tape = pf::field::compileFieldSource(format, "fuzz", text, {}, 0.0, log);
  if (!tape) {
    (void)log.format();
    return 0;
  }
  if (tape->size() > 4000) return 0;  // unrolled loops: compile-time limits are the readers' own test
  using namespace pf::field;
  FloatEvaluator fe(*tape);
  IntervalEvaluator ie(*tape);
  GradientEvaluator ge(*tape);
  const float points[][3] = {{0, 0, 0}, {0.5f, -0.25f, 1}, {-3, 2, 7}, {1e-30f, -1e30f, 0}};
  for (const auto& p : points) {
    (void)fe.evaluate(p[0], p[1], p[2]);
    (void)ge.evaluate(p[0], p[1], p[2]);
    (void)rayPolynomial(*tape, {p[0], p[1], p[2]}, {0.3, -0.2, 1.0});
  }
  std::vector<Choice> choices;
  for (float w : {0.01f, 1.0f, 100.0f}) {
    (void)ie.evaluate({-w, w}, {-w, 0.5f * w}, {0.0f, w}, &choices);
    FloatEvaluator simplified(simplify(*tape, choices));
    (void)simplified.evaluate(0.0f, 0.0f, 0.5f * w);
  }
  if (tape->size() > 500) return 0;  // casting 64 rays by five methods: kept to small tapes
  const ImplicitField field("fuzz", *tape, 2.0f);
  FieldRays rays;
  rays.window_to_object = {0.25, 0, 0, 0, 0, 0.25, 0, 0, 0, 0, -2, 0, -1, -1, 1, 1};  // 8x8 pixels over [-1, 1]^2
  rays.box_min = {-1, -1, -1};
  rays.box_max = {1, 1, 1};
  for (int m = 0; m < kRootMethodCount; ++m) {
    CastRequest req;
    req.field = &field;
    req.rays = rays;
    req.method = static_cast<RootMethod>(m);
    req.param = m == static_cast<int>(RootMethod::March) ? 16.0f : 0.0f;
    req.iteration_cap = 256;
    FieldRayCaster caster;
    FieldCounters counters;
    float t[64];
    caster.castBlock(req, 0, 0, ~uint64_t(0), t, counters);
  }
  return 0;
}
