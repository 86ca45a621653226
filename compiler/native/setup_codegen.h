// Setup programs to LLVM IR: one function per program and variant (native_abi.h) that runs a
// batch of kNativeSetupLanes instances the way raster/setup_batch.cpp's interpreter does, one
// instance per lane of a vector, every register a vector variable that LLVM keeps in vector
// registers. It runs while the batch's lanes take one path; where they part at a conditional
// jump, or at an instruction it does not run (the calls of other primitives: OutParam,
// OutVertex, Emit), it writes the registers back and returns, and the interpreter goes on from
// that instruction -- so the split, the scalar resumption and what follows are the
// interpreter's, unchanged. Every lane computes what the interpreter computes for it (the same
// operations in the same order, lane_ops.h): records are bit-identical.
#pragma once

#include <string>

#include "compiler/isa.h"
#include "compiler/native/native_abi.h"

namespace llvm {
class Function;
class Module;
}  // namespace llvm

namespace pf {

// Adds to `module` the function `name` (a NativeSetupFunction) running `program` under
// `variant`, and returns it; null with `error` set when it cannot.
llvm::Function* buildSetupFunction(llvm::Module& module, const std::string& name, const SetupProgram& program,
                                   const NativeSetupVariant& variant, std::string& error);

}  // namespace pf
