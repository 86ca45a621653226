// Field units of the primitive language -> field tapes.
//
// `field float name(point p, float a, ...) { ... }` (docs/language.md, "Fields") is compiled by
// the language's own front end, lowering and passes, and its optimized IR is then run
// symbolically: everything that depends only on constants and the field's parameters is
// computed at compile time (so `if`, loops and function calls are unrolled), and what depends
// on the point p becomes instructions of a FieldTape -- the form every implicit-surface
// evaluator runs (raster/field/). That is how the interval, gradient and ray-polynomial forms
// of the issue are derived from a field: they are the tape's evaluators.
//
// A field's point-dependent part may use only what a tape can evaluate soundly: + - * /, min,
// max, abs, sqrt, exp, log, sin, cos, atan, and what is built from them: tan (sin / cos), asin,
// acos and atan2 (through atan), pow (constant integer exponents as products; otherwise
// exp(y log x)). Comparisons, && || !, sign and step of point-dependent values are tape values;
// an `if` or ?: on one runs both branches and joins them with the tape's Select (a float or
// bool chosen per point), and break/continue/return taken at some points only are masked as in
// the pixel programs. A loop whose count depends on the point, a point-dependent int, and
// floor/ceil/mod/noise of a point-dependent value are compile errors that name the line (an
// unsupported value is an error only where it is used).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/field/field_tape.h"

namespace pf::field {

// How far a field's compile-time loops may unroll (its tape's length: kMaxFieldTapeSize).
constexpr long kMaxFieldLoopIterations = 1'000'000;

// Compiles field `name` of language source `text` (named `filename` in diagnostics) to a tape;
// a source with one field compiles that one whatever `name` says (an empty name included). `params` give the values of the field's
// parameters after its point, in order. nullopt with errors (file:line:col, caret) in `log`.
std::optional<FieldTape> compileFieldUnit(const std::string& filename, const std::string& text,
                                          const std::string& name, const std::vector<float>& params,
                                          DiagnosticLog& log);

}  // namespace pf::field
