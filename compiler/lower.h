// Lowering: a type-checked primitive (sema.h) -> structured IR (ir.h).
#pragma once

#include <map>
#include <string>

#include "compiler/ast.h"
#include "compiler/ir.h"

namespace pf {

// Returns false (with errors logged) if the unit uses something lowering cannot express.
// `functions` are the program's functions by name: calls to them are inlined.
bool lowerPrimitive(const Unit& unit, const std::map<std::string, const Unit*>& functions,
                    IrFunction& out, DiagnosticLog& log);

}  // namespace pf
