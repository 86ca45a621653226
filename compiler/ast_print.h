// A readable dump of the AST (pfc --emit=ast).
#pragma once

#include <string>

#include "compiler/ast.h"

namespace pf {
std::string printAst(const Program& p);
}
