// The mask frames of a pixel program, found statically. The interpreter keeps a run-time stack
// of frames (one per open varying if or loop: raster/pixel_interpreter.cpp); the code generator
// needs the same stack at every instruction at compile time, to give each level its own
// variables. codegen.cpp emits structured code -- MaskIf .. MaskEnd and LoopBegin .. LoopEnd
// nest, jumps stay within their frame -- so every instruction has one stack, whichever path
// reaches it; this checks that and says where it does not.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compiler/isa.h"

namespace pf {

enum class MaskFrameKind : uint8_t { If, Loop };

struct MaskFrames {
  // Per instruction: the frames open before it runs, innermost last (empty: not reached).
  std::vector<std::vector<MaskFrameKind>> at;
  std::vector<bool> reached;
  int max_depth = 0;
};

// The frames of `code`; false with `error` set when the code is not structured (a jump to an
// instruction with another stack, a frame closed that is not open, a jump out of range).
bool findMaskFrames(const std::vector<Instr>& code, MaskFrames& out, std::string& error);

}  // namespace pf
