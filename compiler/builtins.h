// The built-in functions of the language: their argument rules and result types.
// (Their meaning is in lower_expressions.cpp, whose call() expands each call into instructions.)
#pragma once

#include <functional>
#include <string>

#include "compiler/ast.h"

namespace pf {

// Types a call to a built-in function whose arguments are already typed: sets e.type (Void on
// error) and e.varying. Reports through `err`; an unknown name is an error.
void typeBuiltinCall(Expr& e, UnitKind unit, const std::function<void(SourceLoc, const std::string&)>& err);

// For the componentwise maths built-ins (sin, mix, clamp, ...): their argument count; else 0.
int componentwiseArity(const std::string& name);

}  // namespace pf
