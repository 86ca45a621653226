// Recursive-descent parser: tokens -> AST (compiler/ast.h). Grammar in docs/language.md.
#pragma once

#include "compiler/ast.h"
#include "compiler/lexer.h"

namespace pf {

// Parses a whole source file. Errors go to the log; the parser resynchronises at statement
// boundaries so that one mistake does not hide the next. Never throws to the caller.
Program parse(const SourceFile& file, DiagnosticLog& log);

}  // namespace pf
