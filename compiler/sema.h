// Semantic analysis: resolves names, types every expression, and infers which values are
// uniform (the same for every pixel of an instance) and which are varying (differ per pixel).
// A variable declared `uniform` that receives a varying value is an error whose message walks
// the chain back to the cause: X, Y, Z, ztest(), or a varying variable.
#pragma once

#include <map>
#include <string>

#include "compiler/ast.h"

namespace pf {

// Analyses every unit of the program in place (Expr::type, Expr::varying). Returns false if
// any error was logged. `callable`: primitives compiled before, which its primitives may call.
bool analyze(Program& program, DiagnosticLog& log,
             const std::map<std::string, PrimitiveSignature>& callable = {});
PrimitiveSignature signatureOf(const Unit& u);

}  // namespace pf
