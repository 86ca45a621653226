// The process-wide cache of native programs, keyed by content: a program's bytecode and
// constants, the variant it is specialised on (native_abi.h) and the instruction set. Two
// contexts drawing the same primitive compile it once; a primitive recompiled under the same
// name is new content, so new draws get a new function while draws of the old one still
// pending run the old (nothing compiled is ever freed: functions are small, and a pointer to
// one may be held by any thread). Compiled lazily, on the first block that needs it, in the
// thread that asks; others asking for the same key meanwhile wait for it. Programs native
// code does not run (pixel_codegen.h) are remembered as such, and the interpreter runs them.
#pragma once

#include <cstdint>
#include <string>

#include "compiler/isa.h"
#include "compiler/native/native_abi.h"

namespace pf {

// Whether the environment leaves native code on: PF_JIT unset or not "0".
bool nativeCodeWantedByEnvironment();

struct NativeCacheStats {
  uint64_t compiled = 0;      // functions compiled (each key once)
  uint64_t refused = 0;       // keys native code does not run
  uint64_t failed = 0;        // keys LLVM failed on (said on stderr once each)
  double milliseconds = 0;    // spent building, optimizing and compiling them
};

class NativeProgramCache {
 public:
  static NativeProgramCache& instance();

  // The function for `program` under `variant`; null when native code is unavailable or does
  // not run this program (the interpreter runs it then).
  NativePixelFunction pixelFunction(const PixelProgram& program, const NativePixelVariant& variant);

  NativeCacheStats stats() const;

  NativeProgramCache(const NativeProgramCache&) = delete;
  NativeProgramCache& operator=(const NativeProgramCache&) = delete;

 private:
  NativeProgramCache();
  ~NativeProgramCache();
  struct Impl;
  Impl* impl_;
};

// What `pfc --emit=native` prints for `program` under `variant`: the optimized LLVM IR and the
// assembly; false with `error` set when native code cannot run it.
bool nativePixelListing(const PixelProgram& program, const NativePixelVariant& variant, std::string& listing,
                        std::string& error);

}  // namespace pf
