// Runs a primitive's setup program (compiler/isa.h), scalar, once per instance: from its
// parameters and per-vertex channels to the uniform record the pixel program reads, the screen
// bound, or the verdict that the instance draws nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/compiler.h"
#include "raster/raster_state.h"

namespace pf {

// Where the instances a primitive's setup calls (Op::Emit) go: the renderer submits them.
class SubInstanceSink {
 public:
  virtual ~SubInstanceSink() = default;
  // The callee, its parameter block and its sequence points' channels; `depth` is the
  // caller's call depth + 1.
  virtual void submitCall(const CompiledPrimitive& callee, const uint32_t* params,
                          const float* vertex_channels, int depth) = 0;
};

struct SetupInput {
  const uint32_t* params;     // CompiledPrimitive::paramFloats(sequence_points) 32-bit values
  const float* vertex_channels;  // sequence_points x layout.count floats
  const ChannelLayout* layout;
  const RasterState* state;
  int sequence_points = 0;    // of this instance
  SubInstanceSink* sink = nullptr;  // null: calls of other primitives are dropped
  int depth = 0;              // how deep in calls of primitives this instance is
};

struct SetupOutput {
  bool killed = false;
  bool iteration_cap_hit = false;  // killed because a loop ran past the context's cap
  bool has_bound = false;
  bool back_facing = false;  // facing(): the instance shows its back
  uint32_t instructions = 0;  // executed
  float bound[4] = {0, 0, 0, 0};  // xmin, ymin, xmax, ymax in window coordinates
  // depth_bound(): every depth the instance's pixels test lies in [depth_bound[0], depth_bound[1]].
  bool has_depth_bound = false;
  float depth_bound[2] = {0, 0};
};

// An instance part-way through its setup program, as a batched executor (setup_batch.h)
// leaves it: where it is, its registers and loop counters, and its effects so far.
struct SetupResume {
  uint32_t pc = 0;                  // the next instruction to run
  const uint32_t* regs = nullptr;   // register r at regs[r * reg_stride] (num_regs of them)
  size_t reg_stride = 1;
  const float* interp = nullptr;    // interp register i, channel c at interp[(i * channels + c) * interp_stride]
  size_t interp_stride = 1;
  const uint32_t* loop_counters = nullptr;  // of the loops open at pc, outermost first
  int loop_depth = 0;
  SetupOutput out;                  // bound, facing and instruction count so far
};

class SetupExecutor {
 public:
  // Writes the record (pixel.num_uniform_slots words, then the interp slots, layout.count
  // floats each) to `record`, which must have recordWords() room.
  SetupOutput run(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record);
  // Finishes an instance from `from.pc` with `from`'s registers: exactly what run() gives for an
  // instance that reached that point in that state.
  SetupOutput resume(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record, const SetupResume& from);
  static size_t recordWords(const CompiledPrimitive& prim, int channels) {
    return prim.pixel.num_uniform_slots + static_cast<size_t>(prim.pixel.num_interp_uniform_slots) * channels;
  }

 private:
  // Every state value of the last state seen, so LoadState is a load (instances of one glBegin
  // share their state).
  void cacheState(const RasterState& state);
  // Loads the register file (zeroed registers, constants, the fixed parameters) and zeroes the
  // interp registers.
  void load(const CompiledPrimitive& prim, const SetupInput& in);
  // Runs from `pc` to the end or a kill; `out` holds the effects so far.
  SetupOutput execute(const CompiledPrimitive& prim, const SetupInput& in, uint32_t* record, size_t pc,
                      SetupOutput out, const uint32_t* loop_counters, int loop_depth);
  RasterState cached_state_;
  bool state_cached_ = false;
  float state_values_[kStateValueCount] = {};

  std::vector<uint32_t> regs_;
  std::vector<float> interp_;
  // The outgoing instance of a call: its parameter block and sequence points' channels.
  std::vector<uint32_t> out_params_;
  std::vector<float> out_vertices_;
};

}  // namespace pf
