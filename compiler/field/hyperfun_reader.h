// The HyperFun front end: compiles a HyperFun model (.hf) into a FieldTape.
//
// HyperFun (hyperfun.org; its C interpreter is the reference, see shared/hyperfun.md) describes
// a solid as f(x) >= 0 -- primflow's own convention, so the value is not negated. The model is
// compiled symbolically: variables and array items hold either numbers known at compile time or
// values on the tape, indexes must be known at compile time, `if` and `while` are decided at
// compile time (loops unrolled), object calls are inlined, and the hf* library becomes tape
// instructions (hyperfun_library.h). What is supported and what is rejected, with the messages:
// docs/hyperfun.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostics.h"
#include "compiler/field/field_tape.h"

namespace pf::field {

// The tape of the object `object` in `text` (case-insensitive; HyperFun's `hfp -o`), or of the
// first object when the file has none of that name. params are the values of a[1], a[2], ...
// (`hfp -a`); the items of a[] not given are 0, and more values than a[] holds is an error.
// `time` is x[4], HyperFun's time coordinate (further coordinates are 0), known when the model
// compiles: an animation is a model compiled once per frame.
// Errors (file:line:col, source line, caret) go to `log`, named `name`; nullopt then.
// `attributes`, when given, receives the model's attributes (seed 000's procedural colour): one
// tape per item of the drawn object's s array, its value when the model has run -- s[1], s[2],
// s[3] are the colour's red, green and blue -- or nothing when its header declares no s.
std::optional<FieldTape> readHyperFunModel(const std::string& name, std::string text, DiagnosticLog& log,
                                           const std::vector<double>& params = {},
                                           const std::string& object = "my_model", double time = 0.0,
                                           std::vector<FieldTape>* attributes = nullptr);

}  // namespace pf::field
