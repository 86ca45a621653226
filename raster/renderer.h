// The renderer behind a context: setup on submission, binning into screen tiles, and at flush
// the tiles run on the worker threads: for each instance in a tile's bin, its pixel program
// over the pixel blocks of its bound; then the tile's shading pass.
//
//   submit()  -> SetupExecutor (scalar, once per instance) -> Scene bins
//   submitInstances() -> BatchSetupExecutor (16 instances at a time) -> Scene bins, in order
//   flush()   -> WorkerPool: per tile: clear, PixelExecutor per block, shadeTile
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "raster/coarse_depth.h"
#include "raster/gang_block.h"
#include "raster/pixel_executor.h"
#include "raster/scene.h"
#include "raster/setup_batch.h"
#include "raster/setup_executor.h"
#include "raster/worker_pool.h"

namespace pf {

// Work counters for the frames since the last reset (as llvmpipe's LP_COUNT): cheap enough to
// stay on; `pfrender --stats` prints them.
struct FrameStats {
  uint64_t instances_submitted = 0;
  uint64_t instances_killed = 0;      // setup decided the instance draws nothing
  uint64_t bin_entries = 0;           // (instance, tile) pairs
  uint64_t tiles_run = 0;             // tiles with at least one instance
  uint64_t tiles_skipped = 0;         // tiles no instance's bound touches (cleared, nothing run)
  uint64_t blocks_run = 0;
  uint64_t blocks_rejected = 0;       // skipped whole by interval tests (raster/block_rejection.h)
  uint64_t lanes_started = 0;
  uint64_t lanes_committed = 0;
  uint64_t blocks_covered = 0;        // blocks run whose every lane committed
  uint64_t blocks_accepted = 0;       // blocks run without coverage tests (PixelProgram::covered)
  uint64_t blocks_walked = 0;         // blocks rejected or accepted by their own verdict, their
                                      // region's undecided (native code: PixelExecutor::blockVerdict)
  uint64_t region_walks = 0;          // native code's walks over an undecided region's 16 blocks
                                      // (PixelExecutor::BlockWalkTally: only where they pay)
  uint64_t blocks_native = 0;         // blocks run by native code (compiler/native/), not the interpreter
  uint64_t blocks_packed = 0;         // blocks run on packed lanes (a small bound's pixels)
  uint64_t blocks_ganged = 0;         // packed blocks holding several instances' pixels (raster/gang_block.h)
  uint64_t blocks_depth_culled = 0;   // (instance, block) pairs skipped by coarse depth culling
                                      // (raster/coarse_depth.h; not in blocks_run)
  uint64_t pixels_depth_culled = 0;   // pixels of small instances left out of packed lanes by it
  uint64_t pixels_shaded = 0;
  uint64_t gbuffer_bytes = 0;         // G-buffer the tiles run used: per tile, the frame's layout's
                                      // slots and the shading-state ids, 64x64 x 4 bytes each
  uint64_t setup_instructions = 0;    // executed by setup programs
  uint64_t pixel_instructions = 0;    // executed by interpreted pixel programs, once per block
  uint64_t iteration_cap_pixels = 0;  // pixels stopped by the iteration cap
  uint64_t iteration_cap_instances = 0;  // instances stopped by it in setup
  field::FieldCounters field;         // implicit surfaces (field_hit): rays, evaluations, culling
  uint64_t unknown_field_lanes = 0;   // field_hit / field_gradient lanes naming no field
};

// Runaway primitives since the last report: what the API turns into an error and a log line.
struct IterationCapReport {
  uint64_t pixels = 0, instances = 0;
  std::string primitive;  // one of the primitives that hit the cap
};

class Renderer : private SubInstanceSink {
 public:
  explicit Renderer(int threads);

  int threadCount() const { return pool_.threadCount(); }
  // The colour buffer (caller's, RGBA8, row 0 at the bottom), the depth buffer and the 8-bit
  // stencil buffer (each may be null).
  void setTarget(uint8_t* color, float* depth, int width, int height, uint8_t* stencil = nullptr);

  // Recorded; applied at flush before the instances that follow it. `color_mask`: the RGBA
  // channels (bit k: channel k) the colour clear writes; `rect`: the pixels cleared.
  void clear(bool color, bool depth, const float rgba[4], float z, uint8_t color_mask = 0xf,
             const PixelRect& rect = PixelRect{});
  // The stencil buffer's clear: `value` into the bits of `write_mask`, within `rect`; recorded
  // like clear() (a pending clear of another rectangle is flushed first).
  void clearStencil(uint8_t value, uint8_t write_mask, const PixelRect& rect = PixelRect{});

  // Runs setup and bins the instance (`sequence_points`: how many it has, for primitives
  // with parameter-sized arrays; otherwise the primitive's own count). Instances of other
  // primitives its setup calls are submitted as it runs, each binned on its own, in order.
  // Returns false if setup killed it.
  // `shared_params`: the parameter block of each of the layout's shared interpolators (their
  // setup runs once here, for this instance and every instance it calls). `per_pixel_lighting`:
  // GL's lighting for pixels of primitives that set N (layout.surface_slot), snapshotted.
  bool submit(const CompiledPrimitive& prim, const uint32_t* params, const float* vertex_channels,
              const ChannelLayout& layout, const RasterState& state, const ShadeState& shade,
              int sequence_points = -1, const uint32_t* const* shared_params = nullptr,
              const LightingState* per_pixel_lighting = nullptr);

  // `instances` instances of one primitive under one state, layout and shade (consecutive
  // instances of one glBegin): as submit() of each in turn -- the same records, bins and
  // counters, in the same order -- with their setup run kSetupBatchLanes at a time across
  // instances (BatchSetupExecutor) where that pays. Instance i's parameters start at
  // params + i * param_stride, its channels at vertex_channels + i * vertex_stride, its shared
  // interpolators' blocks at shared_params + i * layout.shared.size().
  void submitInstances(const CompiledPrimitive& prim, int instances, const uint32_t* params, size_t param_stride,
                       const float* vertex_channels, size_t vertex_stride, const ChannelLayout& layout,
                       const RasterState& state, const ShadeState& shade, int sequence_points = -1,
                       const uint32_t* const* shared_params = nullptr,
                       const LightingState* per_pixel_lighting = nullptr);
  // Batched setup on or off (on unless the environment says PF_SETUP_BATCH=0).
  void setSetupBatching(bool on) { setup_batching_ = on; }
  bool setupBatching() const { return setup_batching_; }
  // Coarse depth culling of instances with a depth_bound() on or off (on unless the environment
  // says PF_DEPTH_CULL=0; images are identical either way).
  void setDepthCulling(bool on) { depth_culling_ = on; }
  bool depthCulling() const { return depth_culling_; }
  // Gang blocks (raster/gang_block.h) on or off (on unless the environment says
  // PF_GANG_BLOCKS=0; images are identical either way).
  void setGangBlocks(bool on) { gang_blocks_ = on; }
  // Pixel programs as native code (compiler/native/) where it can, or all on the interpreter
  // (on unless the environment says PF_JIT=0; images are identical either way).
  void setNativeCode(bool on);
  bool nativeCode() const { return native_code_; }
  // The batched setup's counters, summed over the threads that ran batches.
  SetupBatchCounters setupBatchCounters() const;

  // Executes everything recorded: afterwards the colour and depth buffers hold the image.
  void flush();
  bool pending() const { return !scene_.empty(); }

  // Takes (and clears) the iteration-cap hits since the last call.
  IterationCapReport takeIterationCapReport() {
    IterationCapReport r = cap_report_;
    cap_report_ = IterationCapReport{};
    return r;
  }

  const FrameStats& stats() const { return stats_; }
  void resetStats() { stats_ = FrameStats{}; }
  // Drops everything recorded since the last flush (after a failed allocation: the API reports
  // GL_OUT_OF_MEMORY and the next frame starts clean).
  void discardPending();

 private:
  struct WorkerScratch {
    PixelExecutor executor;
    PackedLanes packed_lanes;
    PixelExecutor::AlignedBlocks aligned_blocks;  // an instance's blocks in a tile, run together
    CoarseDepth coarse_depth;
    GangBlock gang;
    uint64_t blocks_depth_culled = 0;
    uint64_t pixels_depth_culled = 0;
    std::vector<uint32_t> shade_ids;
    // Ordered draws (fragment_ops.h): the pixels the alpha test discarded, and the depth under
    // the instance before it ran (restored where its fragment was discarded).
    std::vector<uint8_t> discarded;
    std::vector<float> depth_before;
    std::vector<uint8_t> covered;  // a stencil draw's pixels over its bound (its first run)
    std::vector<float> gbuffer;
    std::vector<float*> slot_planes;
    uint64_t pixels_shaded = 0;
    uint64_t tiles_run = 0;
  };

  void runTile(int tile, WorkerScratch& scratch);
  // runTile's parts: the pending clear within the tile; shading the pixels committed to the
  // tile's G-buffer (`ordered`: an ordered draw's, through its fragment operations, the depth
  // restored under its discarded fragments from depth_before over `bound`), then emptying it.
  void clearTile(int x0, int y0, int w, int h);
  void resolveTile(WorkerScratch& s, int x0, int y0, int w, int h, const RasterState* ordered, const PixelRect& bound);
  // A stencil draw (fragment_ops.h) runs twice: a first run without the depth test finds the
  // pixels it covers; coverStencil keeps them (less those the alpha test discards) and empties
  // the G-buffer. A second run with the depth test commits those that pass it; applyStencil
  // then gives each covered pixel's stencil value the operation its tests say and drops the
  // fragments that failed the stencil test (their depth put back). The next resolveTile
  // writes the colours of the rest.
  void coverStencil(WorkerScratch& s, int x0, int y0, int w, int h, const RasterState& state, const PixelRect& bound);
  void applyStencil(WorkerScratch& s, int x0, int y0, const RasterState& state, const PixelRect& bound);
  // submit()'s parts: the state, layout and shade bookkeeping (false: no target), the shared
  // interpolators' setup, and the binning of an instance set up.
  bool beginSubmission(const ChannelLayout& layout, const RasterState& state, const ShadeState& shade,
                       const LightingState* per_pixel_lighting);
  void runShared(const ChannelLayout& layout, const uint32_t* const* shared_params);
  bool binInstance(const CompiledPrimitive& prim, const SetupOutput& out, size_t offset);
  bool submitAt(const CompiledPrimitive& prim, const uint32_t* params, const float* vertex_channels,
                int sequence_points, int depth);
  void submitCall(const CompiledPrimitive& callee, const uint32_t* params, const float* vertex_channels,
                  int depth) override;

  WorkerPool pool_;
  Scene scene_;
  // One executor per depth of primitive calls: a caller's registers stay put while its callee runs.
  SetupExecutor setups_[kMaxPrimitiveCallDepth + 1];
  std::vector<uint32_t> record_scratch_[kMaxPrimitiveCallDepth + 1];
  // One per thread: the batches of a submission are set up across the pool.
  std::vector<std::unique_ptr<BatchSetupExecutor>> batch_setups_;
  std::vector<uint32_t> batch_records_;  // setup's records where they cannot go to the scene's directly
  std::vector<SetupOutput> batch_outputs_;
  bool setup_batching_ = true;
  bool pack_small_bounds_ = true;  // PF_PACKED_LANES=0: every instance on aligned blocks
  bool depth_culling_ = true;      // PF_DEPTH_CULL=0: no coarse depth culling
  bool gang_blocks_ = true;        // PF_GANG_BLOCKS=0: small instances packed one at a time
  bool native_code_ = PixelExecutor::nativeWanted();  // PF_JIT=0: pixel programs interpreted
  uint64_t flushes_ = 0;
  uint32_t shared_offset_ = kNoShared;  // the shared records of the submission in progress
  uint64_t calls_this_submission_ = 0;  // instances its primitive calls made (submitCall)
  uint64_t calls_budget_ = 0;           // and how many it may make before they are a runaway's
  std::vector<std::unique_ptr<WorkerScratch>> scratch_;
  uint8_t* color_ = nullptr;
  float* depth_ = nullptr;
  uint8_t* stencil_ = nullptr;
  int width_ = 0, height_ = 0;
  FrameStats stats_;
  IterationCapReport cap_report_;
};

}  // namespace pf
