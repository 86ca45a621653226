// Lowering: a type-checked primitive (sema.h) -> structured IR (ir.h).
#pragma once

#include "compiler/ast.h"
#include "compiler/ir.h"

namespace pf {

// Returns false (with errors logged) if the unit uses something lowering cannot express.
bool lowerPrimitive(const Unit& unit, IrFunction& out, DiagnosticLog& log);

}  // namespace pf
