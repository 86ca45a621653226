// Lowering: a type-checked primitive (sema.h) -> structured IR (ir.h).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "compiler/ast.h"
#include "compiler/ir.h"

namespace pf {

struct CompiledPrimitive;
using PrimitiveTable = std::map<std::string, std::shared_ptr<const CompiledPrimitive>>;

// Returns false (with errors logged) if the unit uses something lowering cannot express.
// `functions` are the program's functions by name: calls to them are inlined. `primitives`
// are the primitives it may call (each call becomes an instance of the callee, at run time).
bool lowerPrimitive(const Unit& unit, const std::map<std::string, const Unit*>& functions,
                    const PrimitiveTable& primitives, IrFunction& out, DiagnosticLog& log);

// Lowers a field unit: its value is the operand of the one ShadeOut at the end of the body,
// its point the FieldPoint values, its other parameters the parameter block's slots.
bool lowerField(const Unit& unit, const std::map<std::string, const Unit*>& functions, IrFunction& out,
                DiagnosticLog& log);

}  // namespace pf
