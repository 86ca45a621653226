// Code generation: IR -> the two programs of a primitive (the setup / per-pixel split).
//   setup: every uniform value that something needs, and the effects of the whole instance
//          (bound, kill); varying control flow is flattened (its uniform values are pure).
//   pixel: every varying value and per-pixel effect, with uniform control flow as jumps on
//          values exported by setup, and varying control flow as execution masks. A loop that
//          holds per-pixel work runs in the pixel program, and the uniform values that change
//          from one of its iterations to the next are computed there too.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compiler/ir.h"

namespace pf {

struct CodegenResult {
  SetupProgram setup;
  PixelProgram pixel;
  // What the two programs cannot express (a parameter-sized array read per pixel).
  std::vector<std::pair<SourceLoc, std::string>> errors;
};

CodegenResult generateCode(const IrFunction& f);

}  // namespace pf
