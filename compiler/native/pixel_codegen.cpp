// Pixel programs to LLVM IR (see pixel_codegen.h): the function's chunk loop, and each
// program's instructions -- the cases of PixelExecutor::execute, one for one, with the lane
// masks as vectors of i1 and every register a variable that LLVM's mem2reg turns into SSA.
#include "compiler/native/pixel_codegen.h"

#include <cstddef>
#include <atomic>
#include <functional>

#include <llvm/IR/Function.h>
#include <llvm/IR/Intrinsics.h>

#include "compiler/native/lane_ops.h"
#include "compiler/native/pixel_codegen_impl.h"

namespace pf {

namespace {
std::atomic<NativeFault> fault_for_testing{NativeFault::None};
}  // namespace

void setNativeFaultForTesting(NativeFault fault) { fault_for_testing.store(fault); }
NativeFault nativeFaultForTesting() { return fault_for_testing.load(); }

bool nativePixelSupports(const PixelProgram& program, std::string* why) {
  for (const Instr& in : program.code)
    if (in.op == Op::FieldBox || in.op == Op::FieldHit || in.op == Op::FieldGradient || in.op == Op::FieldColor) {
      if (why) *why = "it evaluates a field (field_hit / field_gradient / field_color run the field's evaluators on the block)";
      return false;
    }
  return true;
}

llvm::Function* buildPixelFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                   const NativePixelVariant& variant, std::string& error) {
  if (!nativePixelSupports(program, &error)) return nullptr;
  for (const NativePixelVariant::Shared& s : variant.shared)
    if (s.named_index < 0 && (!s.pixel || !nativePixelSupports(*s.pixel, &error))) {
      if (!s.pixel) error = "a shared interpolator without a program";
      return nullptr;
    }
  PixelCodegen g(module, variant, nativeFaultForTesting());
  return g.build(name, program, error);
}

PixelCodegen::PixelCodegen(llvm::Module& module, const NativePixelVariant& variant, NativeFault fault)
    : fault_(fault),
      module_(module),
      ctx_(module.getContext()),
      b_(module.getContext()),
      variant_(variant),
      width_(static_cast<unsigned>(nativeVectorWidth(variant.isa))) {
  iv_ = llvm::FixedVectorType::get(b_.getInt32Ty(), width_);
  fv_ = llvm::FixedVectorType::get(b_.getFloatTy(), width_);
  mv_ = llvm::FixedVectorType::get(b_.getInt1Ty(), width_);
}

llvm::AllocaInst* PixelCodegen::entryAlloca(llvm::Type* t, const char* name) {
  llvm::IRBuilder<> at(entry_, entry_->begin());
  return at.CreateAlloca(t, nullptr, name);
}

llvm::Value* PixelCodegen::argField(size_t offset, llvm::Type* type, const char* name) {
  llvm::Value* p = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), args_, offset);
  return b_.CreateLoad(type, p, name);
}

llvm::Value* PixelCodegen::invariantLoad(llvm::Type* t, llvm::Value* ptr) {
  // (Memory outside the function guarantees 4-byte alignment only.)
  llvm::LoadInst* l = b_.CreateAlignedLoad(t, ptr, llvm::Align(t->isPointerTy() ? 8 : 4));
  l->setMetadata(llvm::LLVMContext::MD_invariant_load, llvm::MDNode::get(ctx_, {}));
  return l;
}

llvm::Function* PixelCodegen::build(const std::string& name, const PixelProgram& program, std::string& error) {
  auto* fn_type = llvm::FunctionType::get(b_.getInt64Ty(), {b_.getPtrTy()}, false);
  fn_ = llvm::Function::Create(fn_type, llvm::Function::ExternalLinkage, name, module_);
  args_ = fn_->getArg(0);
  args_->setName("args");
  fn_->addParamAttr(0, llvm::Attribute::NoAlias);
  entry_ = llvm::BasicBlock::Create(ctx_, "entry", fn_);
  b_.SetInsertPoint(entry_);

  // The programs, checked before anything is emitted: the primitive's and the interpolators'.
  Env prim;
  prim.program = &program;
  prim.channels = variant_.channels;
  prim.wide_record = variant_.gang;
  if (!prepare(prim, error)) return nullptr;

  llvm::Type* ptr = b_.getPtrTy();
  llvm::Type* i32 = b_.getInt32Ty();
  record_ = argField(offsetof(NativeBlockArgs, record), ptr, "record");
  shared_records_ = argField(offsetof(NativeBlockArgs, shared_records), ptr, "shared_records");
  lane_x_ = argField(offsetof(NativeBlockArgs, lane_x), ptr, "lane_x");
  lane_y_ = argField(offsetof(NativeBlockArgs, lane_y), ptr, "lane_y");
  depth_ = argField(offsetof(NativeBlockArgs, depth), ptr, "depth");
  state_values_ = argField(offsetof(NativeBlockArgs, state_values), ptr, "state_values");
  shade_ids_ = argField(offsetof(NativeBlockArgs, shade_ids), ptr, "shade_ids");
  planes_ = argField(offsetof(NativeBlockArgs, planes), ptr, "planes");
  surface_planes_ = argField(offsetof(NativeBlockArgs, surface_planes), ptr, "surface_planes");
  llvm::Value* mask = argField(offsetof(NativeBlockArgs, mask), b_.getInt64Ty(), "mask");
  bx_ = argField(offsetof(NativeBlockArgs, bx), i32, "bx");
  by_ = argField(offsetof(NativeBlockArgs, by), i32, "by");
  depth_stride_ = argField(offsetof(NativeBlockArgs, depth_stride), i32, "depth_stride");
  tile_x0_ = argField(offsetof(NativeBlockArgs, tile_x0), i32, "tile_x0");
  tile_y0_ = argField(offsetof(NativeBlockArgs, tile_y0), i32, "tile_y0");
  shade_id_ = argField(offsetof(NativeBlockArgs, shade_id), i32, "shade_id");
  iteration_cap_ = argField(offsetof(NativeBlockArgs, iteration_cap), i32, "iteration_cap");
  depth_pass_ = argField(offsetof(NativeBlockArgs, depth_pass), i32, "depth_pass");
  clip_planes_ = argField(offsetof(NativeBlockArgs, clip_planes), ptr, "clip_planes");
  clip_count_ = argField(offsetof(NativeBlockArgs, clip_plane_count), i32, "clip_plane_count");
  polygon_stipple_ = argField(offsetof(NativeBlockArgs, polygon_stipple), ptr, "polygon_stipple");
  depth_write_ = b_.CreateICmpNE(argField(offsetof(NativeBlockArgs, depth_write), i32, "depth_write"), b_.getInt32(0));
  has_depth_ = b_.CreateICmpNE(depth_, llvm::ConstantPointerNull::get(b_.getPtrTy()), "has_depth");
  packed_ = variant_.gang ? b_.getTrue() : b_.CreateICmpNE(lane_x_, llvm::ConstantPointerNull::get(b_.getPtrTy()), "packed");
  prim.record = record_;

  for (int ch = 0; ch < variant_.channels; ++ch) staging_.push_back(entryAlloca(iv_, "staging"));
  for (int k = 0; k < 8; ++k) surface_.push_back(entryAlloca(iv_, "surface"));
  llvm::AllocaInst* chunk_slot = entryAlloca(i32, "chunk");
  llvm::AllocaInst* result_slot = entryAlloca(b_.getInt64Ty(), "committed");
  b_.CreateStore(b_.getInt32(0), chunk_slot);
  b_.CreateStore(b_.getInt64(0), result_slot);

  // for (chunk = 0; chunk < 64 / W; ++chunk): the chunk's lanes of `mask`, if any, run.
  llvm::BasicBlock* head = llvm::BasicBlock::Create(ctx_, "chunk.head", fn_);
  llvm::BasicBlock* check = llvm::BasicBlock::Create(ctx_, "chunk.check", fn_);
  llvm::BasicBlock* body = llvm::BasicBlock::Create(ctx_, "chunk.body", fn_);
  llvm::BasicBlock* commit_block = llvm::BasicBlock::Create(ctx_, "chunk.commit", fn_);
  llvm::BasicBlock* next = llvm::BasicBlock::Create(ctx_, "chunk.next", fn_);
  llvm::BasicBlock* exit = llvm::BasicBlock::Create(ctx_, "exit", fn_);
  b_.CreateBr(head);

  b_.SetInsertPoint(head);
  chunk_ = b_.CreateLoad(i32, chunk_slot, "c");
  b_.CreateCondBr(b_.CreateICmpULT(chunk_, b_.getInt32(kNativeLanes / width_)), check, exit);

  b_.SetInsertPoint(check);
  first_lane_ = b_.CreateMul(chunk_, b_.getInt32(width_), "first_lane");
  llvm::Value* bits = b_.CreateLShr(mask, b_.CreateZExt(first_lane_, b_.getInt64Ty()));
  llvm::Value* chunk_bits = b_.CreateTrunc(bits, b_.getIntNTy(width_));
  b_.CreateCondBr(b_.CreateICmpEQ(chunk_bits, b_.getIntN(width_, 0)), next, body);

  b_.SetInsertPoint(body);
  llvm::Value* in_mask = b_.CreateBitCast(chunk_bits, mv_, "in_mask");
  pixelCoordinates(x_, y_);
  for (int ch = 0; ch < variant_.channels; ++ch) b_.CreateStore(splatI(0), staging_[static_cast<size_t>(ch)]);
  for (llvm::AllocaInst* s : surface_) b_.CreateStore(splatI(0), s);
  prim.dead = next;
  prim.done = commit_block;
  startProgram(prim, in_mask, nullptr);
  emitProgram(prim);

  b_.SetInsertPoint(commit_block);
  llvm::Value* alive = b_.CreateLoad(mv_, prim.alive, "alive");
  commit(fault_ == NativeFault::CommitWithoutMask ? allLanes(true) : alive);
  llvm::Value* alive_bits = b_.CreateZExt(b_.CreateBitCast(alive, b_.getIntNTy(width_)), b_.getInt64Ty());
  llvm::Value* shifted = b_.CreateShl(alive_bits, b_.CreateZExt(first_lane_, b_.getInt64Ty()));
  b_.CreateStore(b_.CreateOr(b_.CreateLoad(b_.getInt64Ty(), result_slot), shifted), result_slot);
  b_.CreateBr(next);

  b_.SetInsertPoint(next);
  b_.CreateStore(b_.CreateAdd(b_.CreateLoad(i32, chunk_slot), b_.getInt32(1)), chunk_slot);
  b_.CreateBr(head);

  b_.SetInsertPoint(exit);
  b_.CreateRet(b_.CreateLoad(b_.getInt64Ty(), result_slot));
  return fn_;
}

// The program's frames and variables (allocated in the entry block, so that mem2reg promotes
// them): one per register, two masks, three per nesting level.
bool PixelCodegen::prepare(Env& env, std::string& error) {
  if (!findMaskFrames(env.program->code, env.frames, error)) return false;
  for (uint32_t r = 0; r < env.program->num_regs; ++r) env.regs.push_back(entryAlloca(iv_, "v"));
  env.alive = entryAlloca(mv_, "alive");
  env.cur = entryAlloca(mv_, "cur");
  for (int d = 0; d < env.frames.max_depth; ++d) {
    env.saved.push_back(entryAlloca(mv_, "saved"));
    env.cond.push_back(entryAlloca(mv_, "cond"));
    env.iterations.push_back(entryAlloca(b_.getInt32Ty(), "iterations"));
  }
  if (env.interpolator)
    for (int k = 0; k < 4; ++k) env.shade_out.push_back(entryAlloca(iv_, "shade_out"));
  // Every interpolator register, for each channel.
  for (uint32_t r = 0; r < env.program->num_interp_regs; ++r)
    for (int ch = 0; ch < env.channels; ++ch) env.xregs[{r, ch}] = entryAlloca(iv_, "x");
  return true;
}

// A program's start: registers zero (the interpreter's hold stale lanes no program reads;
// zeros keep LLVM from reasoning about undefined ones), the built-ins, the masks.
void PixelCodegen::startProgram(Env& env, llvm::Value* in_mask, llvm::Value* const* p_in) {
  for (llvm::AllocaInst* r : env.regs) b_.CreateStore(splatI(0), r);
  for (auto& [key, slot] : env.xregs) b_.CreateStore(splatI(0), slot);
  auto set = [&](uint32_t reg, llvm::Value* v) {
    if (reg < env.regs.size()) b_.CreateStore(v, env.regs[reg]);
  };
  set(kRegX, x_);
  set(kRegY, y_);
  // Z: the depth under each lane, for a primitive drawn with a depth buffer; else 0.
  set(kRegZ, env.interpolator ? splatI(0) : loadDepth(in_mask));
  if (env.program->reads_surface || p_in)
    for (int k = 0; k < 4; ++k)
      set(kRegP + static_cast<uint32_t>(k),
          p_in ? p_in[k] : splatI(k == 3 ? 0x3f800000u : 0u));
  if (env.interpolator)
    for (llvm::AllocaInst* s : env.shade_out) b_.CreateStore(splatI(0), s);
  b_.CreateStore(in_mask, env.alive);
  b_.CreateStore(allLanes(true), env.cur);
}

void PixelCodegen::emitProgram(Env& env) {
  const std::vector<Instr>& code = env.program->code;
  // A block starts at every jump target and after every jump.
  std::map<size_t, llvm::BasicBlock*> blocks;
  auto leader = [&](size_t pc) {
    if (!blocks.count(pc)) blocks[pc] = llvm::BasicBlock::Create(ctx_, "pc" + std::to_string(pc), fn_);
  };
  for (size_t pc = 0; pc < code.size(); ++pc) {
    const Op op = code[pc].op;
    if (op == Op::Jmp || op == Op::JmpIfNot || op == Op::JmpIfNone || op == Op::LoopBack) {
      leader(code[pc].a);
      leader(pc + 1);
    }
  }
  if (!blocks.count(code.size())) blocks[code.size()] = env.done;
  llvm::BasicBlock* start = llvm::BasicBlock::Create(ctx_, "program", fn_);
  b_.CreateBr(start);
  b_.SetInsertPoint(start);
  bool open = true;  // the current block has no terminator yet
  for (size_t pc = 0; pc <= code.size(); ++pc) {
    auto it = blocks.find(pc);
    if (it != blocks.end()) {
      if (open) b_.CreateBr(it->second);
      if (it->second == env.done) break;
      b_.SetInsertPoint(it->second);
      open = true;
    }
    if (pc == code.size()) {
      if (open) b_.CreateBr(env.done);
      break;
    }
    if (!open || !env.frames.reached[pc]) {
      // Never run: a block that only leads on (LLVM deletes it).
      if (open) {
        b_.CreateBr(env.done);
        open = false;
      }
      continue;
    }
    emitInstruction(env, pc, code[pc], blocks);
    open = b_.GetInsertBlock()->getTerminator() == nullptr;
  }
  // Blocks left without a terminator (targets past a jump that is never run) lead to the end.
  for (auto& [pc, block] : blocks)
    if (block != env.done && !block->getTerminator()) {
      llvm::IRBuilder<> at(block);
      at.CreateBr(env.done);
    }
}

void PixelCodegen::emitInstruction(Env& env, size_t pc, const Instr& in, std::map<size_t, llvm::BasicBlock*>& blocks) {
  const std::vector<MaskFrameKind>& frames = env.frames.at[pc];
  const int depth = static_cast<int>(frames.size());
  auto continueIn = [&](const char* name) { return llvm::BasicBlock::Create(ctx_, name, fn_); };
  auto mask = [&](llvm::AllocaInst* slot) { return b_.CreateLoad(mv_, slot); };
  auto nonzero = [&](llvm::Value* v) { return b_.CreateICmpNE(v, splatI(0)); };

  if (isLaneValueOp(in.op)) {
    llvm::Value* r = emitLaneOp(b_, module_, in.op, operand(env, in.a), operand(env, in.b), operand(env, in.c),
                                operand(env, in.d), in.imm);
    setReg(env, in.dst, r, in.masked_write);
    return;
  }
  switch (in.op) {
    case Op::Jmp: b_.CreateBr(blocks.at(in.a)); return;
    case Op::JmpIfNot: {
      // A uniform condition. In a register (or a gang's wide record) every active lane holds
      // it: the first active lane's value; no active lane jumps. Else the record's word.
      llvm::Value* jump;
      const bool wide = operandKind(in.b) == OperandKind::Reg || (env.wide_record && operandKind(in.b) == OperandKind::Uniform);
      if (wide) {
        llvm::Value* bits = b_.CreateBitCast(exec(env), b_.getIntNTy(width_));
        llvm::Value* lane = b_.CreateIntrinsic(llvm::Intrinsic::cttz, {b_.getIntNTy(width_)}, {bits, b_.getTrue()});
        // (cttz of 0 is poison: the lane is masked into range; the value is unused then.)
        lane = b_.CreateAnd(lane, b_.getIntN(width_, width_ - 1));
        llvm::Value* value = b_.CreateExtractElement(operand(env, in.b), lane);
        jump = b_.CreateOr(b_.CreateICmpEQ(bits, b_.getIntN(width_, 0)), b_.CreateICmpEQ(value, b_.getInt32(0)));
        jump = b_.CreateFreeze(jump);
      } else {
        jump = b_.CreateICmpEQ(b_.CreateExtractElement(operand(env, in.b), uint64_t{0}), b_.getInt32(0));
      }
      b_.CreateCondBr(jump, blocks.at(in.a), blocks.at(pc + 1));
      return;
    }
    case Op::JmpIfNone:
      b_.CreateCondBr(any(exec(env)), blocks.at(pc + 1), blocks.at(in.a));
      return;
    case Op::MaskIf: {
      llvm::Value* cur = mask(env.cur);
      llvm::Value* c = nonzero(operand(env, in.b));
      b_.CreateStore(cur, env.saved[static_cast<size_t>(depth)]);
      b_.CreateStore(c, env.cond[static_cast<size_t>(depth)]);
      b_.CreateStore(b_.CreateAnd(cur, c), env.cur);
      return;
    }
    case Op::MaskElse:
      b_.CreateStore(b_.CreateAnd(mask(env.saved[static_cast<size_t>(depth - 1)]),
                                  b_.CreateNot(mask(env.cond[static_cast<size_t>(depth - 1)]))),
                     env.cur);
      return;
    case Op::MaskEnd: case Op::LoopEnd:
      b_.CreateStore(mask(env.saved[static_cast<size_t>(depth - 1)]), env.cur);
      return;
    case Op::LoopBegin:
      b_.CreateStore(mask(env.cur), env.saved[static_cast<size_t>(depth)]);
      b_.CreateStore(allLanes(false), env.cond[static_cast<size_t>(depth)]);
      b_.CreateStore(b_.getInt32(0), env.iterations[static_cast<size_t>(depth)]);
      return;
    case Op::LoopTest:
      b_.CreateStore(b_.CreateAnd(mask(env.cur), nonzero(operand(env, in.b))), env.cur);
      return;
    case Op::Break: case Op::Continue: {
      // The active lanes leave `levels` loops (and the ifs inside them); a continue comes back
      // at the innermost loop's continue point (PixelExecutor's leaveLoop, unrolled).
      llvm::Value* lanes = exec(env);
      llvm::Value* keep = b_.CreateNot(lanes);
      const bool to_continue = in.op == Op::Continue;
      int levels = to_continue ? 1 : std::max<int>(in.imm, 1);
      for (int f = depth - 1; f >= 0; --f) {
        const bool loop = frames[static_cast<size_t>(f)] == MaskFrameKind::Loop;
        if (loop && --levels == 0) {
          if (to_continue) {
            llvm::AllocaInst* c = env.cond[static_cast<size_t>(f)];
            b_.CreateStore(b_.CreateOr(mask(c), lanes), c);
          }
          break;
        }
        llvm::AllocaInst* s = env.saved[static_cast<size_t>(f)];
        b_.CreateStore(b_.CreateAnd(mask(s), keep), s);
        if (loop) {
          llvm::AllocaInst* c = env.cond[static_cast<size_t>(f)];
          b_.CreateStore(b_.CreateAnd(mask(c), keep), c);
        }
      }
      b_.CreateStore(b_.CreateAnd(mask(env.cur), keep), env.cur);
      return;
    }
    case Op::LoopContinue: {
      llvm::AllocaInst* c = env.cond[static_cast<size_t>(depth - 1)];
      b_.CreateStore(b_.CreateOr(mask(env.cur), b_.CreateAnd(mask(c), mask(env.alive))), env.cur);
      b_.CreateStore(allLanes(false), c);
      return;
    }
    case Op::LoopBack: {
      // An iteration counted; at the context's cap the lanes still looping stop (and draw
      // nothing) and the hit is reported.
      llvm::AllocaInst* it = env.iterations[static_cast<size_t>(depth - 1)];
      llvm::Value* n = b_.CreateAdd(b_.CreateLoad(b_.getInt32Ty(), it), b_.getInt32(1));
      b_.CreateStore(n, it);
      llvm::BasicBlock* capped = continueIn("capped");
      b_.CreateCondBr(b_.CreateICmpUGE(n, iteration_cap_), capped, blocks.at(in.a));
      b_.SetInsertPoint(capped);
      llvm::Value* stuck = exec(env);
      llvm::Value* count = b_.CreateZExt(
          b_.CreateIntrinsic(llvm::Intrinsic::ctpop, {b_.getIntNTy(width_)}, {b_.CreateBitCast(stuck, b_.getIntNTy(width_))}),
          b_.getInt64Ty());
      llvm::Value* lanes_at = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), args_, offsetof(NativeBlockArgs, cap_lanes));
      b_.CreateStore(b_.CreateAdd(b_.CreateLoad(b_.getInt64Ty(), lanes_at), count), lanes_at);
      llvm::Value* source_at = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), args_, offsetof(NativeBlockArgs, cap_source));
      b_.CreateStore(b_.getInt32(static_cast<uint32_t>(env.cap_source)), source_at);
      llvm::Value* alive = b_.CreateAnd(mask(env.alive), b_.CreateNot(stuck));
      b_.CreateStore(alive, env.alive);
      b_.CreateStore(allLanes(false), env.cur);
      b_.CreateCondBr(any(alive), blocks.at(in.a), env.dead);
      return;
    }
    case Op::Retire: {
      llvm::Value* alive = b_.CreateAnd(mask(env.alive), b_.CreateNot(exec(env)));
      b_.CreateStore(alive, env.alive);
      llvm::BasicBlock* on = continueIn("alive");
      b_.CreateCondBr(any(alive), on, env.dead);
      b_.SetInsertPoint(on);
      return;
    }
    case Op::ZTest: {
      // The depth function as a comparison of (Z, the depth the block started with): its
      // passing outcomes (less, equal, greater, unordered) from the context's state.
      llvm::Value* z = b_.CreateBitCast(operand(env, in.a), fv_);
      llvm::Value* zb = b_.CreateBitCast(operand(env, makeOperand(OperandKind::Reg, kRegZ)), fv_);
      auto passes = [&](uint32_t bit) {
        return b_.CreateVectorSplat(width_, b_.CreateICmpNE(b_.CreateAnd(depth_pass_, b_.getInt32(bit)), b_.getInt32(0)));
      };
      llvm::Value* r = b_.CreateOr(
          b_.CreateOr(b_.CreateAnd(passes(kDepthPassLess), b_.CreateFCmpOLT(z, zb)),
                      b_.CreateAnd(passes(kDepthPassEqual), b_.CreateFCmpOEQ(z, zb))),
          b_.CreateOr(b_.CreateAnd(passes(kDepthPassGreater), b_.CreateFCmpOLT(zb, z)),
                      b_.CreateAnd(passes(kDepthPassUnordered), b_.CreateFCmpUNO(z, zb))));
      r = keptByClipPlanes(env, r, z);
      if (in.imm != 0) r = keptByStipple(env, r);  // polygon_ztest()
      setReg(env, in.dst, b_.CreateZExt(r, iv_), true);
      return;
    }
    case Op::ZCommit:
      if (!env.interpolator) storeDepth(operand(env, in.a), exec(env));
      return;
    case Op::InterpReturn: {
      if (env.interpolator) return;
      llvm::Value* e = exec(env);
      forChannels(env, in.imm, [&](int ch) { maskedAssign(staging_[static_cast<size_t>(ch)], interpOperand(env, in.a, ch), e); });
      return;
    }
    case Op::InterpShared:
      if (!env.interpolator) emitShared(env, in);
      return;
    case Op::SurfaceCommit: {
      if (env.interpolator) return;  // its surface goes nowhere
      const uint32_t ops[4] = {in.a, in.b, in.c, in.d};
      llvm::Value* e = exec(env);
      for (int k = 0; k < (in.imm == 0 ? 4 : 3); ++k)
        maskedAssign(surface_[static_cast<size_t>(in.imm * 4 + k)], operand(env, ops[k]), e);
      return;
    }
    case Op::ShadeOut: {
      if (!env.interpolator) return;  // a primitive's goes nowhere
      const uint32_t ops[4] = {in.a, in.b, in.c, in.d};
      llvm::Value* e = exec(env);
      for (int k = 0; k < 4; ++k) maskedAssign(env.shade_out[static_cast<size_t>(k)], operand(env, ops[k]), e);
      return;
    }
    case Op::HasNamed: {
      const bool bound = !env.interpolator && in.imm < variant_.named_bound.size() && variant_.named_bound[in.imm];
      setReg(env, in.dst, splatI(bound ? 1u : 0u), false);
      return;
    }
    case Op::HasKinds: {
      bool has = false;
      if (!env.interpolator)
        for (int k = 0; k < 3; ++k)
          if ((in.imm & (1u << k)) && variant_.kind_end[k] > variant_.kind_begin[k]) has = true;
      setReg(env, in.dst, splatI(has ? 1u : 0u), false);
      return;
    }
    case Op::LoadState: {
      llvm::Value* v = invariantLoad(b_.getInt32Ty(), b_.CreateConstInBoundsGEP1_32(b_.getInt32Ty(), state_values_, in.imm));
      setReg(env, in.dst, b_.CreateVectorSplat(width_, v), false);
      return;
    }
    case Op::InterpNamedReturn: {
      if (env.interpolator) return;
      const uint32_t ops[4] = {in.a, in.b, in.c, in.d};
      llvm::Value* e = exec(env);
      for (const NativePixelVariant::Shared& s : variant_.shared) {
        if (s.named_index != static_cast<int>(in.imm)) continue;
        for (int k = 0; k < 4; ++k)
          maskedAssign(staging_[static_cast<size_t>(s.first + k)], operand(env, ops[k]), e);
      }
      return;
    }
    case Op::XSel: {
      llvm::Value* e = in.masked_write ? exec(env) : nullptr;
      forChannels(env, in.imm, [&](int ch) {
        llvm::Value* r = emitLaneOp(b_, module_, Op::Sel, operand(env, in.a), interpOperand(env, in.b, ch),
                                    interpOperand(env, in.c, ch), nullptr, 0);
        llvm::AllocaInst* d = xreg(env, operandIndex(in.dst), ch);
        if (e) maskedAssign(d, r, e); else b_.CreateStore(r, d);
      });
      return;
    }
    case Op::XAdd: case Op::XSub: case Op::XMulF: case Op::XDivF: case Op::XNeg: case Op::XMov: {
      const Op scalar = in.op == Op::XAdd ? Op::FAdd : in.op == Op::XSub ? Op::FSub : in.op == Op::XMulF ? Op::FMul
                        : in.op == Op::XDivF ? Op::FDiv : in.op == Op::XNeg ? Op::FNeg : Op::Mov;
      const bool float_b = in.op == Op::XMulF || in.op == Op::XDivF;
      llvm::Value* e = in.masked_write ? exec(env) : nullptr;
      forChannels(env, in.imm, [&](int ch) {
        llvm::Value* a = interpOperand(env, in.a, ch);
        llvm::Value* bv = in.b == kNoOperand ? splatI(0) : float_b ? operand(env, in.b) : interpOperand(env, in.b, ch);
        llvm::Value* r = emitLaneOp(b_, module_, scalar, a, bv, splatI(0), splatI(0), 0);
        llvm::AllocaInst* d = xreg(env, operandIndex(in.dst), ch);
        if (e) maskedAssign(d, r, e); else b_.CreateStore(r, d);
      });
      return;
    }
    default:
      return;  // setup-only instructions never reach a pixel program (nor do field searches here)
  }
}

// InterpShared: each shared interpolator of the layout that the primitive does not compute
// itself runs at the surface point P for the active lanes, inlined (the interpreter's
// sub-executor: its own registers and masks, Z = 0, P given, N = 0); its value goes to its four
// staging channels in the active lanes.
void PixelCodegen::emitShared(Env& env, const Instr& in) {
  if (variant_.shared.empty()) return;
  llvm::Value* e = exec(env);
  const uint32_t ops[4] = {in.a, in.b, in.c, in.d};
  llvm::Value* p[4];
  for (int k = 0; k < 4; ++k) p[k] = operand(env, ops[k]);
  // No shared records (an instance drawn without them): nothing runs, as in the interpreter.
  llvm::BasicBlock* run = llvm::BasicBlock::Create(ctx_, "shared", fn_);
  llvm::BasicBlock* after = llvm::BasicBlock::Create(ctx_, "shared.after", fn_);
  b_.CreateCondBr(b_.CreateAnd(any(e), b_.CreateICmpNE(shared_records_, llvm::ConstantPointerNull::get(b_.getPtrTy()))),
                  run, after);
  b_.SetInsertPoint(run);
  for (size_t k = 0; k < variant_.shared.size(); ++k) {
    const NativePixelVariant::Shared& s = variant_.shared[k];
    if (s.named_index >= 0) continue;  // the primitive fills it (InterpNamedReturn)
    Env sub;
    sub.program = s.pixel;
    sub.interpolator = true;
    sub.cap_source = static_cast<int>(k);
    sub.channels = 0;
    sub.record = b_.CreateConstInBoundsGEP1_32(b_.getInt32Ty(), shared_records_, s.record_offset);
    std::string error;
    if (!prepare(sub, error)) continue;  // checked when the variant was keyed (native_cache.cpp)
    llvm::BasicBlock* done = llvm::BasicBlock::Create(ctx_, "interpolator.done", fn_);
    sub.dead = done;
    sub.done = done;
    startProgram(sub, e, p);
    emitProgram(sub);
    b_.SetInsertPoint(done);
    for (int c = 0; c < 4; ++c)
      maskedAssign(staging_[static_cast<size_t>(s.first + c)], b_.CreateLoad(iv_, sub.shade_out[static_cast<size_t>(c)]), e);
  }
  b_.CreateBr(after);
  b_.SetInsertPoint(after);
}

// The lanes of `passed` that the user clip planes keep, for fragments at depth `z`: the
// interpreter's RasterState::clipKeeps, operation for operation ((a X + b Y) + c z) + d >= 0.
// No plane enabled (the usual case): one branch past all of it.
llvm::Value* PixelCodegen::keptByClipPlanes(Env& env, llvm::Value* passed, llvm::Value* z) {
  // (X and Y read before the branch: a register's value may be reused after it.)
  llvm::Value* x = b_.CreateBitCast(operand(env, makeOperand(OperandKind::Reg, kRegX)), fv_);
  llvm::Value* y = b_.CreateBitCast(operand(env, makeOperand(OperandKind::Reg, kRegY)), fv_);
  // Runs `body` (returning a new value) when `condition` holds, else keeps `value`.
  auto when = [&](llvm::Value* condition, llvm::Value* value, const char* name,
                  const std::function<llvm::Value*()>& body) -> llvm::Value* {
    llvm::BasicBlock* from = b_.GetInsertBlock();
    llvm::BasicBlock* then = llvm::BasicBlock::Create(ctx_, name, fn_);
    llvm::BasicBlock* join = llvm::BasicBlock::Create(ctx_, "clip.join", fn_);
    b_.CreateCondBr(condition, then, join);
    b_.SetInsertPoint(then);
    llvm::Value* changed = body();
    llvm::BasicBlock* then_end = b_.GetInsertBlock();
    b_.CreateBr(join);
    b_.SetInsertPoint(join);
    llvm::PHINode* merged = b_.CreatePHI(value->getType(), 2);
    merged->addIncoming(value, from);
    merged->addIncoming(changed, then_end);
    return merged;
  };
  return when(b_.CreateICmpNE(clip_count_, b_.getInt32(0)), passed, "clip", [&] {
    llvm::Value* kept = passed;
    for (int p = 0; p < kNativeMaxClipPlanes; ++p) {
      llvm::Value* active = b_.CreateICmpULT(b_.getInt32(static_cast<uint32_t>(p)), clip_count_);
      kept = when(active, kept, "clip.plane", [&] {
        auto coefficient = [&](int k) {
          llvm::Value* at = b_.CreateConstGEP1_32(b_.getFloatTy(), clip_planes_, static_cast<unsigned>(4 * p + k));
          return b_.CreateVectorSplat(width_, b_.CreateLoad(b_.getFloatTy(), at));
        };
        llvm::Value* sum = b_.CreateFAdd(b_.CreateFMul(coefficient(0), x), b_.CreateFMul(coefficient(1), y));
        sum = b_.CreateFAdd(sum, b_.CreateFMul(coefficient(2), z));
        sum = b_.CreateFAdd(sum, coefficient(3));
        return b_.CreateAnd(kept, b_.CreateFCmpOGE(sum, splatF(0.0f)));
      });
    }
    return kept;
  });
}

// The lanes of `passed` that the polygon stipple keeps (polygon_ztest()): the interpreter's
// RasterState::stippleKeeps, bit 31 - (x & 31) of row y & 31 with x and y the pixel centre
// truncated to an integer. No stipple (GL_POLYGON_STIPPLE off, a null pointer): one branch past it.
llvm::Value* PixelCodegen::keptByStipple(Env& env, llvm::Value* passed) {
  llvm::Value* x = b_.CreateBitCast(operand(env, makeOperand(OperandKind::Reg, kRegX)), fv_);
  llvm::Value* y = b_.CreateBitCast(operand(env, makeOperand(OperandKind::Reg, kRegY)), fv_);
  llvm::BasicBlock* from = b_.GetInsertBlock();
  llvm::BasicBlock* then = llvm::BasicBlock::Create(ctx_, "stipple", fn_);
  llvm::BasicBlock* join = llvm::BasicBlock::Create(ctx_, "stipple.join", fn_);
  b_.CreateCondBr(b_.CreateICmpNE(polygon_stipple_, llvm::ConstantPointerNull::get(b_.getPtrTy())), then, join);
  b_.SetInsertPoint(then);
  llvm::Value* mask31 = splatI(31);
  llvm::Value* row_index = b_.CreateAnd(b_.CreateFPToSI(y, iv_), mask31);
  llvm::Value* column = b_.CreateAnd(b_.CreateFPToSI(x, iv_), mask31);
  llvm::Value* at = b_.CreateGEP(b_.getInt32Ty(), polygon_stipple_, row_index, "stipple.at");
  // (Gathered only for the lanes that passed: another lane's x or y -- a lane past a packed
  // block's count -- is nothing to index memory with.)
  llvm::Value* rows = b_.CreateMaskedGather(iv_, at, llvm::Align(4), passed, splatI(0));
  llvm::Value* bit = b_.CreateAnd(b_.CreateLShr(rows, b_.CreateSub(mask31, column)), splatI(1));
  llvm::Value* kept = b_.CreateAnd(passed, b_.CreateICmpNE(bit, splatI(0)));
  llvm::BasicBlock* then_end = b_.GetInsertBlock();
  b_.CreateBr(join);
  b_.SetInsertPoint(join);
  llvm::PHINode* merged = b_.CreatePHI(passed->getType(), 2);
  merged->addIncoming(passed, from);
  merged->addIncoming(kept, then_end);
  return merged;
}

}  // namespace pf
