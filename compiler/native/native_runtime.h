// The functions native code calls for what it does not inline: the maths functions (sin, exp,
// pow, noise ...) and the fixed-point instructions, one lane at a time. Each is evalScalar
// (compiler/scalar_ops.h) for its op -- the one definition the interpreters and the constant
// folder use -- so native code and the interpreter compute the same bits by construction.
#pragma once

#include <cstdint>

#include "compiler/isa.h"

namespace pf {

// A helper the JIT resolves by name: `arity` 32-bit operands in, one 32-bit result out
// (arity 6: op, a, b, c, d, imm -- the fixed-point helper).
struct NativeHelper {
  const char* name;
  Op op;
  int arity;
  void* address;
};

// The helper for value op `op` (null if native code computes it inline), and all of them.
const NativeHelper* nativeHelperFor(Op op);
const NativeHelper* nativeHelpers(int& count);

}  // namespace pf
