// The value instructions in LLVM IR (see lane_ops.h). Each case is evalScalar's line for the
// op, written on vectors; the comments say where the two must be read together.
#include "compiler/native/lane_ops.h"

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/Module.h>

#include "compiler/native/native_runtime.h"

namespace pf {
namespace {

using llvm::Value;

struct Lanes {
  llvm::IRBuilderBase& b;
  llvm::Module& m;
  llvm::VectorType* iv;  // <W x i32>
  llvm::VectorType* fv;  // <W x float>
  unsigned width;

  Value* f(Value* x) { return b.CreateBitCast(x, fv); }
  Value* i(Value* x) { return b.CreateBitCast(x, iv); }
  Value* splatI(uint32_t v) { return b.CreateVectorSplat(width, b.getInt32(v)); }
  Value* splatF(float v) { return b.CreateVectorSplat(width, llvm::ConstantFP::get(b.getFloatTy(), v)); }
  Value* boolToI(Value* cmp) { return b.CreateZExt(cmp, iv); }  // comparisons give 0 or 1
  Value* intrinsic(llvm::Intrinsic::ID id, Value* x) {
    return b.CreateIntrinsic(id, {x->getType()}, {x});
  }

  // The helper for `op`, called on each lane in turn.
  Value* helper(Op op, Value* a, Value* bv, Value* c, Value* d, uint32_t imm) {
    const NativeHelper* h = nativeHelperFor(op);
    llvm::Type* i32 = b.getInt32Ty();
    std::vector<llvm::Type*> params(static_cast<size_t>(h->arity), i32);
    auto* type = llvm::FunctionType::get(i32, params, false);
    llvm::FunctionCallee callee = m.getOrInsertFunction(h->name, type);
    if (auto* fn = llvm::dyn_cast<llvm::Function>(callee.getCallee())) {
      // Pure: LLVM may drop a call whose lane is never used and share equal calls.
      fn->setDoesNotAccessMemory();
      fn->setDoesNotThrow();
      fn->setWillReturn();
    }
    Value* out = llvm::UndefValue::get(iv);
    Value* ops[4] = {a, bv, c, d};
    for (unsigned l = 0; l < width; ++l) {
      std::vector<Value*> args;
      if (h->arity == 6) args.push_back(b.getInt32(static_cast<uint32_t>(op)));
      for (int k = 0; k < (h->arity == 6 ? 4 : h->arity); ++k) args.push_back(b.CreateExtractElement(ops[k], l));
      if (h->arity == 6) args.push_back(b.getInt32(imm));
      out = b.CreateInsertElement(out, b.CreateCall(callee, args), l);
    }
    return out;
  }
};

}  // namespace

Value* emitLaneOp(llvm::IRBuilderBase& b, llvm::Module& m, Op op, Value* a, Value* bv, Value* c, Value* d,
                  uint32_t imm) {
  auto* iv = llvm::cast<llvm::VectorType>(a->getType());
  const unsigned width = llvm::cast<llvm::FixedVectorType>(iv)->getNumElements();
  Lanes L{b, m, iv, llvm::FixedVectorType::get(b.getFloatTy(), width), width};
  switch (op) {
    case Op::FAdd: return L.i(b.CreateFAdd(L.f(a), L.f(bv)));
    case Op::FSub: return L.i(b.CreateFSub(L.f(a), L.f(bv)));
    case Op::FMul: return L.i(b.CreateFMul(L.f(a), L.f(bv)));
    case Op::FDiv: return L.i(b.CreateFDiv(L.f(a), L.f(bv)));
    case Op::FMin: return L.i(b.CreateSelect(b.CreateFCmpOLT(L.f(bv), L.f(a)), L.f(bv), L.f(a)));  // b < a ? b : a
    case Op::FMax: return L.i(b.CreateSelect(b.CreateFCmpOLT(L.f(a), L.f(bv)), L.f(bv), L.f(a)));  // a < b ? b : a
    case Op::FNeg: return b.CreateXor(a, L.splatI(0x80000000u));
    case Op::FAbs: return b.CreateAnd(a, L.splatI(0x7fffffffu));
    case Op::FFloor: return L.i(L.intrinsic(llvm::Intrinsic::floor, L.f(a)));
    case Op::FCeil: return L.i(L.intrinsic(llvm::Intrinsic::ceil, L.f(a)));
    case Op::FSqrt: return L.i(L.intrinsic(llvm::Intrinsic::sqrt, L.f(a)));
    case Op::FSign: {  // a > 0 ? 1 : a < 0 ? -1 : 0 (NaN: 0)
      Value* x = L.f(a);
      Value* neg = b.CreateSelect(b.CreateFCmpOLT(x, L.splatF(0.0f)), L.splatF(-1.0f), L.splatF(0.0f));
      return L.i(b.CreateSelect(b.CreateFCmpOGT(x, L.splatF(0.0f)), L.splatF(1.0f), neg));
    }
    case Op::FSin: case Op::FCos: case Op::FTan: case Op::FAsin: case Op::FAcos: case Op::FAtan: case Op::FAtan2:
    case Op::FPow: case Op::FExp: case Op::FLog: case Op::FNoise:
    case Op::QAdd: case Op::QSub: case Op::QMul: case Op::QDiv: case Op::QNeg: case Op::QAbs: case Op::QLt:
    case Op::QLe: case Op::QEq: case Op::QFromF: case Op::QFromI: case Op::QToF: case Op::QToI: case Op::QConv:
      return L.helper(op, a, bv, c, d, imm);
    // Integer arithmetic wraps; division by zero gives 0, INT_MIN / -1 gives INT_MIN (a), and
    // the remainder of either is 0. The divisor is made harmless first: no lane may trap.
    case Op::IAdd: return b.CreateAdd(a, bv);
    case Op::ISub: return b.CreateSub(a, bv);
    case Op::IMul: return b.CreateMul(a, bv);
    case Op::IDiv: {
      Value* zero = b.CreateICmpEQ(bv, L.splatI(0));
      Value* overflow = b.CreateAnd(b.CreateICmpEQ(a, L.splatI(0x80000000u)), b.CreateICmpEQ(bv, L.splatI(~0u)));
      Value* safe = b.CreateSelect(b.CreateOr(zero, overflow), L.splatI(1), bv);
      Value* q = b.CreateSDiv(a, safe);
      return b.CreateSelect(zero, L.splatI(0), b.CreateSelect(overflow, a, q));
    }
    case Op::IMod: {
      Value* none = b.CreateOr(b.CreateICmpEQ(bv, L.splatI(0)), b.CreateICmpEQ(bv, L.splatI(~0u)));
      Value* r = b.CreateSRem(a, b.CreateSelect(none, L.splatI(1), bv));
      return b.CreateSelect(none, L.splatI(0), r);
    }
    case Op::INeg: return b.CreateSub(L.splatI(0), a);
    case Op::IMin: return b.CreateSelect(b.CreateICmpSLT(a, bv), a, bv);
    case Op::IMax: return b.CreateSelect(b.CreateICmpSLT(a, bv), bv, a);
    case Op::IAbs: return b.CreateSelect(b.CreateICmpSLT(a, L.splatI(0)), b.CreateSub(L.splatI(0), a), a);
    case Op::I2F: return L.i(b.CreateSIToFP(a, L.fv));
    case Op::F2I:  // saturating, NaN -> 0: exactly saturatingToInt
      return b.CreateIntrinsic(llvm::Intrinsic::fptosi_sat, {iv, L.fv}, {L.f(a)});
    case Op::FLt: return L.boolToI(b.CreateFCmpOLT(L.f(a), L.f(bv)));
    case Op::FLe: return L.boolToI(b.CreateFCmpOLE(L.f(a), L.f(bv)));
    case Op::FEq: return L.boolToI(b.CreateFCmpOEQ(L.f(a), L.f(bv)));
    case Op::FNe: return L.boolToI(b.CreateFCmpUNE(L.f(a), L.f(bv)));  // C's != is true for NaN
    case Op::ILt: return L.boolToI(b.CreateICmpSLT(a, bv));
    case Op::ILe: return L.boolToI(b.CreateICmpSLE(a, bv));
    case Op::IEq: return L.boolToI(b.CreateICmpEQ(a, bv));
    case Op::INe: return L.boolToI(b.CreateICmpNE(a, bv));
    case Op::BAnd: return b.CreateAnd(b.CreateAnd(a, bv), L.splatI(1));
    case Op::BOr: return b.CreateAnd(b.CreateOr(a, bv), L.splatI(1));
    case Op::BNot: return b.CreateXor(a, L.splatI(1));
    case Op::Sel: return b.CreateSelect(b.CreateICmpNE(a, L.splatI(0)), bv, c);
    case Op::CrossSign: {
      // sign(a * d - b * c) from products in double (exact for floats): (p > q) - (p < q).
      auto* dv = llvm::FixedVectorType::get(b.getDoubleTy(), width);
      Value* p = b.CreateFMul(b.CreateFPExt(L.f(a), dv), b.CreateFPExt(L.f(d), dv));
      Value* q = b.CreateFMul(b.CreateFPExt(L.f(bv), dv), b.CreateFPExt(L.f(c), dv));
      Value* gt = b.CreateUIToFP(b.CreateFCmpOGT(p, q), L.fv);
      Value* lt = b.CreateUIToFP(b.CreateFCmpOLT(p, q), L.fv);
      return L.i(b.CreateFSub(gt, lt));
    }
    case Op::Mov: return a;
    default: return L.splatI(0);  // evalScalar's default: not a value op
  }
}

}  // namespace pf
