// The record words a pixel program reads on its uniform paths (see record_reads.h).
#include "compiler/record_reads.h"

#include <algorithm>

namespace pf {
namespace {

// Whether operand `k` (0 a, 1 b, 2 c) of `op` is an interpolator_data operand (a channel
// vector: its uniform slot is the record's interp part), as the pixel executor reads them.
bool interpOperand(Op op, int k) {
  switch (op) {
    case Op::XAdd: case Op::XSub: return k <= 1;
    case Op::XNeg: case Op::XMov: case Op::XMulF: case Op::XDivF: case Op::InterpReturn: return k == 0;
    case Op::XSel: return k == 1 || k == 2;
    default: return false;
  }
}

}  // namespace

void recordWordsRead(const PixelProgram& program, int channels, const uint32_t* record,
                     std::vector<RecordWordRun>& runs, RecordReadsScratch& scratch) {
  std::vector<uint8_t>& visited = scratch.visited;
  std::vector<uint32_t>& work = scratch.work;
  const size_t n = program.code.size();
  const uint32_t words = program.num_uniform_slots + program.num_interp_uniform_slots * static_cast<uint32_t>(channels);
  visited.assign(n + words, 0);  // [0, n): instructions reached; then the words read
  uint8_t* read = visited.data() + n;
  work.assign(1, 0u);
  auto reach = [&](uint32_t pc) {
    if (pc < n && !visited[pc]) {
      visited[pc] = 1;
      work.push_back(pc);
    }
  };
  if (n) visited[0] = 1;
  else work.clear();
  auto isBranchSlot = [&](uint32_t o) {
    return operandKind(o) == OperandKind::Uniform &&
           std::find(program.branch_slots.begin(), program.branch_slots.end(), operandIndex(o)) !=
               program.branch_slots.end();
  };
  while (!work.empty()) {
    const uint32_t pc = work.back();
    work.pop_back();
    const Instr& in = program.code[pc];
    const uint32_t ops[4] = {in.a, in.b, in.c, in.d};
    const bool jump = in.op == Op::Jmp || in.op == Op::JmpIfNot || in.op == Op::JmpIfNone || in.op == Op::LoopBack;
    for (int k = 0; k < 4; ++k) {
      const uint32_t o = ops[k];
      if (o == kNoOperand || (jump && k == 0) || operandKind(o) != OperandKind::Uniform) continue;
      const uint32_t i = operandIndex(o);
      if (interpOperand(in.op, k)) {
        for (int ch = 0; ch < channels; ++ch) {
          const uint32_t w = program.num_uniform_slots + i * static_cast<uint32_t>(channels) + static_cast<uint32_t>(ch);
          if (w < words) read[w] = 1;
        }
      } else if (i < words) {
        read[i] = 1;
      }
    }
    switch (in.op) {
      case Op::Jmp: reach(in.a); break;
      case Op::JmpIfNot:
        if (isBranchSlot(in.b)) {  // the gang's members agree on it: one way
          reach(record[operandIndex(in.b)] == 0 ? in.a : pc + 1);
        } else {
          reach(in.a);
          reach(pc + 1);
        }
        break;
      case Op::JmpIfNone: case Op::LoopBack:
        reach(in.a);
        reach(pc + 1);
        break;
      default: reach(pc + 1); break;
    }
  }
  runs.clear();
  for (uint32_t w = 0; w < words; ++w) {
    if (!read[w]) continue;
    if (!runs.empty() && runs.back().first + runs.back().count == w)
      ++runs.back().count;
    else
      runs.push_back({w, 1});
  }
}

}  // namespace pf
