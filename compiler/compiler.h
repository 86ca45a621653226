// The compiler's entry point: source text -> compiled primitives, ready to register in a
// context. Built-in primitives (primitives/*.pfl) and a user's primitives go through here alike.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "compiler/ast.h"
#include "compiler/codegen.h"
#include "compiler/diagnostics.h"
#include "compiler/ir.h"

namespace pf {

struct CompiledPrimitive {
  std::string name;
  // Its parameters as declared, X, Y and Z left out: what a call from another primitive passes.
  PrimitiveSignature signature;
  std::vector<ParamInfo> params;
  int param_floats = 0;     // the fixed part of the parameter block
  int sequence_points = 1;  // per instance; 0: any number (parameter-sized arrays)
  int count_slot = -1;      // sequence_points == 0: the slot that receives the count
  int sized_floats = 0;     // sequence_points == 0: floats per sequence point after the fixed part
  bool has_interp_data = false;
  bool is_interpolator = false;  // a shared interpolator, not a primitive
  // The primitives it calls (Op::Emit's imm), kept alive with it; how deep its calls nest.
  std::vector<std::shared_ptr<const CompiledPrimitive>> callees;
  int call_depth = 0;
  InterpKindSet kinds_handled = 0;
  // The shared interpolators it computes itself (its `name:` interpolation labels; Op::HasNamed
  // and Op::InterpNamedReturn index this): channels bound to one of them are filled by the
  // primitive's branch, not by the interpolator's program.
  std::vector<std::string> named_interpolators;
  bool computesInterpolator(const std::string& interpolator) const {
    for (const std::string& n : named_interpolators)
      if (n == interpolator) return true;
    return false;
  }
  bool writes_normal = false;  // sets N, or calls a primitive that does: pixels carry P and N to shading
  SetupProgram setup;
  PixelProgram pixel;
  // The optimized IR both programs came from: what the tests' scalar reference interpreter
  // runs, pixel by pixel, to check the split, the masks and the SIMD executor against.
  std::shared_ptr<const IrFunction> ir;

  // Size of the parameter block of an instance with `count` sequence points, and where
  // element `i` of parameter p starts in it.
  int paramFloats(int count) const { return param_floats + (sequence_points == 0 ? count * sized_floats : 0); }
  int paramOffset(const ParamInfo& p, int count, int i) const {
    return p.parameter_sized ? param_floats + count * p.offset + i * p.components : p.offset + i * p.components;
  }

  const ParamInfo* findParam(const std::string& n) const {
    for (const ParamInfo& p : params)
      if (p.name == n) return &p;
    return nullptr;
  }
};

using PrimitiveTable = std::map<std::string, std::shared_ptr<const CompiledPrimitive>>;

struct CompiledModule {
  std::vector<std::shared_ptr<const CompiledPrimitive>> primitives;
  // Shared interpolators (paper section 3.4): programs like a primitive's, whose pixel program
  // reads P and ends in Op::ShadeOut; bound to shading parameters with pfglMaterialInterpEXT.
  std::vector<std::shared_ptr<const CompiledPrimitive>> interpolators;
};

// What pfc --emit can print.
enum class EmitStage { None, Ast, Ir, Setup, Pixel, Explain };

// Compiles `text` (named `filename` in diagnostics). On failure returns false; the log holds
// every error. `listing`, when not null, receives the requested stage for each primitive.
// `optimize` = false skips the passes of passes.h (pfc -O0), for comparison and debugging.
// `callable`: primitives compiled before (the context's) that this source's primitives may
// call, besides the ones it defines itself.
// The front end that primitives and fields share: parses `text`, adds the standard library's
// functions and analyzes the program (types, uniform / varying). `callable`: the signatures of
// primitives compiled before that the source may call; `interpolators`: the names of shared
// interpolators compiled before, which interpolation labels may name. `listing` receives the
// AST for EmitStage::Ast.
bool analyzeSource(const std::string& filename, const std::string& text, DiagnosticLog& log, Program& program,
                   const std::map<std::string, PrimitiveSignature>& callable, EmitStage emit = EmitStage::None,
                   std::string* listing = nullptr, const std::set<std::string>& interpolators = {});

// `interpolators`: as analyzeSource's (null: none).
bool compileSource(const std::string& filename, const std::string& text, CompiledModule& out,
                   DiagnosticLog& log, EmitStage emit = EmitStage::None,
                   std::string* listing = nullptr, bool optimize = true,
                   const PrimitiveTable* callable = nullptr, const std::set<std::string>* interpolators = nullptr);

}  // namespace pf
