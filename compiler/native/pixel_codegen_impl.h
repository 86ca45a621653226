// The pixel code generator's class, shared by its three files: pixel_codegen.cpp (the program:
// control flow, masks, values, effects), pixel_operands.cpp (registers and operands) and
// pixel_block_io.cpp (the block's memory: X, Y and the depth under each lane, depth writes, the
// commit to the G-buffer).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include "compiler/isa.h"
#include "compiler/native/mask_frames.h"
#include "compiler/native/native_abi.h"
#include "compiler/native/pixel_codegen.h"

namespace pf {

class PixelCodegen {
 public:
  PixelCodegen(llvm::Module& module, const NativePixelVariant& variant, NativeFault fault);
  llvm::Function* build(const std::string& name, const PixelProgram& program, std::string& error);

 private:
  // One program being emitted: the primitive's, or a shared interpolator's inlined at its
  // InterpShared (the interpreter's sub-executor, with its own registers and masks).
  struct Env {
    const PixelProgram* program = nullptr;
    bool interpolator = false;
    int cap_source = -1;  // NativeBlockArgs::cap_source when its loops hit the cap
    int channels = 0;     // interpolator_data channels (0 in an interpolator)
    llvm::Value* record = nullptr;
    bool wide_record = false;
    MaskFrames frames;
    std::vector<llvm::AllocaInst*> regs;
    std::map<std::pair<uint32_t, int>, llvm::AllocaInst*> xregs;  // (interp register, channel)
    llvm::AllocaInst* alive = nullptr;
    llvm::AllocaInst* cur = nullptr;
    std::vector<llvm::AllocaInst*> saved, cond, iterations;  // per nesting level
    std::vector<llvm::AllocaInst*> shade_out;  // an interpolator's value (4)
    llvm::BasicBlock* dead = nullptr;  // where a chunk whose lanes all retired goes
    llvm::BasicBlock* done = nullptr;  // where the program's end goes
  };

  // --- pixel_codegen.cpp: the program -------------------------------------------------------
  bool prepare(Env& env, std::string& error);
  void startProgram(Env& env, llvm::Value* in_mask, llvm::Value* const* p_in);
  void emitProgram(Env& env);
  void emitInstruction(Env& env, size_t pc, const Instr& in, std::map<size_t, llvm::BasicBlock*>& blocks);
  // The lanes of `passed` (a depth test's result) that the user clip planes keep at depth `z`.
  llvm::Value* keptByClipPlanes(Env& env, llvm::Value* passed, llvm::Value* z);
  llvm::Value* keptByStipple(Env& env, llvm::Value* passed);
  void emitShared(Env& env, const Instr& in);
  llvm::AllocaInst* entryAlloca(llvm::Type* t, const char* name);

  // --- pixel_operands.cpp: registers and operands -------------------------------------------
  llvm::Value* operand(Env& env, uint32_t o);
  llvm::Value* interpOperand(Env& env, uint32_t o, int ch);
  void setReg(Env& env, uint32_t dst, llvm::Value* v, bool masked);
  llvm::AllocaInst* xreg(Env& env, uint32_t reg, int ch);
  llvm::Value* exec(Env& env);
  llvm::Value* any(llvm::Value* mask);
  void forChannels(const Env& env, uint16_t kinds, const std::function<void(int)>& fn) const;
  void maskedAssign(llvm::AllocaInst* slot, llvm::Value* v, llvm::Value* mask);

  // --- pixel_block_io.cpp: the block's memory ----------------------------------------------
  // The chunk's lanes' pixels (lane index vector, packed x / y) and their X, Y.
  void pixelCoordinates(llvm::Value*& x, llvm::Value*& y);
  llvm::Value* depthAddress(llvm::Value* x, llvm::Value* y);  // a vector of pointers
  llvm::Value* loadDepth(llvm::Value* in_mask);
  void storeDepth(llvm::Value* z, llvm::Value* mask);
  void commit(llvm::Value* alive);
  // Contiguous pieces of the chunk in an aligned block: lanes [first, first + count) of the
  // chunk lie on one row, at window pixel (x, y) onwards.
  struct RowPiece {
    unsigned first, count;
    llvm::Value* x;
    llvm::Value* y;
  };
  std::vector<RowPiece> rowPieces();
  llvm::Value* slice(llvm::Value* v, unsigned first, unsigned count);
  llvm::Value* concat(const std::vector<llvm::Value*>& pieces);
  void storeLanes(llvm::Value* value, llvm::Value* address, llvm::Value* mask, bool owned);
  // Emits `aligned` and `packed` on the two sides of a branch on packed_ and merges the
  // values they return (each side the same number, of the same types); a gang variant emits
  // `packed` alone. `when`: a further condition for either to run; else `otherwise`'s values.
  using Values = std::vector<llvm::Value*>;
  Values byShape(const std::function<Values()>& aligned, const std::function<Values()>& packed,
                 llvm::Value* when = nullptr, const Values& otherwise = {});

  const NativeFault fault_;  // (tests only: pixel_codegen.h)

  // --- shared --------------------------------------------------------------------------------
  llvm::Value* argField(size_t offset, llvm::Type* type, const char* name);
  llvm::Value* splatI(uint32_t v) { return b_.CreateVectorSplat(width_, b_.getInt32(v)); }
  llvm::Value* splatF(float v) { return b_.CreateVectorSplat(width_, llvm::ConstantFP::get(b_.getFloatTy(), v)); }
  llvm::Value* allLanes(bool on) { return b_.CreateVectorSplat(width_, b_.getInt1(on)); }
  llvm::Value* invariantLoad(llvm::Type* t, llvm::Value* ptr);

  llvm::Module& module_;
  llvm::LLVMContext& ctx_;
  llvm::IRBuilder<> b_;
  const NativePixelVariant& variant_;
  const unsigned width_;
  llvm::FixedVectorType* iv_;  // <W x i32>
  llvm::FixedVectorType* fv_;  // <W x float>
  llvm::FixedVectorType* mv_;  // <W x i1>
  llvm::Function* fn_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::Value* args_ = nullptr;
  // The arguments, loaded once in the entry block.
  llvm::Value* record_ = nullptr;
  llvm::Value* shared_records_ = nullptr;
  llvm::Value* lane_x_ = nullptr;
  llvm::Value* lane_y_ = nullptr;
  llvm::Value* depth_ = nullptr;
  llvm::Value* state_values_ = nullptr;
  llvm::Value* shade_ids_ = nullptr;
  llvm::Value* planes_ = nullptr;
  llvm::Value* surface_planes_ = nullptr;
  llvm::Value* bx_ = nullptr;
  llvm::Value* by_ = nullptr;
  llvm::Value* depth_stride_ = nullptr;
  llvm::Value* tile_x0_ = nullptr;
  llvm::Value* tile_y0_ = nullptr;
  llvm::Value* shade_id_ = nullptr;
  llvm::Value* iteration_cap_ = nullptr;
  llvm::Value* depth_pass_ = nullptr;   // i32: kDepthPass* bits
  llvm::Value* clip_planes_ = nullptr;  // ptr: NativeBlockArgs::clip_planes
  llvm::Value* polygon_stipple_ = nullptr;  // ptr: NativeBlockArgs::polygon_stipple
  llvm::Value* clip_count_ = nullptr;   // i32: NativeBlockArgs::clip_plane_count
  llvm::Value* depth_write_ = nullptr;  // i1
  llvm::Value* has_depth_ = nullptr;    // i1: a depth buffer
  llvm::Value* packed_ = nullptr;       // i1: packed lanes (always, in a gang variant)
  // The chunk being run: its index and first lane (i32), and what the primitive leaves for the
  // commit: the staging channels and the surface (P, N).
  llvm::Value* chunk_ = nullptr;
  llvm::Value* first_lane_ = nullptr;
  llvm::Value* lane_px_ = nullptr;  // packed: the lanes' pixel x, y (vectors of i32; zeros for aligned blocks)
  llvm::Value* lane_py_ = nullptr;
  llvm::Value* x_ = nullptr;  // the built-in X, Y of the chunk's lanes (i32 bits)
  llvm::Value* y_ = nullptr;
  std::vector<llvm::AllocaInst*> staging_;
  std::vector<llvm::AllocaInst*> surface_;  // P (4), N (3), as the interpreter's surface_
};

}  // namespace pf
