// Block rejection's interval walk as native code (see interval_codegen.h). Every helper here is
// the function of the same name in raster/block_rejection.cpp, written in IR: read the two
// side by side.
#include "compiler/native/interval_codegen.h"

#include <cmath>
#include <limits>
#include <vector>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Intrinsics.h>
#include <llvm/IR/Module.h>

#include "compiler/native/mask_frames.h"

namespace pf {

bool nativeVerdictSupports(const PixelProgram& program, std::string* why) {
  if (program.last_early_retire < 0) {
    if (why) *why = "nothing to reject: the program has no early return";
    return false;
  }
  const size_t n = std::min(program.code.size(), static_cast<size_t>(program.last_early_retire) + 1);
  for (size_t pc = 0; pc < n; ++pc) {
    const Instr& in = program.code[pc];
    if ((in.op == Op::Jmp || in.op == Op::JmpIfNot) && in.a <= pc) {
      if (why) *why = "a backward jump in its leading part";
      return false;
    }
    if (in.dst != kNoOperand && operandKind(in.dst) == OperandKind::Reg && operandIndex(in.dst) >= program.num_regs &&
        in.op != Op::XAdd && in.op != Op::XSub && in.op != Op::XNeg && in.op != Op::XMulF && in.op != Op::XDivF &&
        in.op != Op::XMov && in.op != Op::XSel) {
      if (why) *why = "a register past the program's";
      return false;
    }
  }
  return true;
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

class IntervalCodegen {
 public:
  IntervalCodegen(llvm::Module& m) : module_(m), ctx_(m.getContext()), b_(m.getContext()) {}

  llvm::Function* build(const std::string& name, const PixelProgram& p, std::string& error);

 private:
  struct Range {
    llvm::Value* lo;
    llvm::Value* hi;
    llvm::Value* nan;  // i1
  };
  struct Slot {  // a register's range, as variables
    llvm::AllocaInst* lo;
    llvm::AllocaInst* hi;
    llvm::AllocaInst* nan;
  };
  enum class As { Float, Int, Bool, Any };

  llvm::Value* d(double v) { return llvm::ConstantFP::get(b_.getDoubleTy(), v); }
  llvm::Value* isnan(llvm::Value* v) { return b_.CreateFCmpUNO(v, v); }
  llvm::Value* isinf(llvm::Value* v) { return b_.CreateFCmpOEQ(fabs(v), d(kInf)); }
  llvm::Value* fabs(llvm::Value* v) { return b_.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, v); }
  llvm::Value* select(llvm::Value* c, llvm::Value* a, llvm::Value* b) { return b_.CreateSelect(c, a, b); }
  // std::min / std::max on doubles: (b < a) ? b : a and (a < b) ? b : a.
  llvm::Value* min(llvm::Value* a, llvm::Value* b) { return select(b_.CreateFCmpOLT(b, a), b, a); }
  llvm::Value* max(llvm::Value* a, llvm::Value* b) { return select(b_.CreateFCmpOLT(a, b), b, a); }
  Range pick(llvm::Value* c, const Range& a, const Range& b) {
    return {select(c, a.lo, b.lo), select(c, a.hi, b.hi), select(c, a.nan, b.nan)};
  }
  Range unknown() { return {d(-kInf), d(kInf), b_.getTrue()}; }
  Range unknownBool() { return {d(0.0), d(1.0), b_.getFalse()}; }

  Range widen(llvm::Value* lo, llvm::Value* hi) {
    llvm::Value* bad = b_.CreateOr(isnan(lo), isnan(hi));
    const double tiny = 1.2e-38;
    llvm::Value* wlo = b_.CreateFSub(lo, b_.CreateFAdd(b_.CreateFMul(fabs(lo), d(0x1p-22)), d(tiny)));
    llvm::Value* whi = b_.CreateFAdd(hi, b_.CreateFAdd(b_.CreateFMul(fabs(hi), d(0x1p-22)), d(tiny)));
    return pick(bad, unknown(), Range{wlo, whi, b_.getFalse()});
  }
  Range point(llvm::Value* v) { return pick(isnan(v), unknown(), Range{v, v, b_.getFalse()}); }
  Range boolean(llvm::Value* can_false, llvm::Value* can_true) {
    return {select(can_false, d(0.0), d(1.0)), select(can_true, d(1.0), d(0.0)), b_.getFalse()};
  }
  llvm::Value* certainlyTrue(const Range& r) { return b_.CreateAnd(b_.CreateFCmpOEQ(r.lo, d(1.0)), b_.CreateNot(r.nan)); }
  llvm::Value* certainlyFalse(const Range& r) { return b_.CreateAnd(b_.CreateFCmpOEQ(r.hi, d(0.0)), b_.CreateNot(r.nan)); }
  Range hull(const Range& a, const Range& b) { return {min(a.lo, b.lo), max(a.hi, b.hi), b_.CreateOr(a.nan, b.nan)}; }

  Range add(const Range& a, const Range& b) {
    llvm::Value* lo = b_.CreateFAdd(a.lo, b.lo);
    llvm::Value* hi = b_.CreateFAdd(a.hi, b.hi);
    Range r = widen(select(isnan(lo), d(-kInf), lo), select(isnan(hi), d(kInf), hi));
    llvm::Value* opposite =
        b_.CreateOr(b_.CreateAnd(b_.CreateFCmpOEQ(a.hi, d(kInf)), b_.CreateFCmpOEQ(b.lo, d(-kInf))),
                    b_.CreateAnd(b_.CreateFCmpOEQ(a.lo, d(-kInf)), b_.CreateFCmpOEQ(b.hi, d(kInf))));
    r.nan = b_.CreateOr(b_.CreateOr(a.nan, b.nan), opposite);
    return r;
  }
  Range negate(const Range& a) { return {b_.CreateFNeg(a.hi), b_.CreateFNeg(a.lo), a.nan}; }
  Range mul(const Range& a, const Range& b) {
    llvm::Value* lo = d(kInf);
    llvm::Value* hi = d(-kInf);
    llvm::Value* nan = b_.CreateOr(a.nan, b.nan);
    for (llvm::Value* x : {a.lo, a.hi})
      for (llvm::Value* y : {b.lo, b.hi}) {
        llvm::Value* p = b_.CreateFMul(x, y);
        llvm::Value* pn = isnan(p);
        nan = b_.CreateOr(nan, pn);
        lo = select(pn, lo, min(lo, p));
        hi = select(pn, hi, max(hi, p));
      }
    llvm::Value* empty = b_.CreateFCmpOGT(lo, hi);
    auto spans0 = [&](const Range& r) { return b_.CreateAnd(b_.CreateFCmpOLE(r.lo, d(0.0)), b_.CreateFCmpOGE(r.hi, d(0.0))); };
    auto infinite = [&](const Range& r) { return b_.CreateOr(isinf(r.lo), isinf(r.hi)); };
    nan = b_.CreateOr(nan, b_.CreateOr(b_.CreateAnd(spans0(a), infinite(b)), b_.CreateAnd(spans0(b), infinite(a))));
    Range r = widen(lo, hi);
    r.nan = nan;
    return pick(empty, unknown(), r);
  }
  Range square(const Range& a) {
    llvm::Value* one_sign = b_.CreateOr(b_.CreateFCmpOGE(a.lo, d(0.0)), b_.CreateFCmpOLE(a.hi, d(0.0)));
    Range product = mul(a, a);
    Range r = widen(d(0.0), max(b_.CreateFMul(a.lo, a.lo), b_.CreateFMul(a.hi, a.hi)));
    r.lo = d(0.0);
    r.nan = a.nan;
    return pick(one_sign, product, r);
  }
  Range div(const Range& a, const Range& b) {
    llvm::Value* zero = b_.CreateAnd(b_.CreateFCmpOLE(b.lo, d(0.0)), b_.CreateFCmpOGE(b.hi, d(0.0)));
    Range r = mul(a, Range{b_.CreateFDiv(d(1.0), b.hi), b_.CreateFDiv(d(1.0), b.lo), b.nan});
    return pick(zero, unknown(), r);
  }

  Range load(const Slot& s) {
    return {b_.CreateLoad(b_.getDoubleTy(), s.lo), b_.CreateLoad(b_.getDoubleTy(), s.hi), b_.CreateLoad(b_.getInt1Ty(), s.nan)};
  }
  void store(const Slot& s, const Range& r) {
    b_.CreateStore(r.lo, s.lo);
    b_.CreateStore(r.hi, s.hi);
    b_.CreateStore(r.nan, s.nan);
  }
  Slot slot(llvm::IRBuilder<>& at) {
    return {at.CreateAlloca(b_.getDoubleTy()), at.CreateAlloca(b_.getDoubleTy()), at.CreateAlloca(b_.getInt1Ty())};
  }
  // read(): registers whatever `as` says; uniforms and constants by their bits.
  Range read(uint32_t o, As as) {
    if (o == kNoOperand) return unknown();
    const uint32_t i = operandIndex(o);
    llvm::Value* bits = nullptr;
    switch (operandKind(o)) {
      case OperandKind::Reg: return i < regs_.size() ? load(regs_[i]) : unknown();
      case OperandKind::Uniform: {
        llvm::LoadInst* l = b_.CreateAlignedLoad(b_.getInt32Ty(), b_.CreateConstInBoundsGEP1_32(b_.getInt32Ty(), record_, i),
                                                 llvm::Align(4));
        l->setMetadata(llvm::LLVMContext::MD_invariant_load, llvm::MDNode::get(ctx_, {}));
        bits = l;
        break;
      }
      case OperandKind::Const:
        if (i >= program_->constants.size()) return unknown();
        bits = b_.getInt32(program_->constants[i]);
        break;
      default: return unknown();
    }
    switch (as) {
      case As::Float: return point(b_.CreateFPExt(b_.CreateBitCast(bits, b_.getFloatTy()), b_.getDoubleTy()));
      case As::Int: return point(b_.CreateSIToFP(bits, b_.getDoubleTy()));
      case As::Bool: return point(select(b_.CreateICmpNE(bits, b_.getInt32(0)), d(1.0), d(0.0)));
      case As::Any: return unknown();
    }
    return unknown();
  }
  Range value(const Instr& in);

  llvm::Module& module_;
  llvm::LLVMContext& ctx_;
  llvm::IRBuilder<> b_;
  const PixelProgram* program_ = nullptr;
  llvm::Value* record_ = nullptr;
  llvm::Value* state_values_ = nullptr;
  std::vector<Slot> regs_;
};

// The range an instruction computes (block_rejection.cpp's second switch).
IntervalCodegen::Range IntervalCodegen::value(const Instr& in) {
  auto f = [&](uint32_t o) { return read(o, As::Float); };
  auto iv = [&](uint32_t o) { return read(o, As::Int); };
  auto bv = [&](uint32_t o) { return read(o, As::Bool); };
  switch (in.op) {
    case Op::FAdd: return add(f(in.a), f(in.b));
    case Op::FSub: return add(f(in.a), negate(f(in.b)));
    case Op::FMul: return in.a == in.b ? square(f(in.a)) : mul(f(in.a), f(in.b));
    case Op::FDiv: return div(f(in.a), f(in.b));
    case Op::FNeg: return negate(f(in.a));
    case Op::FAbs: {
      const Range a = f(in.a);
      Range spans{d(0.0), max(b_.CreateFNeg(a.lo), a.hi), a.nan};
      return pick(b_.CreateFCmpOGE(a.lo, d(0.0)), a, pick(b_.CreateFCmpOLE(a.hi, d(0.0)), negate(a), spans));
    }
    case Op::FMin: case Op::FMax: {
      const Range a = f(in.a), b = f(in.b);
      Range r = in.op == Op::FMin ? Range{min(a.lo, b.lo), min(a.hi, b.hi), b_.getFalse()}
                                  : Range{max(a.lo, b.lo), max(a.hi, b.hi), b_.getFalse()};
      return pick(b_.CreateOr(a.nan, b.nan), unknown(), r);
    }
    case Op::FSqrt: {
      const Range a = f(in.a);
      Range r = widen(b_.CreateUnaryIntrinsic(llvm::Intrinsic::sqrt, max(a.lo, d(0.0))),
                      b_.CreateUnaryIntrinsic(llvm::Intrinsic::sqrt, a.hi));
      r.nan = b_.CreateOr(a.nan, b_.CreateFCmpOLT(a.lo, d(0.0)));
      return pick(b_.CreateFCmpOLT(a.hi, d(0.0)), unknown(), r);
    }
    case Op::FLt: case Op::FLe: case Op::FEq: case Op::FNe: {
      const Range a = f(in.a), b = f(in.b);
      llvm::Value* nan = b_.CreateOr(a.nan, b.nan);
      llvm::Value *can_true, *can_false;
      if (in.op == Op::FLt) {
        can_true = b_.CreateFCmpOLT(a.lo, b.hi);
        can_false = b_.CreateOr(b_.CreateFCmpOGE(a.hi, b.lo), nan);
      } else if (in.op == Op::FLe) {
        can_true = b_.CreateFCmpOLE(a.lo, b.hi);
        can_false = b_.CreateOr(b_.CreateFCmpOGT(a.hi, b.lo), nan);
      } else {
        llvm::Value* can_equal = b_.CreateAnd(b_.CreateFCmpOLE(a.lo, b.hi), b_.CreateFCmpOLE(b.lo, a.hi));
        llvm::Value* all_same = b_.CreateAnd(b_.CreateAnd(b_.CreateFCmpOEQ(a.lo, a.hi), b_.CreateFCmpOEQ(b.lo, b.hi)),
                                             b_.CreateFCmpOEQ(a.lo, b.lo));
        llvm::Value* can_differ = b_.CreateOr(b_.CreateNot(all_same), nan);
        can_true = in.op == Op::FEq ? can_equal : can_differ;
        can_false = in.op == Op::FEq ? can_differ : can_equal;
      }
      return boolean(can_false, can_true);
    }
    case Op::BAnd: case Op::BOr: {
      const Range a = bv(in.a), b = bv(in.b);
      return in.op == Op::BAnd ? Range{min(a.lo, b.lo), min(a.hi, b.hi), b_.getFalse()}
                               : Range{max(a.lo, b.lo), max(a.hi, b.hi), b_.getFalse()};
    }
    case Op::BNot: {
      const Range a = bv(in.a);
      return {b_.CreateFSub(d(1.0), a.hi), b_.CreateFSub(d(1.0), a.lo), b_.getFalse()};
    }
    case Op::IAdd: case Op::ISub: case Op::IMul: {
      const Range a = iv(in.a), b = iv(in.b);
      Range s = in.op == Op::IAdd ? add(a, b) : in.op == Op::ISub ? add(a, negate(b)) : mul(a, b);
      llvm::Value* fits = b_.CreateAnd(b_.CreateFCmpOGE(s.lo, d(-2147483648.0)), b_.CreateFCmpOLE(s.hi, d(2147483647.0)));
      Range r{b_.CreateUnaryIntrinsic(llvm::Intrinsic::ceil, b_.CreateFSub(s.lo, d(0.5))),
              b_.CreateUnaryIntrinsic(llvm::Intrinsic::floor, b_.CreateFAdd(s.hi, d(0.5))), b_.getFalse()};
      return pick(fits, r, unknown());
    }
    case Op::ILt: case Op::ILe: case Op::IEq: case Op::INe: {
      const Range a = iv(in.a), b = iv(in.b);
      if (in.op == Op::ILt) return boolean(b_.CreateFCmpOGE(a.hi, b.lo), b_.CreateFCmpOLT(a.lo, b.hi));
      if (in.op == Op::ILe) return boolean(b_.CreateFCmpOGT(a.hi, b.lo), b_.CreateFCmpOLE(a.lo, b.hi));
      llvm::Value* can_equal = b_.CreateAnd(b_.CreateFCmpOLE(a.lo, b.hi), b_.CreateFCmpOLE(b.lo, a.hi));
      llvm::Value* can_differ = b_.CreateNot(b_.CreateAnd(
          b_.CreateAnd(b_.CreateFCmpOEQ(a.lo, a.hi), b_.CreateFCmpOEQ(b.lo, b.hi)), b_.CreateFCmpOEQ(a.lo, b.lo)));
      return in.op == Op::IEq ? boolean(can_differ, can_equal) : boolean(can_equal, can_differ);
    }
    case Op::I2F: {
      const Range a = iv(in.a);
      return widen(a.lo, a.hi);
    }
    case Op::CrossSign: {
      const Range s = add(mul(f(in.a), f(in.d)), negate(mul(f(in.b), f(in.c))));
      llvm::Value* pos = b_.CreateFCmpOGT(s.lo, d(0.0));
      llvm::Value* neg = b_.CreateFCmpOLT(s.hi, d(0.0));
      llvm::Value* lo = select(pos, d(1.0), select(neg, d(-1.0), select(b_.CreateFCmpOEQ(s.lo, d(0.0)), d(0.0), d(-1.0))));
      llvm::Value* hi = select(neg, d(-1.0), select(pos, d(1.0), select(b_.CreateFCmpOEQ(s.hi, d(0.0)), d(0.0), d(1.0))));
      return pick(s.nan, unknown(), Range{lo, hi, b_.getFalse()});
    }
    case Op::Sel: {
      const Range c = bv(in.a);
      auto arm = [&](uint32_t o) { return operandKind(o) == OperandKind::Reg ? read(o, As::Any) : unknown(); };
      const bool both_regs = operandKind(in.b) == OperandKind::Reg && operandKind(in.c) == OperandKind::Reg;
      Range neither = both_regs ? hull(read(in.b, As::Any), read(in.c, As::Any)) : unknown();
      return pick(certainlyTrue(c), arm(in.b), pick(certainlyFalse(c), arm(in.c), neither));
    }
    case Op::Mov:
      return operandKind(in.a) == OperandKind::Reg ? read(in.a, As::Any) : unknown();
    case Op::LoadState: {
      llvm::LoadInst* l = b_.CreateAlignedLoad(b_.getFloatTy(), b_.CreateConstInBoundsGEP1_32(b_.getFloatTy(), state_values_, in.imm),
                                               llvm::Align(4));
      return point(b_.CreateFPExt(l, b_.getDoubleTy()));
    }
    default: return unknown();  // Z tests, fields, noise, the rest
  }
}

llvm::Function* IntervalCodegen::build(const std::string& name, const PixelProgram& p, std::string& error) {
  if (!nativeVerdictSupports(p, &error)) return nullptr;
  MaskFrames frames;
  if (!findMaskFrames(p.code, frames, error)) return nullptr;
  program_ = &p;
  llvm::Type* ptr = b_.getPtrTy();
  auto* type = llvm::FunctionType::get(b_.getInt32Ty(), {ptr, ptr, ptr}, false);
  llvm::Function* fn = llvm::Function::Create(type, llvm::Function::ExternalLinkage, name, module_);
  record_ = fn->getArg(0);
  state_values_ = fn->getArg(1);
  llvm::Value* region = fn->getArg(2);
  llvm::BasicBlock* entry = llvm::BasicBlock::Create(ctx_, "entry", fn);
  llvm::IRBuilder<> at(entry);
  b_.SetInsertPoint(entry);

  for (uint32_t r = 0; r < p.num_regs; ++r) regs_.push_back(slot(at));
  const int depth_max = frames.max_depth;
  std::vector<Slot> cond;
  std::vector<llvm::AllocaInst*> in_else;
  for (int k = 0; k < depth_max; ++k) {
    cond.push_back(slot(at));
    in_else.push_back(at.CreateAlloca(b_.getInt1Ty()));
  }
  llvm::AllocaInst* coverage_may_run = at.CreateAlloca(b_.getInt1Ty());
  for (const Slot& s : regs_) store(s, unknown());
  b_.CreateStore(b_.getInt1(p.last_coverage_retire < 0), coverage_may_run);
  if (p.num_regs > kRegY) {
    auto region_at = [&](int k) {
      return b_.CreateAlignedLoad(b_.getDoubleTy(), b_.CreateConstInBoundsGEP1_32(b_.getDoubleTy(), region, k), llvm::Align(8));
    };
    store(regs_[kRegX], Range{region_at(0), region_at(1), b_.getFalse()});
    store(regs_[kRegY], Range{region_at(2), region_at(3), b_.getFalse()});
  }

  const size_t n = std::min(p.code.size(), static_cast<size_t>(p.last_early_retire) + 1);
  const size_t coverage_end = p.last_coverage_retire >= 0 ? static_cast<size_t>(p.last_coverage_retire) + 1 : 0;
  std::vector<llvm::BasicBlock*> at_pc(n + 1);
  for (size_t pc = 0; pc <= n; ++pc) at_pc[pc] = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc), fn);
  llvm::BasicBlock* unknown_exit = llvm::BasicBlock::Create(ctx_, "unknown", fn);
  llvm::BasicBlock* rejected_exit = llvm::BasicBlock::Create(ctx_, "rejected", fn);
  b_.CreateBr(at_pc[0]);
  auto target = [&](uint32_t t) { return at_pc[std::min<size_t>(t, n)]; };

  for (size_t pc = 0; pc < n; ++pc) {
    b_.SetInsertPoint(at_pc[pc]);
    const Instr& in = p.code[pc];
    if (!frames.reached[pc]) {
      b_.CreateBr(at_pc[pc + 1]);
      continue;
    }
    // live: no frame certainly excludes every lane; certain: every frame certainly includes all.
    const int depth = static_cast<int>(frames.at[pc].size());
    llvm::Value* live = b_.getTrue();
    llvm::Value* certain = b_.getTrue();
    for (int k = 0; k < depth; ++k) {
      const Range c = load(cond[static_cast<size_t>(k)]);
      llvm::Value* e = b_.CreateLoad(b_.getInt1Ty(), in_else[static_cast<size_t>(k)]);
      llvm::Value* runs_all = select(e, certainlyFalse(c), certainlyTrue(c));
      llvm::Value* runs_none = select(e, certainlyTrue(c), certainlyFalse(c));
      live = b_.CreateAnd(live, b_.CreateNot(runs_none));
      certain = b_.CreateAnd(certain, runs_all);
    }
    llvm::BasicBlock* next = at_pc[pc + 1];
    switch (in.op) {
      case Op::MaskIf: {
        const Range c = pick(live, read(in.b == kNoOperand ? in.a : in.b, As::Bool), unknownBool());
        store(cond[static_cast<size_t>(depth)], c);
        b_.CreateStore(b_.getFalse(), in_else[static_cast<size_t>(depth)]);
        b_.CreateBr(next);
        continue;
      }
      case Op::MaskElse:
        b_.CreateStore(b_.getTrue(), in_else[static_cast<size_t>(depth - 1)]);
        b_.CreateBr(next);
        continue;
      case Op::MaskEnd: case Op::JmpIfNone:
        b_.CreateBr(next);
        continue;
      default: break;
    }
    // What follows runs only where some lane is live.
    llvm::BasicBlock* run = llvm::BasicBlock::Create(ctx_, "live", fn);
    b_.CreateCondBr(live, run, next);
    b_.SetInsertPoint(run);
    switch (in.op) {
      case Op::Retire: {
        if (pc + 1 <= coverage_end) b_.CreateStore(b_.getTrue(), coverage_may_run);
        b_.CreateCondBr(certain, rejected_exit, next);
        continue;
      }
      case Op::Jmp: b_.CreateBr(target(in.a)); continue;
      case Op::JmpIfNot: {
        const Range c = read(in.b, As::Bool);
        llvm::BasicBlock* maybe = llvm::BasicBlock::Create(ctx_, "maybe", fn);
        b_.CreateCondBr(certainlyFalse(c), target(in.a), maybe);
        b_.SetInsertPoint(maybe);
        b_.CreateCondBr(certainlyTrue(c), next, unknown_exit);
        continue;
      }
      case Op::LoopBegin: case Op::LoopTest: case Op::Break: case Op::Continue: case Op::LoopContinue:
      case Op::LoopBack: case Op::LoopEnd:
        b_.CreateBr(unknown_exit);
        continue;
      default: break;
    }
    const bool interp = in.op == Op::XAdd || in.op == Op::XSub || in.op == Op::XNeg || in.op == Op::XMulF ||
                        in.op == Op::XDivF || in.op == Op::XMov || in.op == Op::XLoadVertex || in.op == Op::XSel ||
                        in.op == Op::XLoadVertexAt;
    if (!interp && in.dst != kNoOperand && operandKind(in.dst) == OperandKind::Reg) {
      const Slot& dst = regs_[operandIndex(in.dst)];
      Range r = value(in);
      // A merge value written under a mask some lanes may not be in keeps their old values.
      if (in.masked_write) r = pick(certain, r, hull(load(dst), r));
      store(dst, r);
    }
    b_.CreateBr(next);
  }
  b_.SetInsertPoint(at_pc[n]);
  llvm::Value* accepted = b_.getFalse();
  if (p.covered) accepted = b_.CreateNot(b_.CreateLoad(b_.getInt1Ty(), coverage_may_run));
  b_.CreateRet(select(accepted, b_.getInt32(2), b_.getInt32(0)));
  b_.SetInsertPoint(unknown_exit);
  b_.CreateRet(b_.getInt32(0));
  b_.SetInsertPoint(rejected_exit);
  b_.CreateRet(b_.getInt32(1));
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  return fn;
}

}  // namespace

llvm::Function* buildVerdictFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                     std::string& error) {
  IntervalCodegen g(module);
  return g.build(name, program, error);
}

}  // namespace pf
