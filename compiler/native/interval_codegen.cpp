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
  IntervalCodegen(llvm::Module& m, unsigned lanes)
      : module_(m), ctx_(m.getContext()), b_(m.getContext()), lanes_(lanes),
        double_(lanes == 1 ? b_.getDoubleTy() : static_cast<llvm::Type*>(llvm::FixedVectorType::get(b_.getDoubleTy(), lanes))),
        bool_(lanes == 1 ? b_.getInt1Ty() : static_cast<llvm::Type*>(llvm::FixedVectorType::get(b_.getInt1Ty(), lanes))) {}

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

  // A double or a truth value, as one value or one per lane (a region each).
  llvm::Value* d(double v) { return llvm::ConstantFP::get(double_, v); }
  llvm::Value* yes() { return llvm::ConstantInt::get(bool_, 1); }
  llvm::Value* no() { return llvm::ConstantInt::get(bool_, 0); }
  // A value the same in every region (a uniform's, a constant's), as the walk's type.
  llvm::Value* everywhere(llvm::Value* scalar) { return lanes_ == 1 ? scalar : b_.CreateVectorSplat(lanes_, scalar); }
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
  Range unknown() { return {d(-kInf), d(kInf), yes()}; }
  Range unknownBool() { return {d(0.0), d(1.0), no()}; }

  Range widen(llvm::Value* lo, llvm::Value* hi) {
    llvm::Value* bad = b_.CreateOr(isnan(lo), isnan(hi));
    const double tiny = 1.2e-38;
    llvm::Value* wlo = b_.CreateFSub(lo, b_.CreateFAdd(b_.CreateFMul(fabs(lo), d(0x1p-22)), d(tiny)));
    llvm::Value* whi = b_.CreateFAdd(hi, b_.CreateFAdd(b_.CreateFMul(fabs(hi), d(0x1p-22)), d(tiny)));
    return pick(bad, unknown(), Range{wlo, whi, no()});
  }
  Range point(llvm::Value* v) { return pick(isnan(v), unknown(), Range{v, v, no()}); }
  Range boolean(llvm::Value* can_false, llvm::Value* can_true) {
    return {select(can_false, d(0.0), d(1.0)), select(can_true, d(1.0), d(0.0)), no()};
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
    return {b_.CreateLoad(double_, s.lo), b_.CreateLoad(double_, s.hi), b_.CreateLoad(bool_, s.nan)};
  }
  void store(const Slot& s, const Range& r) {
    b_.CreateStore(r.lo, s.lo);
    b_.CreateStore(r.hi, s.hi);
    b_.CreateStore(r.nan, s.nan);
  }
  Slot slot(llvm::IRBuilder<>& at) {
    return {at.CreateAlloca(double_), at.CreateAlloca(double_), at.CreateAlloca(bool_)};
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
      case As::Float: return point(everywhere(b_.CreateFPExt(b_.CreateBitCast(bits, b_.getFloatTy()), b_.getDoubleTy())));
      case As::Int: return point(everywhere(b_.CreateSIToFP(bits, b_.getDoubleTy())));
      case As::Bool: return point(select(b_.CreateICmpNE(bits, b_.getInt32(0)), d(1.0), d(0.0)));
      case As::Any: return unknown();
    }
    return unknown();
  }
  Range value(const Instr& in);

  llvm::Module& module_;
  llvm::LLVMContext& ctx_;
  llvm::IRBuilder<> b_;
  const unsigned lanes_;      // regions walked at once: 1 (a NativeVerdictFunction) or more
  llvm::Type* const double_;  // double, or a vector of lanes_ doubles
  llvm::Type* const bool_;    // i1, or a vector of lanes_
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
      Range r = in.op == Op::FMin ? Range{min(a.lo, b.lo), min(a.hi, b.hi), no()}
                                  : Range{max(a.lo, b.lo), max(a.hi, b.hi), no()};
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
      return in.op == Op::BAnd ? Range{min(a.lo, b.lo), min(a.hi, b.hi), no()}
                               : Range{max(a.lo, b.lo), max(a.hi, b.hi), no()};
    }
    case Op::BNot: {
      const Range a = bv(in.a);
      return {b_.CreateFSub(d(1.0), a.hi), b_.CreateFSub(d(1.0), a.lo), no()};
    }
    case Op::IAdd: case Op::ISub: case Op::IMul: {
      const Range a = iv(in.a), b = iv(in.b);
      Range s = in.op == Op::IAdd ? add(a, b) : in.op == Op::ISub ? add(a, negate(b)) : mul(a, b);
      llvm::Value* fits = b_.CreateAnd(b_.CreateFCmpOGE(s.lo, d(-2147483648.0)), b_.CreateFCmpOLE(s.hi, d(2147483647.0)));
      Range r{b_.CreateUnaryIntrinsic(llvm::Intrinsic::ceil, b_.CreateFSub(s.lo, d(0.5))),
              b_.CreateUnaryIntrinsic(llvm::Intrinsic::floor, b_.CreateFAdd(s.hi, d(0.5))), no()};
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
      return pick(s.nan, unknown(), Range{lo, hi, no()});
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
      return point(everywhere(b_.CreateFPExt(l, b_.getDoubleTy())));
    }
    default: return unknown();  // Z tests, fields, noise, the rest
  }
}

llvm::Function* IntervalCodegen::build(const std::string& name, const PixelProgram& p, std::string& error) {
  if (!nativeVerdictSupports(p, &error)) return nullptr;
  MaskFrames frames;
  if (!findMaskFrames(p.code, frames, error)) return nullptr;
  program_ = &p;
  const bool scalar = lanes_ == 1;
  llvm::Type* ptr = b_.getPtrTy();
  auto* type = scalar ? llvm::FunctionType::get(b_.getInt32Ty(), {ptr, ptr, ptr}, false)
                      : llvm::FunctionType::get(b_.getVoidTy(), {ptr, ptr, ptr, ptr}, false);
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
  llvm::AllocaInst* coverage_may_run = at.CreateAlloca(bool_);
  // Several regions at once: a region whose walk has ended -- rejected, or undecided (at a
  // loop, a jump it cannot decide, or a jump the others take and it does not) -- stays in the
  // vectors, its lanes no longer written and their results unused.
  llvm::AllocaInst* rejected = scalar ? nullptr : at.CreateAlloca(bool_);
  llvm::AllocaInst* undecided = scalar ? nullptr : at.CreateAlloca(bool_);
  for (const Slot& s : regs_) store(s, unknown());
  b_.CreateStore(llvm::ConstantInt::get(bool_, p.last_coverage_retire < 0 ? 1 : 0), coverage_may_run);
  if (!scalar) {
    b_.CreateStore(no(), rejected);
    b_.CreateStore(no(), undecided);
  }
  if (p.num_regs > kRegY) {
    // The regions' bounds: x_lo, x_hi, y_lo, y_hi, each one double per region.
    auto region_at = [&](int k) {
      return b_.CreateAlignedLoad(double_, b_.CreateConstInBoundsGEP1_32(b_.getDoubleTy(), region, k * lanes_),
                                  llvm::Align(8));
    };
    store(regs_[kRegX], Range{region_at(0), region_at(1), no()});
    store(regs_[kRegY], Range{region_at(2), region_at(3), no()});
  }

  const size_t n = std::min(p.code.size(), static_cast<size_t>(p.last_early_retire) + 1);
  const size_t coverage_end = p.last_coverage_retire >= 0 ? static_cast<size_t>(p.last_coverage_retire) + 1 : 0;
  std::vector<llvm::BasicBlock*> at_pc(n + 1);
  for (size_t pc = 0; pc <= n; ++pc) at_pc[pc] = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc), fn);
  llvm::BasicBlock* unknown_exit = scalar ? llvm::BasicBlock::Create(ctx_, "unknown", fn) : nullptr;
  llvm::BasicBlock* rejected_exit = scalar ? llvm::BasicBlock::Create(ctx_, "rejected", fn) : nullptr;
  b_.CreateBr(at_pc[0]);
  auto target = [&](uint32_t t) { return at_pc[std::min<size_t>(t, n)]; };
  auto addTo = [&](llvm::AllocaInst* set, llvm::Value* lanes) {
    b_.CreateStore(b_.CreateOr(b_.CreateLoad(bool_, set), lanes), set);
  };

  for (size_t pc = 0; pc < n; ++pc) {
    b_.SetInsertPoint(at_pc[pc]);
    const Instr& in = p.code[pc];
    if (!frames.reached[pc]) {
      b_.CreateBr(at_pc[pc + 1]);
      continue;
    }
    // live: no frame certainly excludes every lane; certain: every frame certainly includes all.
    const int depth = static_cast<int>(frames.at[pc].size());
    llvm::Value* live = yes();
    llvm::Value* certain = yes();
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
    // What follows runs only where some lane is live -- of a region whose walk goes on.
    // strays: regions going on where no lane is live (a jump they do not take ends them).
    llvm::Value* active = live;
    llvm::Value* strays = nullptr;
    if (!scalar) {
      llvm::Value* ended = b_.CreateOr(b_.CreateLoad(bool_, rejected), b_.CreateLoad(bool_, undecided));
      active = b_.CreateAnd(live, b_.CreateNot(ended));
      strays = b_.CreateNot(b_.CreateOr(active, ended));
    }
    llvm::BasicBlock* run = llvm::BasicBlock::Create(ctx_, "live", fn);
    b_.CreateCondBr(scalar ? live : b_.CreateOrReduce(active), run, next);
    b_.SetInsertPoint(run);
    switch (in.op) {
      case Op::Retire: {
        if (pc + 1 <= coverage_end) addTo(coverage_may_run, active);
        if (scalar) {
          b_.CreateCondBr(certain, rejected_exit, next);
        } else {
          addTo(rejected, b_.CreateAnd(active, certain));
          llvm::Value* ended = b_.CreateOr(b_.CreateLoad(bool_, rejected), b_.CreateLoad(bool_, undecided));
          b_.CreateCondBr(b_.CreateAndReduce(ended), at_pc[n], next);
        }
        continue;
      }
      case Op::Jmp:
        if (!scalar) addTo(undecided, strays);
        b_.CreateBr(target(in.a));
        continue;
      case Op::JmpIfNot: {
        const Range c = read(in.b, As::Bool);
        if (scalar) {
          llvm::BasicBlock* maybe = llvm::BasicBlock::Create(ctx_, "maybe", fn);
          b_.CreateCondBr(certainlyFalse(c), target(in.a), maybe);
          b_.SetInsertPoint(maybe);
          b_.CreateCondBr(certainlyTrue(c), next, unknown_exit);
          continue;
        }
        // The regions that certainly jump decide the way (if there are any); the others end.
        llvm::Value* jumps = b_.CreateAnd(active, certainlyFalse(c));
        llvm::Value* falls = b_.CreateAnd(active, certainlyTrue(c));
        addTo(undecided, b_.CreateAnd(active, b_.CreateNot(b_.CreateOr(jumps, falls))));
        llvm::BasicBlock* jump = llvm::BasicBlock::Create(ctx_, "jump", fn);
        b_.CreateCondBr(b_.CreateOrReduce(jumps), jump, next);
        b_.SetInsertPoint(jump);
        addTo(undecided, b_.CreateOr(falls, strays));
        b_.CreateBr(target(in.a));
        continue;
      }
      case Op::LoopBegin: case Op::LoopTest: case Op::Break: case Op::Continue: case Op::LoopContinue:
      case Op::LoopBack: case Op::LoopEnd:
        if (scalar) {
          b_.CreateBr(unknown_exit);
        } else {
          addTo(undecided, active);
          b_.CreateBr(next);
        }
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
      // (Where no lane of a region is live its register keeps its range; a region whose walk
      // has ended may take any -- it is not read again -- so values the same in every region
      // stay so, and LLVM computes them once rather than per lane.)
      if (!scalar && depth > 0) r = pick(live, r, load(dst));
      store(dst, r);
    }
    b_.CreateBr(next);
  }
  b_.SetInsertPoint(at_pc[n]);
  llvm::Value* accepted = no();
  if (p.covered) accepted = b_.CreateNot(b_.CreateLoad(bool_, coverage_may_run));
  if (scalar) {
    b_.CreateRet(select(accepted, b_.getInt32(2), b_.getInt32(0)));
    b_.SetInsertPoint(unknown_exit);
    b_.CreateRet(b_.getInt32(0));
    b_.SetInsertPoint(rejected_exit);
    b_.CreateRet(b_.getInt32(1));
  } else {
    llvm::Type* bytes = llvm::FixedVectorType::get(b_.getInt8Ty(), lanes_);
    auto v = [&](int k) { return llvm::ConstantInt::get(bytes, k); };
    llvm::Value* verdicts =
        select(b_.CreateLoad(bool_, rejected), v(1),
               select(b_.CreateLoad(bool_, undecided), v(0), select(accepted, v(2), v(0))));
    b_.CreateAlignedStore(verdicts, fn->getArg(3), llvm::Align(1));
    b_.CreateRetVoid();
  }
  fn->addFnAttr(llvm::Attribute::NoUnwind);
  return fn;
}

}  // namespace

llvm::Function* buildVerdictFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                     std::string& error) {
  IntervalCodegen g(module, 1);
  return g.build(name, program, error);
}

llvm::Function* buildBlockVerdictsFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                           int lanes, std::string& error) {
  IntervalCodegen g(module, static_cast<unsigned>(lanes));
  return g.build(name, program, error);
}

}  // namespace pf
