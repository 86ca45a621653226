// The Fidget front end: reads Fidget's SSA text format (.vm) into a FieldTape.
//
// Format (mkeeter/fidget, models/*.vm): one operation per line, `NAME OP ARGS...`, `#` starts a
// comment, blank lines are ignored; ARGS name earlier values, except `const` whose argument is a
// number. The last line's value is the model. Fidget's sign convention is negative inside; the
// tape is negated at the end so that it follows primflow's (HyperFun's) f >= 0 inside.
#pragma once

#include <optional>
#include <string>

#include "compiler/diagnostics.h"
#include "compiler/field/field_tape.h"

namespace pf::field {

// The model's tape, or nullopt with errors (file:line:col, source line, caret) in `log`.
std::optional<FieldTape> readFidgetModel(const std::string& name, std::string text, DiagnosticLog& log);

}  // namespace pf::field
