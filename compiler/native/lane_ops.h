// LLVM IR for the value instructions of compiler/isa.h (every op up to Op::Mov) on vectors of
// 32-bit lanes: the native counterpart of evalScalar (compiler/scalar_ops.h), one lane's meaning
// applied to each lane of a vector. The arithmetic is IEEE with nothing contracted or
// reassociated; what LLVM cannot express exactly (sin, exp, pow, noise, fixed point) calls the
// helpers of native_runtime.h lane by lane. The pixel code generator uses it, and any other
// generator of vector code over the same instructions can.
#pragma once

#include <cstdint>

#include "compiler/isa.h"

namespace llvm {
class Module;
class Value;
class IRBuilderBase;
}  // namespace llvm

namespace pf {

// Whether `op` computes a value (evalScalar's ops: up to Op::Mov).
constexpr bool isLaneValueOp(Op op) { return op <= Op::Mov; }

// dst = op(a, b, c, d) lane by lane, every operand and the result a vector of i32 (the lanes'
// bits, as the interpreters' registers hold them); missing operands are zero vectors.
llvm::Value* emitLaneOp(llvm::IRBuilderBase& b, llvm::Module& m, Op op, llvm::Value* a, llvm::Value* bv,
                        llvm::Value* c, llvm::Value* d, uint32_t imm);

}  // namespace pf
