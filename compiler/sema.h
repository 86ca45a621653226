// Semantic analysis: resolves names, types every expression, and infers which values are
// uniform (the same for every pixel of an instance) and which are varying (differ per pixel).
// A variable declared `uniform` that receives a varying value is an error whose message walks
// the chain back to the cause: X, Y, Z, ztest(), or a varying variable.
#pragma once

#include <map>
#include <set>
#include <string>

#include "compiler/ast.h"

namespace pf {

// Analyses every unit of the program in place (Expr::type, Expr::varying). Returns false if
// any error was logged. `callable`: primitives compiled before, which its primitives may call;
// `interpolators`: the shared interpolators compiled before, which an interpolation label may
// name (besides those the program defines before the label).
bool analyze(Program& program, DiagnosticLog& log,
             const std::map<std::string, PrimitiveSignature>& callable = {},
             const std::set<std::string>& interpolators = {});
PrimitiveSignature signatureOf(const Unit& u);

}  // namespace pf
