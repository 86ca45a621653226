// Setup across instances: the setup program (compiler/isa.h) of up to kSetupBatchLanes
// instances of one primitive, under one state and channel layout, run at once, one instance
// per lane -- each instruction decoded once for all of them, its arithmetic a loop over the
// lanes that GCC vectorizes (as the pixel executor's kernels; docs/architecture.md).
//
// Exactly the scalar executor's results, instance by instance: the lanes run the same
// instructions only while they take the same path. A conditional jump that some lanes take and
// others do not splits them: the smaller group leaves the batch -- its registers, loop counters
// and effects so far are handed to the scalar SetupExecutor (resume()), which finishes each of
// those instances from its next instruction -- and the larger group goes on. The same happens
// at instructions that are not batched (calls of other primitives: OutParam, OutVertex, Emit)
// for every lane, and when fewer than kMinBatchLanes lanes would go on.
//
// Native code (compiler/native/setup_codegen.h), once the program has set up enough instances
// to be compiled, runs the batch while its lanes agree and hands it to this loop where they
// part: the same results, bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/native/native_abi.h"
#include "compiler/native/native_cache.h"
#include "raster/setup_executor.h"

namespace pf {

constexpr int kSetupBatchLanes = 16;
// Below this many lanes a batch (or what is left of one after a split) runs scalar.
constexpr int kMinBatchLanes = 4;

// What the batched executor did, for tests and the docs' figures.
struct SetupBatchCounters {
  uint64_t batches = 0;           // run() calls that ran batched
  uint64_t lanes_batched = 0;     // instances that finished in the batch
  uint64_t lanes_resumed = 0;     // instances handed to the scalar executor part-way
  uint64_t lanes_scalar = 0;      // instances run scalar from the start
  uint64_t batches_native = 0;    // batches native code ran (to their end or where they parted)
  uint64_t lanes_native = 0;      // instances whose setup native code ran to its end or kill
};

class BatchSetupExecutor {
 public:
  // Sets up `count` instances: in[i], records[i] (recordWords() room each) and out[i] are
  // instance i's. Instances that cannot share a batch (different states, layouts, sequence
  // counts or depths, or a primitive that calls others) and batches of fewer than
  // kMinBatchLanes run scalar. Any count: batches are formed kSetupBatchLanes at a time.
  // With use_native, native code runs the batches once it is compiled (nativeFunction()).
  void run(const CompiledPrimitive& prim, const SetupInput* in, int count, uint32_t* const* records,
           SetupOutput* out);
  // The same, every batch run by `native` (null: the interpreter), nativeFunction()'s answer
  // for these instances' program and layout -- looked up once for a draw's batches.
  void run(const CompiledPrimitive& prim, const SetupInput* in, int count, uint32_t* const* records,
           SetupOutput* out, NativeSetupFunction native);

  // The native function that sets up `instances` more instances of `prim` drawn with `layout`:
  // null while the program has not yet set up enough instances to be compiled (they count
  // towards it: native_cache.h), or when native code is off, unavailable or refuses it.
  NativeSetupFunction nativeFunction(const CompiledPrimitive& prim, const ChannelLayout& layout, int instances);

  // Sizes the batch's register files for `prim` with `layout`'s channels, as runBatch would on
  // its first batch. The renderer calls it for every thread's executor on the submitting thread
  // before spreading batches across the pool, so that which thread happens to run a batch first
  // (the machine's load decides) never decides when memory is allocated.
  void reserveFor(const CompiledPrimitive& prim, const ChannelLayout& layout);

  // True where batching can pay: a primitive with no callees (an Emit would leave the batch,
  // and the callees' instances must be binned between their callers').
  static bool batchable(const CompiledPrimitive& prim) { return prim.callees.empty(); }

  SetupBatchCounters counters;
  // Tests: batch primitives that call others too (their calls leave the batch at OutParam; a
  // lane resumed earlier may then submit its calls before an earlier lane's).
  bool batch_callers = false;
  // Native code runs batches once compiled (the renderer's choice: PF_JIT, the context's).
  bool use_native = false;

 private:
  void runBatch(const CompiledPrimitive& prim, const SetupInput* in, int lanes, uint32_t* const* records,
                SetupOutput* out, NativeSetupFunction native);
  // Hands lane `l` to the scalar executor at `pc`.
  void finishScalar(const CompiledPrimitive& prim, const SetupInput& in, int l, uint32_t pc, uint32_t* record,
                    SetupOutput& out, uint32_t instructions, const uint32_t* loop_counters, int loop_depth);

  SetupExecutor scalar_;
  NativeSetupVariant variant_;
  NativeSetupArgs native_args_;
  // The last program's cache entry, found again by content (its code, constants, exports and
  // variant) without building the cache's key: a draw looks its program up once per batch.
  struct Remembered {
    std::vector<Instr> code;
    std::vector<uint32_t> constants, scalar_exports, interp_exports;
    uint32_t num_regs = 0, num_interp_regs = 0;
    NativeSetupVariant variant;
    NativeProgramCache::Entry* entry = nullptr;
  };
  Remembered remembered_;
  RasterState cached_state_;  // the state values of the last state seen, as the scalar executor's
  bool state_cached_ = false;
  float state_values_[kStateValueCount] = {};
  // Lane-major files: register / constant / parameter r of lane l at regs_[r * K + l]; interp
  // register i, channel c of lane l at interp_[(i * channels + c) * K + l].
  std::vector<uint32_t> regs_;
  std::vector<float> interp_;
};

}  // namespace pf
