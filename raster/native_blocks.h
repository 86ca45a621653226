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
#include "compiler/native/native_cache.h"
#include "raster/lane_kernels.h"
#include "raster/limits.h"
#include "raster/raster_state.h"

namespace pf {

struct BlockTarget;
struct PackedLanes;

// The native instruction set matching the interpreter kernels' (lane_kernels.h).
NativeIsa nativeIsaOf(LaneIsa isa);

// A native pixel program as the executor calls it.
struct NativeBlockFunction {
  NativePixelFunction fn = nullptr;  // null: the interpreter runs the program
  bool reads_state = false;          // LoadState: the state's values are passed
  explicit operator bool() const { return fn != nullptr; }
};

class NativeBlocks {
 public:
  // The function that runs `program` (prim's pixel program or its covered variant) for an
  // instance drawn with `layout`, for one block; null when the interpreter must (native code
  // is unavailable or does not run this program, or the program has not yet run enough blocks
  // to be compiled: native_cache.h). `gang`: for gang blocks (a record of kLanes words per
  // slot).
  NativeBlockFunction find(const CompiledPrimitive& prim, const PixelProgram& program, const ChannelLayout& layout,
                           bool gang);

  // Runs `fn` over the block (aligned at (bx, by), or `packed`'s lanes) for the lanes of
  // `mask`; returns the lanes that committed. Lanes the iteration cap stopped are added to
  // `cap_lanes` and who stopped them to `cap_primitive`.
  uint64_t run(const NativeBlockFunction& fn, const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
               int bx, int by, const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
               const uint32_t* shared_records, uint64_t& cap_lanes, const CompiledPrimitive*& cap_primitive);

  // run() in two steps, for several blocks of one instance: the arguments but the block's set
  // up once (prepare), then each block (call).
  struct PreparedCall {
    NativeBlockArgs args;
    float* planes[kMaxChannels];
    const RasterState* state = nullptr;
    const CompiledPrimitive* prim = nullptr;
    const ChannelLayout* layout = nullptr;
  };
  void prepare(PreparedCall& call, const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout,
               const RasterState& state, uint32_t shade_id, const PackedLanes* packed, const BlockTarget& target,
               const uint32_t* shared_records);
  uint64_t call(const NativeBlockFunction& fn, PreparedCall& call, int bx, int by, uint64_t mask, uint64_t& cap_lanes,
                const CompiledPrimitive*& cap_primitive);

  // Block rejection's verdict for `program` over the region of pixel centres
  // [x_lo, x_hi] x [y_lo, y_hi] by native code (compiler/native/interval_codegen.h): the
  // interpreter's verdict, or false when native code does not (yet) walk this program.
  bool verdict(const PixelProgram& program, const uint32_t* record, const RasterState& state, const double region[4],
               uint32_t& out);
  // The same walk over `lanes` regions at once (kNativeRegionLanes or kNativeVerdictLanes:
  // interval_codegen.h's NativeBlockVerdictsFunction, `regions` their bounds, bound by bound),
  // into `verdicts`; false when native code does not (yet) walk this program so.
  bool verdicts(const PixelProgram& program, const uint32_t* record, const RasterState& state, int lanes,
                const double* regions, uint8_t* verdicts);

  // Forgets what it found (keyed by addresses a later frame may reuse).
  void startFrame();

 private:
  struct Found {
    const PixelProgram* program;
    const Instr* code;
    size_t code_size;
    const ChannelLayout* layout;
    bool gang;
    NativeIsa isa;
    NativeProgramCache::Entry* entry;
    NativeBlockFunction fn;  // fn.fn set once the entry has a function
    bool never;              // the entry settled without one
  };
  struct FoundWalk {
    const PixelProgram* program;
    const Instr* code;
    size_t code_size;
    NativeIsa isa;  // (of a walk over several regions)
    int lanes;      // regions at once: 1 (a NativeVerdictFunction) or more
    NativeProgramCache::Entry* entry;
    void* fn;  // a NativeVerdictFunction or NativeBlockVerdictsFunction
    bool never, reads_state;
  };
  std::vector<FoundWalk> walks_;
  size_t last_walk_ = 0;
  // The walk of `program` over `lanes` regions at once, its function compiled once the walks
  // asked of it pass the threshold.
  FoundWalk* walkFor(const PixelProgram& program, int lanes);
  const float* stateValues(const RasterState& state);
  // The variant `program` of `prim` runs in with `layout` (into variant_).
  const NativePixelVariant& variantFor(const CompiledPrimitive& prim, const ChannelLayout& layout, bool gang,
                                       NativeIsa isa);
  // Where the instance's depth test passes (native_abi.h's kDepthPass* bits).
  static uint32_t depthPass(const RasterState& state);
  PreparedCall single_;  // run()'s
  std::vector<Found> found_;  // (its storage kept across frames: a frame allocates nothing)
  NativePixelVariant variant_;  // the one being looked up (its vectors' storage kept)
  size_t last_ = 0;
  // The state values LoadState reads, for the last state seen.
  RasterState values_state_;
  bool values_valid_ = false;
  float state_values_[kStateValueCount] = {};
};

}  // namespace pf
