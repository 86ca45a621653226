// Pixel programs to LLVM IR: one function per program and variant (native_abi.h) that runs an
// 8x8 block the way raster/pixel_interpreter.cpp does, but in machine code. The block is walked a
// vector at a time (4, 8 or 16 lanes: a chunk), each chunk running the whole program with its
// registers in vector registers and the execution mask as a vector of booleans; the
// interpreter's run-time mask stack becomes variables per nesting level (mask_frames.h). Every
// lane computes what the interpreter computes for it -- the same operations in the same order,
// lane_ops.h -- so images are bit-identical. A chunk's lanes are independent of the block's
// other lanes for every instruction but the field searches, which cast the block's rays
// together: programs with those are not compiled (the interpreter runs them).
#pragma once

#include <string>

#include "compiler/isa.h"
#include "compiler/native/native_abi.h"

namespace llvm {
class Function;
class Module;
}  // namespace llvm

namespace pf {

// Deliberate miscompiles, for the test that checks the suite catches one (a mask dropped):
// merge values written in every lane, or every lane committed. Part of the cache key, so a
// faulty function never runs for a key compiled without the fault.
enum class NativeFault : uint8_t { None, MergeWithoutMask, CommitWithoutMask };
void setNativeFaultForTesting(NativeFault fault);
NativeFault nativeFaultForTesting();

// Whether native code can run `program`; if not, `why` says what stops it.
bool nativePixelSupports(const PixelProgram& program, std::string* why = nullptr);

// Adds to `module` the function `name` (a NativePixelFunction) running `program` under
// `variant`, and returns it; null with `error` set when it cannot (nativePixelSupports, or
// code that is not structured).
llvm::Function* buildPixelFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                   const NativePixelVariant& variant, std::string& error);

}  // namespace pf
