// Setup programs to LLVM IR (see setup_codegen.h). Each case below is the batched
// interpreter's case of the same op (BatchSetupExecutor::runBatch, raster/setup_batch.cpp):
// read the two side by side.
#include "compiler/native/setup_codegen.h"

#include <cstddef>
#include <functional>
#include <map>
#include <vector>

#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include "compiler/native/lane_ops.h"

namespace pf {
namespace {

constexpr unsigned K = kNativeSetupLanes;

class SetupCodegen {
 public:
  SetupCodegen(llvm::Module& module, const NativeSetupVariant& variant)
      : module_(module), ctx_(module.getContext()), b_(module.getContext()), variant_(variant) {
    iv_ = llvm::FixedVectorType::get(b_.getInt32Ty(), K);
    fv_ = llvm::FixedVectorType::get(b_.getFloatTy(), K);
    mv_ = llvm::FixedVectorType::get(b_.getInt1Ty(), K);
  }

  llvm::Function* build(const std::string& name, const SetupProgram& program, std::string& error);

 private:
  // Registers, constants and parameters as the interpreter's lanesOf()/argOf() read them.
  llvm::Value* operand(uint32_t o);
  void setReg(uint32_t dst, llvm::Value* v);
  llvm::AllocaInst* xreg(uint32_t reg, int ch);
  void forChannels(uint16_t set, const std::function<void(int)>& fn) const;
  bool hasKinds(unsigned set) const;

  void emitInstruction(size_t pc, const Instr& in, std::map<size_t, llvm::BasicBlock*>& blocks);
  // Writes each batch lane's record from the registers (the program's end).
  void emitExports();
  // Stops before instruction `pc` (having run `executed` instructions): the interpreter goes on.
  void leave(size_t pc, llvm::Value* executed);
  // Ends the batch with every lane killed, `executed` instructions run.
  void kill(NativeSetupStatus status, llvm::Value* executed);
  // Stores `v` (a vector of 32-bit lanes) at args->field[row].
  void storeLanes(size_t field_offset, unsigned row, llvm::Value* v);
  llvm::Value* argAddress(size_t offset) { return b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), args_, offset); }
  llvm::Value* argField(size_t offset, llvm::Type* type) { return b_.CreateLoad(type, argAddress(offset)); }
  llvm::Value* gather(llvm::Value* pointers, llvm::Value* mask, llvm::Value* passthrough);
  llvm::Value* splatI(uint32_t v) { return b_.CreateVectorSplat(K, b_.getInt32(v)); }
  llvm::AllocaInst* entryAlloca(llvm::Type* t, const char* name) {
    llvm::IRBuilder<> at(entry_, entry_->begin());
    return at.CreateAlloca(t, nullptr, name);
  }

  llvm::Module& module_;
  llvm::LLVMContext& ctx_;
  llvm::IRBuilder<> b_;
  const NativeSetupVariant& variant_;
  const SetupProgram* program_ = nullptr;
  llvm::FixedVectorType* iv_;
  llvm::FixedVectorType* fv_;
  llvm::FixedVectorType* mv_;
  llvm::Function* fn_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  // Per instruction: the registers the interpreter may read going on from it (liveRegisters).
  std::vector<std::vector<bool>> live_in_;
  llvm::Value* args_ = nullptr;
  llvm::Value* regs_file_ = nullptr;
  llvm::Value* active_ = nullptr;       // i32: the batch's lanes
  llvm::Value* active_lanes_ = nullptr; // <K x i1>
  llvm::AllocaInst* count_ = nullptr;   // instructions run
  std::map<uint32_t, llvm::Value*> params_;  // each parameter read, gathered from the lanes' blocks at the start
  std::vector<llvm::AllocaInst*> regs_;
  std::map<std::pair<uint32_t, int>, llvm::AllocaInst*> xregs_;  // (interp register, channel)
};

// Which registers each instruction's execution may go on to read before writing them -- those a
// batch leaving before it must hand to the interpreter (the others' values are never read).
// Conservative: every register operand of every instruction is a use (an interp register's
// index counts too, as a register's), and only the value instructions, which write all of
// their destination, end a register's life; the end reads the exports. Backward, over Jmp's,
// JmpIfNot's and LoopBack's edges, to a fixed point.
std::vector<std::vector<bool>> liveRegisters(const SetupProgram& p) {
  const size_t n = p.code.size();
  const size_t regs = p.num_regs;
  std::vector<std::vector<bool>> in(n + 1, std::vector<bool>(regs, false));
  auto use = [&](std::vector<bool>& set, uint32_t o) {
    if (o != kNoOperand && operandKind(o) == OperandKind::Reg && operandIndex(o) < regs) set[operandIndex(o)] = true;
  };
  for (uint32_t o : p.scalar_exports) use(in[n], o);
  auto defines = [](Op op) {
    return isLaneValueOp(op) || op == Op::LoadParamAt || op == Op::LoadState || op == Op::HasKinds ||
           op == Op::HasNamed;
  };
  std::vector<bool> out(regs);
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t pc = n; pc-- > 0;) {
      const Instr& ins = p.code[pc];
      const size_t target = std::min<size_t>(ins.a, n);
      std::fill(out.begin(), out.end(), false);
      auto from = [&](size_t next) {
        for (size_t r = 0; r < regs; ++r) out[r] = out[r] || in[next][r];
      };
      switch (ins.op) {
        case Op::Jmp: from(target); break;
        case Op::JmpIfNot: from(pc + 1); from(target); break;
        case Op::LoopBack: from(target); break;
        case Op::Kill: break;
        default: from(pc + 1); break;
      }
      std::vector<bool> live = out;
      if (defines(ins.op) && ins.dst != kNoOperand && operandKind(ins.dst) == OperandKind::Reg &&
          operandIndex(ins.dst) < regs)
        live[operandIndex(ins.dst)] = false;
      else
        use(live, ins.dst);
      for (uint32_t o : {ins.a, ins.b, ins.c, ins.d}) use(live, o);
      if (live != in[pc]) {
        in[pc] = std::move(live);
        changed = true;
      }
    }
  }
  return in;
}

// What the interpreter cannot have either: operands past the program's registers (the
// compiler never writes them; the interpreter's file would read a constant there).
bool supports(const SetupProgram& p, std::string& why) {
  auto bad = [&](uint32_t o) {
    return o != kNoOperand && operandKind(o) == OperandKind::Reg && operandIndex(o) >= p.num_regs;
  };
  for (const Instr& in : p.code)
    if (isLaneValueOp(in.op) && (bad(in.dst) || bad(in.a) || bad(in.b) || bad(in.c) || bad(in.d))) {
      why = "an operand past the program's registers";
      return false;
    }
  return true;
}

llvm::Value* SetupCodegen::operand(uint32_t o) {
  if (o == kNoOperand) return splatI(0);
  const uint32_t i = operandIndex(o);
  switch (operandKind(o)) {
    case OperandKind::Reg: return i < regs_.size() ? b_.CreateLoad(iv_, regs_[i]) : splatI(0);
    case OperandKind::Const: return splatI(i < program_->constants.size() ? program_->constants[i] : 0u);
    case OperandKind::Param: {
      auto it = params_.find(i);
      return it != params_.end() ? it->second : splatI(0);
    }
    case OperandKind::Uniform: break;  // (setup programs have none)
  }
  return splatI(0);
}

void SetupCodegen::setReg(uint32_t dst, llvm::Value* v) {
  if (dst == kNoOperand || operandKind(dst) != OperandKind::Reg) return;
  const uint32_t i = operandIndex(dst);
  if (i < regs_.size()) b_.CreateStore(v, regs_[i]);
}

llvm::AllocaInst* SetupCodegen::xreg(uint32_t reg, int ch) {
  auto it = xregs_.find({reg, ch});
  if (it != xregs_.end()) return it->second;
  // (Past num_interp_regs or the layout's channels -- never in the compiler's output: a
  // variable of its own, zero at the start.)
  llvm::IRBuilder<> at(entry_, entry_->begin());
  llvm::AllocaInst* slot = at.CreateAlloca(fv_, nullptr, "x");
  at.CreateStore(llvm::Constant::getNullValue(fv_), slot);
  xregs_[{reg, ch}] = slot;
  return slot;
}

void SetupCodegen::forChannels(uint16_t set, const std::function<void(int)>& fn) const {
  for (int k = 0; k < 3; ++k)
    if (set & (1u << k))
      for (int c = variant_.kind_begin[k]; c < variant_.kind_end[k]; ++c) fn(c);
}

bool SetupCodegen::hasKinds(unsigned set) const {  // ChannelLayout::hasKinds
  for (int k = 0; k < 3; ++k)
    if ((set & (1u << k)) && variant_.kind_end[k] > variant_.kind_begin[k]) return true;
  return false;
}

llvm::Value* SetupCodegen::gather(llvm::Value* pointers, llvm::Value* mask, llvm::Value* passthrough) {
  return b_.CreateMaskedGather(passthrough->getType(), pointers, llvm::Align(4), mask, passthrough);
}

void SetupCodegen::storeLanes(size_t field_offset, unsigned row, llvm::Value* v) {
  b_.CreateAlignedStore(b_.CreateBitCast(v, iv_), argAddress(field_offset + row * K * sizeof(uint32_t)),
                        llvm::Align(4));
}

void SetupCodegen::leave(size_t pc, llvm::Value* executed) {
  b_.CreateStore(b_.getInt32(static_cast<uint32_t>(pc)), argAddress(offsetof(NativeSetupArgs, pc)));
  b_.CreateStore(executed, argAddress(offsetof(NativeSetupArgs, instructions)));
  // The registers the interpreter may read from here on, and every interp register, into its
  // lane-major files. (Each exit its own stores, no block shared by all: where every exit
  // branched to one, its phis of every register at every exit were most of the compile time.)
  const std::vector<bool>& live = live_in_[pc];
  for (uint32_t r = 0; r < regs_.size(); ++r)
    if (live[r])
      b_.CreateAlignedStore(b_.CreateLoad(iv_, regs_[r]),
                            b_.CreateConstInBoundsGEP1_64(b_.getInt32Ty(), regs_file_, uint64_t{r} * K), llvm::Align(4));
  llvm::Value* interp = argField(offsetof(NativeSetupArgs, interp), b_.getPtrTy());
  for (auto& [key, slot] : xregs_) {
    if (key.first >= program_->num_interp_regs) continue;  // (not the interpreter's)
    const uint64_t row = uint64_t{key.first} * static_cast<uint64_t>(variant_.channels) + static_cast<uint64_t>(key.second);
    b_.CreateAlignedStore(b_.CreateLoad(fv_, slot), b_.CreateConstInBoundsGEP1_64(b_.getFloatTy(), interp, row * K),
                          llvm::Align(4));
  }
  b_.CreateRet(b_.getInt32(static_cast<uint32_t>(NativeSetupStatus::Left)));
}

void SetupCodegen::kill(NativeSetupStatus status, llvm::Value* executed) {
  b_.CreateStore(executed, argAddress(offsetof(NativeSetupArgs, instructions)));
  b_.CreateRet(b_.getInt32(static_cast<uint32_t>(status)));
}

llvm::Function* SetupCodegen::build(const std::string& name, const SetupProgram& program, std::string& error) {
  if (!supports(program, error)) return nullptr;
  program_ = &program;
  auto* fn_type = llvm::FunctionType::get(b_.getInt32Ty(), {b_.getPtrTy()}, false);
  fn_ = llvm::Function::Create(fn_type, llvm::Function::ExternalLinkage, name, module_);
  args_ = fn_->getArg(0);
  args_->setName("args");
  fn_->addParamAttr(0, llvm::Attribute::NoAlias);
  entry_ = llvm::BasicBlock::Create(ctx_, "entry", fn_);
  b_.SetInsertPoint(entry_);
  live_in_ = liveRegisters(program);

  regs_file_ = argField(offsetof(NativeSetupArgs, regs), b_.getPtrTy());
  active_ = argField(offsetof(NativeSetupArgs, active), b_.getInt32Ty());
  active_lanes_ = b_.CreateBitCast(b_.CreateTrunc(active_, b_.getIntNTy(K)), mv_, "active_lanes");
  count_ = entryAlloca(b_.getInt32Ty(), "count");
  b_.CreateStore(b_.getInt32(0), count_);
  // Registers and interp registers start at zero, as the interpreter's file.
  for (uint32_t r = 0; r < program.num_regs; ++r) {
    regs_.push_back(entryAlloca(iv_, "r"));
    b_.CreateStore(splatI(0), regs_.back());
  }
  for (uint32_t r = 0; r < program.num_interp_regs; ++r)
    for (int c = 0; c < variant_.channels; ++c) {
      llvm::AllocaInst* slot = entryAlloca(fv_, "x");
      b_.CreateStore(llvm::Constant::getNullValue(fv_), slot);
      xregs_[{r, c}] = slot;
    }
  b_.CreateStore(b_.getInt32(0), argAddress(offsetof(NativeSetupArgs, loop_depth)));
  b_.CreateStore(b_.getInt32(0), argAddress(offsetof(NativeSetupArgs, has_bound)));
  b_.CreateStore(b_.getInt32(0), argAddress(offsetof(NativeSetupArgs, has_depth_bound)));
  b_.CreateStore(b_.getInt32(0), argAddress(offsetof(NativeSetupArgs, has_facing)));

  // The parameters the program reads, word k of each lane's block (lanes past the batch read
  // lane 0's, as the interpreter's file holds them).
  {
    auto* pv = llvm::FixedVectorType::get(b_.getPtrTy(), K);
    llvm::Value* blocks =
        b_.CreateAlignedLoad(pv, argAddress(offsetof(NativeSetupArgs, params)), llvm::Align(8), "param_blocks");
    auto read = [&](uint32_t o) {
      if (o == kNoOperand || operandKind(o) != OperandKind::Param || params_.count(operandIndex(o))) return;
      llvm::Value* at = b_.CreateInBoundsGEP(b_.getInt32Ty(), blocks, splatI(operandIndex(o)));
      params_[operandIndex(o)] = gather(at, llvm::Constant::getAllOnesValue(mv_), splatI(0));
    };
    for (const Instr& in : program.code)
      for (uint32_t o : {in.dst, in.a, in.b, in.c, in.d}) read(o);
    for (uint32_t o : program.scalar_exports) read(o);
  }

  // A block at every jump target and at the end.
  const std::vector<Instr>& code = program.code;
  std::map<size_t, llvm::BasicBlock*> blocks;
  auto blockAt = [&](size_t pc) {
    if (!blocks.count(pc)) blocks[pc] = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc), fn_);
  };
  for (const Instr& in : code)
    if (in.op == Op::Jmp || in.op == Op::JmpIfNot || in.op == Op::LoopBack) blockAt(std::min<size_t>(in.a, code.size()));
  blockAt(code.size());
  llvm::BasicBlock* first = llvm::BasicBlock::Create(ctx_, "start", fn_);
  b_.CreateBr(first);
  b_.SetInsertPoint(first);

  for (size_t pc = 0; pc < code.size(); ++pc) {
    auto it = blocks.find(pc);
    if (it != blocks.end()) {
      if (!b_.GetInsertBlock()->getTerminator()) b_.CreateBr(it->second);
      b_.SetInsertPoint(it->second);
    } else if (b_.GetInsertBlock()->getTerminator()) {
      b_.SetInsertPoint(llvm::BasicBlock::Create(ctx_, "after" + std::to_string(pc), fn_));
    }
    emitInstruction(pc, code[pc], blocks);
  }
  if (!b_.GetInsertBlock()->getTerminator()) b_.CreateBr(blocks.at(code.size()));

  // The end: each lane's record, as the interpreter's exports write it.
  b_.SetInsertPoint(blocks.at(code.size()));
  b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), count_), argAddress(offsetof(NativeSetupArgs, instructions)));
  emitExports();
  b_.CreateRet(b_.getInt32(static_cast<uint32_t>(NativeSetupStatus::Done)));

  return fn_;
}

void SetupCodegen::emitExports() {
  const SetupProgram& p = *program_;
  std::vector<llvm::Value*> scalars, channels;
  for (uint32_t o : p.scalar_exports) scalars.push_back(operand(o));
  for (uint32_t x : p.interp_exports)
    for (int c = 0; c < variant_.channels; ++c) channels.push_back(b_.CreateBitCast(b_.CreateLoad(fv_, xreg(x, c)), iv_));
  llvm::Type* i32 = b_.getInt32Ty();
  for (unsigned l = 0; l < K; ++l) {
    llvm::BasicBlock* lane = llvm::BasicBlock::Create(ctx_, "export" + std::to_string(l), fn_);
    llvm::BasicBlock* next = llvm::BasicBlock::Create(ctx_, "exported" + std::to_string(l), fn_);
    b_.CreateCondBr(b_.CreateICmpNE(b_.CreateAnd(active_, b_.getInt32(1u << l)), b_.getInt32(0)), lane, next);
    b_.SetInsertPoint(lane);
    llvm::Value* record = b_.CreateAlignedLoad(
        b_.getPtrTy(), argAddress(offsetof(NativeSetupArgs, records) + l * sizeof(void*)), llvm::Align(8));
    uint64_t word = 0;
    for (llvm::Value* v : scalars)
      b_.CreateAlignedStore(b_.CreateExtractElement(v, l), b_.CreateConstInBoundsGEP1_64(i32, record, word++),
                            llvm::Align(4));
    for (llvm::Value* v : channels)
      b_.CreateAlignedStore(b_.CreateExtractElement(v, l), b_.CreateConstInBoundsGEP1_64(i32, record, word++),
                            llvm::Align(4));
    b_.CreateBr(next);
    b_.SetInsertPoint(next);
  }
}

void SetupCodegen::emitInstruction(size_t pc, const Instr& in, std::map<size_t, llvm::BasicBlock*>& blocks) {
  llvm::Type* i32 = b_.getInt32Ty();
  llvm::Value* before = b_.CreateLoad(i32, count_);
  llvm::Value* after = b_.CreateAdd(before, b_.getInt32(1));
  b_.CreateStore(after, count_);
  auto target = [&](uint32_t a) { return blocks.at(std::min<size_t>(a, program_->code.size())); };
  auto fallthrough = [&]() { return llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc) + ".next", fn_); };
  if (isLaneValueOp(in.op)) {
    setReg(in.dst, emitLaneOp(b_, module_, in.op, operand(in.a), operand(in.b), operand(in.c), operand(in.d), in.imm));
    return;
  }
  switch (in.op) {
    case Op::Jmp: b_.CreateBr(target(in.a)); return;
    case Op::JmpIfNot: {
      // The lanes whose condition holds go on; all of them or none: one path. Else the lanes
      // part, and the interpreter splits them at this instruction.
      llvm::Value* holds = b_.CreateICmpNE(operand(in.b), splatI(0));
      llvm::Value* on = b_.CreateAnd(b_.CreateZExt(b_.CreateBitCast(holds, b_.getIntNTy(K)), i32), active_);
      llvm::BasicBlock* go_on = fallthrough();
      llvm::BasicBlock* not_all = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc) + ".some", fn_);
      llvm::BasicBlock* part = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc) + ".part", fn_);
      b_.CreateCondBr(b_.CreateICmpEQ(on, active_), go_on, not_all);
      b_.SetInsertPoint(not_all);
      b_.CreateCondBr(b_.CreateICmpEQ(on, b_.getInt32(0)), target(in.a), part);
      b_.SetInsertPoint(part);
      leave(pc, before);
      b_.SetInsertPoint(go_on);
      return;
    }
    case Op::Kill: kill(NativeSetupStatus::Killed, after); return;
    case Op::LoopBegin: {
      llvm::Value* depth_at = argAddress(offsetof(NativeSetupArgs, loop_depth));
      llvm::Value* depth = b_.CreateLoad(i32, depth_at);
      llvm::BasicBlock* deep = llvm::BasicBlock::Create(ctx_, "too_deep", fn_);
      llvm::BasicBlock* go_on = fallthrough();
      b_.CreateCondBr(b_.CreateICmpSGE(depth, b_.getInt32(kNativeSetupMaxLoops)), deep, go_on);
      b_.SetInsertPoint(deep);
      kill(NativeSetupStatus::Killed, after);
      b_.SetInsertPoint(go_on);
      llvm::Value* counter = b_.CreateInBoundsGEP(i32, argAddress(offsetof(NativeSetupArgs, loop_counters)), depth);
      b_.CreateStore(b_.getInt32(0), counter);
      b_.CreateStore(b_.CreateAdd(depth, b_.getInt32(1)), depth_at);
      return;
    }
    case Op::LoopBack: {
      llvm::Value* depth = argField(offsetof(NativeSetupArgs, loop_depth), i32);
      llvm::BasicBlock* open = llvm::BasicBlock::Create(ctx_, "loop_open", fn_);
      llvm::BasicBlock* capped = llvm::BasicBlock::Create(ctx_, "loop_capped", fn_);
      b_.CreateCondBr(b_.CreateICmpSGT(depth, b_.getInt32(0)), open, target(in.a));
      b_.SetInsertPoint(open);
      llvm::Value* counter = b_.CreateInBoundsGEP(i32, argAddress(offsetof(NativeSetupArgs, loop_counters)),
                                                  b_.CreateSub(depth, b_.getInt32(1)));
      llvm::Value* n = b_.CreateAdd(b_.CreateLoad(i32, counter), b_.getInt32(1));
      b_.CreateStore(n, counter);
      llvm::Value* cap = argField(offsetof(NativeSetupArgs, iteration_cap), b_.getInt64Ty());
      b_.CreateCondBr(b_.CreateICmpUGE(b_.CreateZExt(n, b_.getInt64Ty()), cap), capped, target(in.a));
      b_.SetInsertPoint(capped);
      kill(NativeSetupStatus::CapHit, after);
      return;
    }
    case Op::LoopEnd: {
      llvm::Value* depth_at = argAddress(offsetof(NativeSetupArgs, loop_depth));
      llvm::Value* depth = b_.CreateLoad(i32, depth_at);
      llvm::Value* open = b_.CreateICmpSGT(depth, b_.getInt32(0));
      b_.CreateStore(b_.CreateSelect(open, b_.CreateSub(depth, b_.getInt32(1)), depth), depth_at);
      return;
    }
    case Op::Bound: {
      const uint32_t from[4] = {in.a, in.b, in.c, in.dst};
      for (unsigned k = 0; k < 4; ++k) storeLanes(offsetof(NativeSetupArgs, bound), k, operand(from[k]));
      b_.CreateStore(b_.getInt32(1), argAddress(offsetof(NativeSetupArgs, has_bound)));
      return;
    }
    case Op::BackFacing:
      storeLanes(offsetof(NativeSetupArgs, back_facing), 0,
                 b_.CreateZExt(b_.CreateICmpNE(operand(in.a), splatI(0)), iv_));
      b_.CreateStore(b_.getInt32(1), argAddress(offsetof(NativeSetupArgs, has_facing)));
      return;
    case Op::DepthBound:
      storeLanes(offsetof(NativeSetupArgs, depth_bound), 0, operand(in.a));
      storeLanes(offsetof(NativeSetupArgs, depth_bound), 1, operand(in.b));
      b_.CreateStore(b_.getInt32(1), argAddress(offsetof(NativeSetupArgs, has_depth_bound)));
      return;
    case Op::LoadState: {
      llvm::Value* v = b_.getInt32(0);  // (0.0f)
      if (in.imm < kStateValueCount) {
        llvm::Value* values = argField(offsetof(NativeSetupArgs, state_values), b_.getPtrTy());
        v = b_.CreateLoad(i32, b_.CreateConstInBoundsGEP1_32(i32, values, in.imm));
      }
      setReg(in.dst, b_.CreateVectorSplat(K, v));
      return;
    }
    case Op::HasKinds: setReg(in.dst, splatI(hasKinds(in.imm) ? 1u : 0u)); return;
    case Op::HasNamed:
      setReg(in.dst, splatI(in.imm < variant_.named_bound.size() && variant_.named_bound[in.imm] ? 1u : 0u));
      return;
    case Op::LoadParamAt: {
      // Lane l: its block's word slot + imm, for a slot >= 0 inside the block; else 0.
      llvm::Value* slot = operand(in.a);
      auto* i64v = llvm::FixedVectorType::get(b_.getInt64Ty(), K);
      llvm::Value* at = b_.CreateAdd(b_.CreateSExt(slot, i64v), b_.CreateVectorSplat(K, b_.getInt64(in.imm)));
      llvm::Value* words = b_.CreateVectorSplat(K, argField(offsetof(NativeSetupArgs, param_words), b_.getInt64Ty()));
      llvm::Value* inside = b_.CreateAnd(b_.CreateICmpSGE(slot, splatI(0)), b_.CreateICmpSLT(at, words));
      auto* pv = llvm::FixedVectorType::get(b_.getPtrTy(), K);
      llvm::Value* blocks_at = b_.CreateAlignedLoad(pv, argAddress(offsetof(NativeSetupArgs, params)), llvm::Align(8));
      llvm::Value* pointers = b_.CreateInBoundsGEP(i32, blocks_at, at);
      setReg(in.dst, gather(pointers, b_.CreateAnd(inside, active_lanes_), splatI(0)));
      return;
    }
    case Op::XLoadVertex: case Op::XLoadVertexAt: {
      // Lane l of the batch: sequence point imm's (or a's, when inside; else zeros) channels;
      // lanes past the batch keep what they held.
      auto* pv = llvm::FixedVectorType::get(b_.getPtrTy(), K);
      llvm::Value* vertices =
          b_.CreateAlignedLoad(pv, argAddress(offsetof(NativeSetupArgs, vertex_channels)), llvm::Align(8));
      auto* i64v = llvm::FixedVectorType::get(b_.getInt64Ty(), K);
      const int nch = variant_.channels;
      llvm::Value* point = nullptr;
      llvm::Value* load_lanes = active_lanes_;
      if (in.op == Op::XLoadVertex) {
        point = b_.CreateVectorSplat(K, b_.getInt64(in.imm));
      } else {
        llvm::Value* i = operand(in.a);
        llvm::Value* points = b_.CreateVectorSplat(K, argField(offsetof(NativeSetupArgs, sequence_points), i32));
        llvm::Value* inside = b_.CreateAnd(b_.CreateICmpSGE(i, splatI(0)), b_.CreateICmpSLT(i, points));
        load_lanes = b_.CreateAnd(inside, active_lanes_);
        point = b_.CreateSExt(i, i64v);
      }
      llvm::Value* base = b_.CreateMul(point, b_.CreateVectorSplat(K, b_.getInt64(static_cast<uint64_t>(nch))));
      const uint32_t dst = operandIndex(in.dst);
      for (int c = 0; c < nch; ++c) {
        llvm::AllocaInst* d = xreg(dst, c);
        llvm::Value* old = b_.CreateLoad(fv_, d);
        llvm::Value* index = b_.CreateAdd(base, b_.CreateVectorSplat(K, b_.getInt64(static_cast<uint64_t>(c))));
        llvm::Value* pointers = b_.CreateInBoundsGEP(b_.getFloatTy(), vertices, index);
        llvm::Value* passthrough =
            in.op == Op::XLoadVertex ? old : b_.CreateSelect(active_lanes_, llvm::Constant::getNullValue(fv_), old);
        b_.CreateStore(gather(pointers, load_lanes, passthrough), d);
      }
      return;
    }
    case Op::XSel: {
      llvm::Value* s = b_.CreateICmpNE(operand(in.a), splatI(0));
      forChannels(in.imm, [&](int c) {
        llvm::Value* x = b_.CreateLoad(fv_, xreg(operandIndex(in.b), c));
        llvm::Value* y = b_.CreateLoad(fv_, xreg(operandIndex(in.c), c));
        b_.CreateStore(b_.CreateSelect(s, x, y), xreg(operandIndex(in.dst), c));
      });
      return;
    }
    case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
      llvm::Value* scale = nullptr;
      if (in.op == Op::XMulF || in.op == Op::XDivF) scale = b_.CreateBitCast(operand(in.b), fv_);
      forChannels(in.imm, [&](int c) {
        llvm::Value* a = b_.CreateLoad(fv_, xreg(operandIndex(in.a), c));
        llvm::Value* r = a;
        switch (in.op) {
          case Op::XAdd: r = b_.CreateFAdd(a, b_.CreateLoad(fv_, xreg(operandIndex(in.b), c))); break;
          case Op::XSub: r = b_.CreateFSub(a, b_.CreateLoad(fv_, xreg(operandIndex(in.b), c))); break;
          case Op::XMulF: r = b_.CreateFMul(a, scale); break;
          case Op::XDivF: r = b_.CreateFDiv(a, scale); break;
          case Op::XNeg: r = b_.CreateFNeg(a); break;
          default: break;
        }
        b_.CreateStore(r, xreg(operandIndex(in.dst), c));
      });
      return;
    }
    default:
      // Not run here (calls of other primitives; anything a setup program should not hold):
      // the interpreter goes on from this instruction, which has not run.
      leave(pc, before);
      return;
  }
}

}  // namespace

llvm::Function* buildSetupFunction(llvm::Module& module, const std::string& name, const SetupProgram& program,
                                   const NativeSetupVariant& variant, std::string& error) {
  SetupCodegen g(module, variant);
  return g.build(name, program, error);
}

}  // namespace pf
