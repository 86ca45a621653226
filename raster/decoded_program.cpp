// Pre-decoded pixel programs (see decoded_program.h).
#include "raster/decoded_program.h"

#include "raster/limits.h"

namespace pf {

void decodeProgram(const PixelProgram& program, const LaneIsaTables& isa, DecodedProgram& out) {
  out.program = &program;
  out.code_data = program.code.data();
  out.constants_data = program.constants.data();
  out.code_size = program.code.size();
  out.isa = &isa;
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
        case OperandKind::Uniform: d.base[k] = OperandBase::Record; d.offset[k] = i; break;
        case OperandKind::Const: d.base[k] = OperandBase::Constants; d.offset[k] = i; break;
        case OperandKind::Param: break;  // never in a pixel program: zeros, as the switch reads it
      }
    }
    d.kernel = (*isa.kernels)[static_cast<size_t>(ins.op)][wide];
    d.masked_write = ins.masked_write;
    d.imm = ins.imm;
    d.dst = operandIndex(ins.dst) * static_cast<uint32_t>(kLanes);
  }
}

}  // namespace pf
