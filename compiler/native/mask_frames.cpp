// Static mask frames of a pixel program (see mask_frames.h).
#include "compiler/native/mask_frames.h"

namespace pf {

bool findMaskFrames(const std::vector<Instr>& code, MaskFrames& out, std::string& error) {
  const size_t n = code.size();
  out.at.assign(n, {});
  out.reached.assign(n, false);
  out.max_depth = 0;
  std::vector<size_t> work;
  // Reaching `pc` with `frames`: recorded the first time, checked every other time.
  auto reach = [&](size_t pc, const std::vector<MaskFrameKind>& frames, size_t from) {
    if (pc > n) {
      error = "instruction " + std::to_string(from) + " jumps past the program's end";
      return false;
    }
    if (pc == n) {
      if (!frames.empty()) {
        error = "the program ends with " + std::to_string(frames.size()) + " mask frames open";
        return false;
      }
      return true;
    }
    if (out.reached[pc]) {
      if (out.at[pc] != frames) {
        error = "instruction " + std::to_string(pc) + " is reached with different mask frames";
        return false;
      }
      return true;
    }
    out.reached[pc] = true;
    out.at[pc] = frames;
    out.max_depth = std::max(out.max_depth, static_cast<int>(frames.size()));
    work.push_back(pc);
    return true;
  };
  if (n == 0) return true;
  if (!reach(0, {}, 0)) return false;
  while (!work.empty()) {
    const size_t pc = work.back();
    work.pop_back();
    const Instr& in = code[pc];
    std::vector<MaskFrameKind> frames = out.at[pc];
    auto close = [&](MaskFrameKind kind) {
      if (frames.empty() || frames.back() != kind) {
        error = "instruction " + std::to_string(pc) + " (" + opName(in.op) + ") closes a frame that is not open";
        return false;
      }
      frames.pop_back();
      return true;
    };
    auto insideLoop = [&] {
      for (auto k : frames)
        if (k == MaskFrameKind::Loop) return true;
      return false;
    };
    bool next = true;  // falls through to pc + 1
    switch (in.op) {
      case Op::MaskIf: frames.push_back(MaskFrameKind::If); break;
      case Op::LoopBegin: frames.push_back(MaskFrameKind::Loop); break;
      case Op::MaskElse:
        if (frames.empty() || frames.back() != MaskFrameKind::If) {
          error = "instruction " + std::to_string(pc) + " (maskelse) outside a varying if";
          return false;
        }
        break;
      case Op::MaskEnd:
        if (!close(MaskFrameKind::If)) return false;
        break;
      case Op::LoopEnd:
        if (!close(MaskFrameKind::Loop)) return false;
        break;
      case Op::LoopTest: case Op::LoopContinue:
        if (frames.empty() || frames.back() != MaskFrameKind::Loop) {
          error = "instruction " + std::to_string(pc) + " (" + opName(in.op) + ") outside a loop's own frame";
          return false;
        }
        break;
      case Op::Continue:
        if (!insideLoop()) {
          error = "instruction " + std::to_string(pc) + " (continue) outside a loop";
          return false;
        }
        break;
      case Op::Break: {
        int loops = 0;
        for (auto k : frames) loops += k == MaskFrameKind::Loop ? 1 : 0;
        if (loops < std::max<int>(in.imm, 1)) {
          error = "instruction " + std::to_string(pc) + " (break) leaves more loops than are open";
          return false;
        }
        break;
      }
      case Op::Jmp:
        next = false;
        if (!reach(in.a, frames, pc)) return false;
        break;
      case Op::JmpIfNot: case Op::JmpIfNone:
        if (!reach(in.a, frames, pc)) return false;
        break;
      case Op::LoopBack:
        if (frames.empty() || frames.back() != MaskFrameKind::Loop) {
          error = "instruction " + std::to_string(pc) + " (loopback) outside a loop";
          return false;
        }
        next = false;
        if (!reach(in.a, frames, pc)) return false;
        break;
      default: break;
    }
    if (next && !reach(pc + 1, frames, pc)) return false;
  }
  return true;
}

}  // namespace pf
