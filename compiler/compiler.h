// The compiler's entry point: source text -> compiled primitives, ready to register in a
// context. Built-in primitives (primitives/*.pfl) and a user's primitives go through here alike.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/codegen.h"
#include "compiler/diagnostics.h"
#include "compiler/ir.h"

namespace pf {

struct CompiledPrimitive {
  std::string name;
  std::vector<ParamInfo> params;
  int param_floats = 0;
  int sequence_points = 1;
  bool has_interp_data = false;
  InterpKindSet kinds_handled = 0;
  SetupProgram setup;
  PixelProgram pixel;
  // The optimized IR both programs came from: what the tests' scalar reference interpreter
  // runs, pixel by pixel, to check the split, the masks and the SIMD executor against.
  std::shared_ptr<const IrFunction> ir;

  const ParamInfo* findParam(const std::string& n) const {
    for (const ParamInfo& p : params)
      if (p.name == n) return &p;
    return nullptr;
  }
};

struct CompiledModule {
  std::vector<std::shared_ptr<const CompiledPrimitive>> primitives;
  std::vector<std::string> interpolators;  // checked; bound to parameters by a later version
};

// What pfc --emit can print.
enum class EmitStage { None, Ast, Ir, Setup, Pixel, Explain };

// Compiles `text` (named `filename` in diagnostics). On failure returns false; the log holds
// every error. `listing`, when not null, receives the requested stage for each primitive.
// `optimize` = false skips the passes of passes.h (pfc -O0), for comparison and debugging.
bool compileSource(const std::string& filename, const std::string& text, CompiledModule& out,
                   DiagnosticLog& log, EmitStage emit = EmitStage::None,
                   std::string* listing = nullptr, bool optimize = true);

}  // namespace pf
