// Pre-decoded pixel programs (see decoded_program.h).
#include "raster/decoded_program.h"

#include "raster/limits.h"

#include <vector>

namespace pf {
namespace {

// Fuses each FMul whose value is read once, by an FAdd or FSub later in the program, into that
// instruction (FusedForm): the FMul's slot then runs nothing. Sound when the product computed
// at the add is the one the FMul made: its operands are uniforms, constants or registers
// written once and never under a mask (so unchanged since), and nothing else reads the FMul's
// register. Counted conservatively: every register operand of any instruction is a use and
// every register destination a definition (the interpolator-data ops' registers are another
// file, counted anyway where their numbers are a pixel register's; a register number past the
// program's registers is never treated as unchanging).
void fuseProducts(const PixelProgram& program, const LaneIsaTables& isa, DecodedProgram& out) {
  const bool wide_uniforms = out.wide_uniforms;
  const size_t n = program.code.size();
  DecodedProgram::Scratch& s = out.scratch;
  s.uses.assign(program.num_regs, 0);
  s.defs.assign(program.num_regs, 0);
  s.def_pc.assign(program.num_regs, -1);
  s.masked.assign(program.num_regs, 0);
  s.consumed.assign(n, 0);
  std::vector<uint32_t>& uses = s.uses;
  std::vector<uint32_t>& defs = s.defs;
  std::vector<int32_t>& def_pc = s.def_pc;
  std::vector<uint8_t>& masked = s.masked;
  std::vector<uint8_t>& consumed = s.consumed;
  auto reg = [&](uint32_t o) -> int64_t {
    if (o == kNoOperand || operandKind(o) != OperandKind::Reg) return -1;
    const uint32_t i = operandIndex(o);
    return i < program.num_regs ? static_cast<int64_t>(i) : -1;
  };
  for (size_t pc = 0; pc < n; ++pc) {
    const Instr& ins = program.code[pc];
    for (uint32_t o : {ins.a, ins.b, ins.c, ins.d}) {
      if (const int64_t r = reg(o); r >= 0) ++uses[static_cast<size_t>(r)];
    }
    if (const int64_t r = reg(ins.dst); r >= 0) {
      ++defs[static_cast<size_t>(r)];
      def_pc[static_cast<size_t>(r)] = static_cast<int32_t>(pc);
      if (ins.masked_write) masked[static_cast<size_t>(r)] = 1;
    }
  }
  // A value that cannot change between the product and the add.
  auto stable = [&](uint32_t o) {
    const int64_t r = reg(o);
    if (r < 0) return o == kNoOperand || operandKind(o) != OperandKind::Reg;  // uniform, constant, none
    if (r < static_cast<int64_t>(kFirstFreePixelReg)) return defs[static_cast<size_t>(r)] == 0;  // X, Y, Z, P, N
    return defs[static_cast<size_t>(r)] == 1 && !masked[static_cast<size_t>(r)];
  };
  auto shape = [&](uint32_t o) {
    return reg(o) >= 0 || (wide_uniforms && o != kNoOperand && operandKind(o) == OperandKind::Uniform) ? 1u : 0u;
  };
  for (size_t pc = 0; pc < n; ++pc) {
    const Instr& add = program.code[pc];
    if (add.op != Op::FAdd && add.op != Op::FSub) continue;
    for (int side = 0; side < 2; ++side) {
      const uint32_t t_op = side == 0 ? add.a : add.b, other = side == 0 ? add.b : add.a;
      const int64_t t = reg(t_op);
      if (t < static_cast<int64_t>(kFirstFreePixelReg)) continue;
      const size_t ti = static_cast<size_t>(t);
      if (uses[ti] != 1 || defs[ti] != 1 || masked[ti] || def_pc[ti] < 0 || static_cast<size_t>(def_pc[ti]) >= pc)
        continue;
      const size_t mul_pc = static_cast<size_t>(def_pc[ti]);
      const Instr& mul = program.code[mul_pc];
      if (mul.op != Op::FMul || consumed[mul_pc] || !stable(mul.a) || !stable(mul.b)) continue;
      const FusedForm form = add.op == Op::FAdd ? (side == 0 ? FusedForm::ProductPlus : FusedForm::PlusProduct)
                                                : (side == 0 ? FusedForm::ProductMinus : FusedForm::MinusProduct);
      DecodedInstr& d = out.code[pc];
      const DecodedInstr& m = out.code[mul_pc];
      const DecodedInstr plain = d;
      d.kernel = (*isa.fused)[static_cast<size_t>(form)][shape(mul.a) | shape(mul.b) << 1 | shape(other) << 2];
      d.base[0] = m.base[0];
      d.offset[0] = m.offset[0];
      d.base[1] = m.base[1];
      d.offset[1] = m.offset[1];
      d.base[2] = plain.base[side == 0 ? 1 : 0];
      d.offset[2] = plain.offset[side == 0 ? 1 : 0];
      d.base[3] = OperandBase::Zero;
      d.offset[3] = 0;
      out.code[mul_pc].kernel = nullptr;  // runs nothing: its only reader computes it
      consumed[mul_pc] = 1;
      ++out.fused;
      break;
    }
  }
}

}  // namespace

void decodeProgram(const PixelProgram& program, const LaneIsaTables& isa, DecodedProgram& out,
                   bool wide_uniforms) {
  out.program = &program;
  out.wide_uniforms = wide_uniforms;
  out.code_data = program.code.data();
  out.constants_data = program.constants.data();
  out.code_size = program.code.size();
  out.isa = &isa;
  out.fused = 0;
  out.code.assign(program.code.size(), DecodedInstr{});
  for (size_t pc = 0; pc < program.code.size(); ++pc) {
    const Instr& ins = program.code[pc];
    // Value-producing ops run through kernels; effects, control and the interpolator-data ops
    // (per channel) stay with the executor's switch. (A kernel op with an interpolator operand
    // does not exist: those have their own X ops.)
    if (static_cast<size_t>(ins.op) >= kLaneKernelOps) continue;
    DecodedInstr& d = out.code[pc];
    const uint32_t ops[4] = {ins.a, ins.b, ins.c, ins.d};
    unsigned wide = 0;
    for (int k = 0; k < 4; ++k) {
      const uint32_t o = ops[k];
      if (o == kNoOperand) continue;  // zeros, scalar
      const uint32_t i = operandIndex(o);
      switch (operandKind(o)) {
        case OperandKind::Reg:
          d.base[k] = OperandBase::Regs;
          d.offset[k] = i * static_cast<uint32_t>(kLanes);
          wide |= 1u << k;
          break;
        case OperandKind::Uniform:
          d.base[k] = OperandBase::Record;
          if (wide_uniforms) {
            d.offset[k] = i * static_cast<uint32_t>(kLanes);
            wide |= 1u << k;
          } else {
            d.offset[k] = i;
          }
          break;
        case OperandKind::Const: d.base[k] = OperandBase::Constants; d.offset[k] = i; break;
        case OperandKind::Param: break;  // never in a pixel program: zeros, as the switch reads it
      }
    }
    d.kernel = (*isa.kernels)[static_cast<size_t>(ins.op)][wide];
    d.masked_write = ins.masked_write;
    d.imm = ins.imm;
    d.dst = operandIndex(ins.dst) * static_cast<uint32_t>(kLanes);
  }
  fuseProducts(program, isa, out);
}

}  // namespace pf
