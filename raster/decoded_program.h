// A pixel program with the dispatch of its value instructions resolved ahead of the blocks it
// runs on. Whether an operand is wide (a register: one value per lane) or scalar (a uniform of
// the instance's record, a constant, nothing) is known from the operand alone, so each value
// instruction's lane kernel (raster/lane_kernels.h) can be picked once, and each operand becomes
// a base (registers, record, constants, zeros) and an offset. The executor then runs a value
// instruction without decoding it: per block, that decoding was about a fifth of a frame of
// small spheres (docs/performance.md). A product read only by one add or subtract is fused into
// it (FusedForm): one kernel, the same two roundings. A program decoded for gang blocks
// (PixelExecutor::runGangBlock) reads each uniform as a wide register -- its record then holds
// kLanes values per slot, one per lane's instance.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/isa.h"
#include "raster/lane_kernels.h"

namespace pf {

// Where a decoded operand's words are.
enum class OperandBase : uint8_t { Regs, Record, Constants, Zero };

struct DecodedInstr {
  LaneKernel kernel = nullptr;  // null: not a value instruction; the executor's switch runs it
  bool masked_write = false;    // Instr::masked_write: outside the active lanes the value stays
  uint16_t imm = 0;
  uint32_t dst = 0;  // the destination register's first word (registers base)
  OperandBase base[4] = {OperandBase::Zero, OperandBase::Zero, OperandBase::Zero, OperandBase::Zero};
  uint32_t offset[4] = {0, 0, 0, 0};  // the operand's first word from its base
};

struct DecodedProgram {
  // What it was decoded from, and for which kernels (PixelExecutor's memo compares them).
  const PixelProgram* program = nullptr;
  const Instr* code_data = nullptr;
  const uint32_t* constants_data = nullptr;
  size_t code_size = 0;
  const LaneIsaTables* isa = nullptr;
  bool wide_uniforms = false;  // record slot i is kLanes words at i * kLanes (a gang's)
  std::vector<DecodedInstr> code;  // one per instruction of program->code
  int fused = 0;                   // products fused into their add (lane_kernels.h, FusedForm)
  // The fusion's per-register counts (kept with the object: decoding again reuses them).
  struct Scratch {
    std::vector<uint32_t> uses, defs;
    std::vector<int32_t> def_pc;
    std::vector<uint8_t> masked, consumed;
  } scratch;

  bool decodes(const PixelProgram& p, const LaneIsaTables& tables, bool wide) const {
    return program == &p && code_data == p.code.data() && code_size == p.code.size() &&
           constants_data == p.constants.data() && isa == &tables && wide_uniforms == wide;
  }
};

// Decodes `program` into `out` (its storage reused: a frame's decoding allocates nothing once
// the buffers have grown); `wide_uniforms`: for gang blocks.
void decodeProgram(const PixelProgram& program, const LaneIsaTables& isa, DecodedProgram& out,
                   bool wide_uniforms = false);

}  // namespace pf
