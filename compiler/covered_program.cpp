// coveredVariant (see covered_program.h): drop the leading Retire wrappers, then the values only
// they read, and renumber the jumps.
#include "compiler/covered_program.h"

#include <vector>

namespace pf {
namespace {

bool isJump(Op op) { return op == Op::Jmp || op == Op::JmpIfNot || op == Op::JmpIfNone || op == Op::LoopBack; }

// Instructions that only compute their destination register from their operands: removable
// when nothing reads the destination. (Interp ops write interpolator registers, effects write
// elsewhere, FieldHit / FieldGradient keep per-run state: all kept.)
bool isPureValue(const Instr& in) {
  if (in.dst == kNoOperand || operandKind(in.dst) != OperandKind::Reg) return false;
  const int op = static_cast<int>(in.op);
  return op <= static_cast<int>(Op::Mov) || in.op == Op::LoadState || in.op == Op::ZTest;
}

}  // namespace

std::optional<PixelProgram> coveredVariant(const PixelProgram& program) {
  const std::vector<Instr>& code = program.code;
  if (program.last_coverage_retire < 0) return std::nullopt;
  const size_t prefix_end = static_cast<size_t>(program.last_coverage_retire) + 1;  // [0, prefix_end)
  std::vector<char> keep(code.size(), 1);
  // Each leading Retire must sit in codegen's wrapper for a varying `if (...) return;`:
  // MaskIf c; JmpIfNone @after; Retire; MaskEnd (after: the MaskEnd).
  for (size_t pc = 0; pc < prefix_end; ++pc) {
    if (code[pc].op != Op::Retire) continue;
    if (pc < 2 || pc + 1 >= code.size() || code[pc - 2].op != Op::MaskIf || code[pc - 1].op != Op::JmpIfNone ||
        code[pc - 1].a != pc + 1 || code[pc + 1].op != Op::MaskEnd)
      return std::nullopt;
    keep[pc - 2] = keep[pc - 1] = keep[pc] = keep[pc + 1] = 0;
  }
  // The registers something still reads: everything after the prefix (conservatively), then,
  // walking the prefix backwards, the operands of what stays. The prefix has no loops and jumps
  // only forwards, so an instruction's readers all come after it.
  std::vector<char> read(program.num_regs, 0);
  auto markRead = [&](const Instr& in) {
    for (uint32_t o : {in.a, in.b, in.c, in.d})
      if (o != kNoOperand && operandKind(o) == OperandKind::Reg && operandIndex(o) < read.size()) read[operandIndex(o)] = 1;
    // A merge value (masked write) keeps its other lanes: it reads its own old value.
    if (in.masked_write && in.dst != kNoOperand && operandKind(in.dst) == OperandKind::Reg &&
        operandIndex(in.dst) < read.size())
      read[operandIndex(in.dst)] = 1;
  };
  for (size_t pc = prefix_end; pc < code.size(); ++pc) {
    if (isJump(code[pc].op) && code[pc].a < prefix_end) return std::nullopt;  // a jump back into the prefix
    markRead(code[pc]);
  }
  // The jumps' operand a is a target, not a register.
  auto markOperands = [&](const Instr& in) {
    if (!isJump(in.op)) return markRead(in);
    Instr copy = in;
    copy.a = kNoOperand;
    markRead(copy);
  };
  for (size_t pc = prefix_end; pc-- > 0;) {
    const Instr& in = code[pc];
    if (!keep[pc]) continue;
    if (isJump(in.op) && in.a <= pc) return std::nullopt;  // a loop: not a prefix after all
    if (isPureValue(in) && operandIndex(in.dst) < read.size() && !read[operandIndex(in.dst)]) {
      keep[pc] = 0;
      continue;
    }
    markOperands(in);
  }
  // The kept instructions, renumbered; a jump to a removed instruction lands on the next kept.
  std::vector<uint32_t> new_pc(code.size() + 1, 0);
  uint32_t next = 0;
  for (size_t pc = 0; pc < code.size(); ++pc) {
    new_pc[pc] = next;
    if (keep[pc]) ++next;
  }
  new_pc[code.size()] = next;
  PixelProgram out = program;
  out.code.clear();
  for (size_t pc = 0; pc < code.size(); ++pc) {
    if (!keep[pc]) continue;
    Instr in = code[pc];
    if (isJump(in.op)) in.a = in.a <= code.size() ? new_pc[in.a] : in.a;
    out.code.push_back(in);
  }
  out.last_early_retire = -1;
  out.last_coverage_retire = -1;
  out.covered = nullptr;
  return out;
}

}  // namespace pf
