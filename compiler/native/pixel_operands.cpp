// The pixel code generator's registers and operands (see pixel_codegen_impl.h): the execution
// mask, reads of registers, uniforms and constants as the interpreter's src() and xsrc() read
// them, and writes that keep a merge value's inactive lanes.
#include "compiler/native/pixel_codegen_impl.h"

namespace pf {

llvm::Value* PixelCodegen::exec(Env& env) {
  return b_.CreateAnd(b_.CreateLoad(mv_, env.alive), b_.CreateLoad(mv_, env.cur), "exec");
}

llvm::Value* PixelCodegen::any(llvm::Value* mask) {
  return b_.CreateICmpNE(b_.CreateBitCast(mask, b_.getIntNTy(width_)), b_.getIntN(width_, 0));
}

void PixelCodegen::maskedAssign(llvm::AllocaInst* slot, llvm::Value* v, llvm::Value* mask) {
  b_.CreateStore(b_.CreateSelect(mask, v, b_.CreateLoad(iv_, slot)), slot);
}

llvm::Value* PixelCodegen::operand(Env& env, uint32_t o) {
  if (o == kNoOperand) return splatI(0);
  const uint32_t i = operandIndex(o);
  switch (operandKind(o)) {
    case OperandKind::Reg:
      if (i >= env.regs.size()) return splatI(0);
      return b_.CreateLoad(iv_, env.regs[i]);
    case OperandKind::Uniform: {
      if (env.wide_record) {  // a gang's: kLanes words per slot, the chunk's lanes
        llvm::Value* at = b_.CreateAdd(b_.getInt32(i * kNativeLanes), first_lane_);
        return invariantLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), env.record, at));
      }
      llvm::Value* word = invariantLoad(b_.getInt32Ty(), b_.CreateConstInBoundsGEP1_32(b_.getInt32Ty(), env.record, i));
      return b_.CreateVectorSplat(width_, word);
    }
    case OperandKind::Const:
      return splatI(i < env.program->constants.size() ? env.program->constants[i] : 0u);
    case OperandKind::Param: break;
  }
  return splatI(0);
}

// Interp operand `o`, channel `ch`: a register's channel, or the uniform record's (after the
// scalar slots, num_interp_uniform_slots x channels).
llvm::Value* PixelCodegen::interpOperand(Env& env, uint32_t o, int ch) {
  const uint32_t i = operandIndex(o);
  if (operandKind(o) == OperandKind::Reg) return b_.CreateLoad(iv_, xreg(env, i, ch));
  const uint32_t word = env.program->num_uniform_slots + i * static_cast<uint32_t>(env.channels) + static_cast<uint32_t>(ch);
  if (env.wide_record) {
    llvm::Value* at = b_.CreateAdd(b_.getInt32(word * kNativeLanes), first_lane_);
    return invariantLoad(iv_, b_.CreateInBoundsGEP(b_.getInt32Ty(), env.record, at));
  }
  return b_.CreateVectorSplat(width_, invariantLoad(b_.getInt32Ty(), b_.CreateConstInBoundsGEP1_32(b_.getInt32Ty(), env.record, word)));
}

llvm::AllocaInst* PixelCodegen::xreg(Env& env, uint32_t reg, int ch) {
  auto it = env.xregs.find({reg, ch});
  if (it != env.xregs.end()) return it->second;
  // A register past num_interp_regs (never in codegen's output): a variable of its own.
  llvm::AllocaInst* slot = entryAlloca(iv_, "x");
  env.xregs[{reg, ch}] = slot;
  return slot;
}

void PixelCodegen::setReg(Env& env, uint32_t dst, llvm::Value* v, bool masked) {
  if (dst == kNoOperand || operandKind(dst) != OperandKind::Reg) return;
  const uint32_t i = operandIndex(dst);
  if (i >= env.regs.size()) return;
  if (masked && fault_ != NativeFault::MergeWithoutMask)
    maskedAssign(env.regs[i], v, exec(env));
  else
    b_.CreateStore(v, env.regs[i]);
}

void PixelCodegen::forChannels(const Env& env, uint16_t kinds, const std::function<void(int)>& fn) const {
  if (env.interpolator) return;  // its layout has no channels
  for (int kind = 0; kind < 3; ++kind)
    if (kinds & (1u << kind))
      for (int ch = variant_.kind_begin[kind]; ch < variant_.kind_end[kind]; ++ch) fn(ch);
}

}  // namespace pf
