// The rasterizer's side of native pixel programs (compiler/native/): which compiled function
// runs a block -- the program specialised on the instance's layout, the depth state and the
// block's shape, found in the process-wide cache and remembered per executor for the frame --
// and the call itself, with the block's arguments. The rasterizer knows no LLVM: it sees a
// function pointer and the plain structs of compiler/native/native_abi.h.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/compiler.h"
#include "compiler/native/native_abi.h"
#include "raster/raster_state.h"

namespace pf {

struct BlockTarget;
struct PackedLanes;

// A native pixel program as the executor calls it.
struct NativeBlockFunction {
  NativePixelFunction fn = nullptr;  // null: the interpreter runs the program
  bool reads_state = false;          // LoadState: the state's values are passed
  explicit operator bool() const { return fn != nullptr; }
};

class NativeBlocks {
 public:
  // The function that runs `program` (prim's pixel program or its covered variant) for an
  // instance drawn with `layout` and `state` into `target`, on blocks of `shape`; null when the
  // interpreter must (native code is unavailable, or does not run this program).
  NativeBlockFunction find(const CompiledPrimitive& prim, const PixelProgram& program, const ChannelLayout& layout,
                           const RasterState& state, const BlockTarget& target, NativeBlockShape shape);

  // Runs `fn` over the block (aligned at (bx, by), or `packed`'s lanes) for the lanes of
  // `mask`; returns the lanes that committed. Lanes the iteration cap stopped are added to
  // `cap_lanes` and who stopped them to `cap_primitive`.
  uint64_t run(const NativeBlockFunction& fn, const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
               int bx, int by, const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
               const uint32_t* shared_records, uint64_t& cap_lanes, const CompiledPrimitive*& cap_primitive);

  // Forgets what it found (keyed by addresses a later frame may reuse).
  void startFrame();

 private:
  struct Found {
    const PixelProgram* program;
    const Instr* code;
    size_t code_size;
    const ChannelLayout* layout;
    uint8_t depth;  // depth compare, buffer, commit
    NativeBlockShape shape;
    NativeIsa isa;
    NativeBlockFunction fn;
  };
  std::vector<Found> found_;  // (its storage kept across frames: a frame allocates nothing)
  NativePixelVariant variant_;  // the one being looked up (its vectors' storage kept)
  size_t last_ = 0;
  // The state values LoadState reads, for the last state seen.
  RasterState values_state_;
  bool values_valid_ = false;
  float state_values_[kStateValueCount] = {};
};

}  // namespace pf
