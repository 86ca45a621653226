// The renderer (see renderer.h).
#include "raster/renderer.h"

#include "raster/lane_count.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace pf {
namespace {

// The largest bound (pixels within a tile) that joins gang blocks: past it, aligned blocks
// wholly inside the bound may be skipped or run without coverage tests (block rejection), and
// few lanes are left empty anyway.
constexpr int kGangArea = 4 * kLanes;

// Setup across the pool (Renderer::submitInstances): jobs of at least this many batches, and
// this many jobs a thread (a thread that starts late still gets a share).
constexpr int kMinBatchesPerJob = 16;
constexpr int kSetupJobsPerThread = 2;

// Whether the pixels [ix0, ix1) x [iy0, iy1) of the tile at (x0, y0) run in fewer blocks packed
// (PixelExecutor::runPackedBlock) than on the aligned blocks they touch -- and none of those
// blocks lies wholly inside them, where block rejection might skip it or run it without
// coverage tests (a larger bound keeps the aligned blocks).
bool packsBetter(int ix0, int ix1, int iy0, int iy1, int x0, int y0) {
  auto blocksTouched = [](int a0, int a1, int origin) {
    return (a1 - 1 - origin) / kBlockSize - (a0 - origin) / kBlockSize + 1;
  };
  auto blocksInside = [](int a0, int a1, int origin) {
    return std::max(0, (a1 - origin) / kBlockSize - (a0 - origin + kBlockSize - 1) / kBlockSize);
  };
  if (ix1 <= ix0 || iy1 <= iy0) return false;
  if (blocksInside(ix0, ix1, x0) > 0 && blocksInside(iy0, iy1, y0) > 0) return false;
  const int packed = ((ix1 - ix0) * (iy1 - iy0) + kLanes - 1) / kLanes;
  return packed < blocksTouched(ix0, ix1, x0) * blocksTouched(iy0, iy1, y0);
}

}  // namespace

Renderer::Renderer(int threads) : pool_(threads) {
  // PF_SETUP_BATCH=0: every instance's setup scalar (for comparisons; images are identical).
  if (const char* e = std::getenv("PF_SETUP_BATCH")) setup_batching_ = std::strcmp(e, "0") != 0;
  // PF_PACKED_LANES=0: small bounds on aligned blocks too (for comparisons; images are identical).
  if (const char* e = std::getenv("PF_PACKED_LANES")) pack_small_bounds_ = std::strcmp(e, "0") != 0;
  // PF_GANG_BLOCKS=0: small instances packed one at a time (for comparisons; images are identical).
  if (const char* e = std::getenv("PF_GANG_BLOCKS")) gang_blocks_ = std::strcmp(e, "0") != 0;
  // PF_DEPTH_CULL=0: no coarse depth culling (for comparisons; images are identical).
  if (const char* e = std::getenv("PF_DEPTH_CULL")) depth_culling_ = std::strcmp(e, "0") != 0;
  for (int i = 0; i < pool_.threadCount(); ++i) {
    scratch_.push_back(std::make_unique<WorkerScratch>());
    scratch_.back()->executor.use_native = native_code_;
    batch_setups_.push_back(std::make_unique<BatchSetupExecutor>());
    batch_setups_.back()->use_native = native_code_;
  }
}

void Renderer::setTarget(uint8_t* color, float* depth, int width, int height, uint8_t* stencil) {
  if (pending()) flush();
  const int tiles_x = (width + kTileSize - 1) / kTileSize, tiles_y = (height + kTileSize - 1) / kTileSize;
  // The new bins first: if they cannot be allocated (std::bad_alloc), the old target stands.
  std::vector<TileBin> bins(static_cast<size_t>(tiles_x) * tiles_y);
  scene_.bins.swap(bins);
  scene_.tiles_x = tiles_x;
  scene_.tiles_y = tiles_y;
  color_ = color;
  depth_ = depth;
  stencil_ = stencil;
  width_ = width;
  height_ = height;
}

void Renderer::clear(bool color, bool depth, const float rgba[4], float z, uint8_t color_mask, const PixelRect& rect) {
  // A clear after drawing ends the frame so far: what was drawn must land first; so does a
  // pending colour clear with another mask, and a pending clear of another rectangle.
  if (!scene_.instances.empty() || (color && scene_.clear.color && scene_.clear.color_mask != color_mask) ||
      (scene_.clearing() && !(scene_.clear.rect == rect)))
    flush();
  scene_.clear.rect = rect;
  if (color) {
    scene_.clear.color = true;
    scene_.clear.color_mask = color_mask;
    std::copy(rgba, rgba + 4, scene_.clear.rgba);
  }
  if (depth) {
    scene_.clear.depth = true;
    scene_.clear.z = z;
  }
}

namespace {

// Pixels whose centres x + 0.5 can lie in [lo, hi], clamped to [clip_lo, clip_hi).
void pixelRange(float lo, float hi, int clip_lo, int clip_hi, int& out_lo, int& out_hi) {
  out_lo = clip_lo;
  out_hi = clip_hi;
  if (std::isfinite(lo) && lo - 0.5f > static_cast<float>(clip_lo))
    out_lo = lo - 0.5f >= static_cast<float>(clip_hi) ? clip_hi : static_cast<int>(std::ceil(lo - 0.5f));
  if (std::isfinite(hi) && hi - 0.5f < static_cast<float>(clip_hi))
    out_hi = hi - 0.5f < static_cast<float>(clip_lo) ? clip_lo : static_cast<int>(std::floor(hi - 0.5f)) + 1;
}

}  // namespace

bool Renderer::beginSubmission(const ChannelLayout& layout, const RasterState& state, const ShadeState& shade,
                               const LightingState* per_pixel_lighting) {
  if (!color_) return false;
  // The API refuses more channels than this (its reject reason names them); a caller of the
  // renderer itself gets nothing drawn rather than a commit past the executor's tables.
  if (layout.count > kMaxChannels) return false;
  // The shading pass writes with one colour mask: instances with another wait for a flush.
  if (!scene_.instances.empty() && scene_.color_mask != state.color_mask) flush();
  if (scene_.records.size() > kMaxRecordWords) flush();  // offsets into the records are 32-bit
  scene_.color_mask = state.color_mask;
  // Shared state: appended only when it changes.
  if (scene_.states.empty() || !(scene_.states.back() == state)) scene_.states.push_back(state);
  if (scene_.layouts.empty() || !(scene_.layouts.back() == layout)) scene_.layouts.push_back(layout);
  ShadeState lit_shade;
  if (per_pixel_lighting && layout.surface_slot >= 0) {
    if (scene_.lightings.empty() || !(scene_.lightings.back() == *per_pixel_lighting)) {
      scene_.lighting_equations.emplace_back(*per_pixel_lighting);
      try {
        scene_.lightings.push_back(*per_pixel_lighting);
      } catch (...) {  // the two stay in step (std::bad_alloc)
        scene_.lighting_equations.pop_back();
        throw;
      }
    }
    lit_shade = shade;
    lit_shade.surface_slot = layout.surface_slot;
    lit_shade.lighting = static_cast<int>(scene_.lightings.size()) - 1;
  }
  const ShadeState& instance_shade = per_pixel_lighting && layout.surface_slot >= 0 ? lit_shade : shade;
  if (scene_.shades.empty() || !(scene_.shades[scene_.current_shade] == instance_shade)) {
    scene_.current_shade = static_cast<uint32_t>(scene_.shades.size());
    scene_.shades.push_back(instance_shade);
    if (instance_shade.back_color_slot >= 0) {  // its back variant follows it
      ShadeState back = instance_shade;
      back.color_slot = instance_shade.back_color_slot;
      back.back_color_slot = -1;
      scene_.shades.push_back(back);
    }
  }
  if (scene_.states.size() > 0xffff || scene_.layouts.size() > 0xffff) {
    flush();
    return beginSubmission(layout, state, shade, per_pixel_lighting);
  }
  calls_this_submission_ = 0;
  calls_budget_ = kCallsPerIteration * state.iteration_cap;
  return true;
}

void Renderer::runShared(const ChannelLayout& layout, const uint32_t* const* shared_params) {
  // The shared interpolators' uniforms: their setup programs, once for the whole submission.
  shared_offset_ = kNoShared;
  if (!layout.shared.empty() && shared_params) {
    shared_offset_ = static_cast<uint32_t>(scene_.records.size());
    size_t words = 0;
    for (const ChannelLayout::SharedInterpolator& s : layout.shared)
      words = std::max(words, s.record_offset + SetupExecutor::recordWords(*s.program, 0));
    scene_.records.resize(shared_offset_ + words, 0u);
    static const ChannelLayout kNoChannels;
    for (size_t k = 0; k < layout.shared.size(); ++k) {
      const ChannelLayout::SharedInterpolator& s = layout.shared[k];
      SetupInput in{shared_params[k], nullptr, &kNoChannels, &scene_.states.back(), 1, nullptr, 0};
      SetupOutput out = setups_[0].run(*s.program, in, scene_.records.data() + shared_offset_ + s.record_offset);
      stats_.setup_instructions += out.instructions;
    }
  }
}

bool Renderer::submit(const CompiledPrimitive& prim, const uint32_t* params, const float* vertex_channels,
                      const ChannelLayout& layout, const RasterState& state, const ShadeState& shade,
                      int sequence_points, const uint32_t* const* shared_params,
                      const LightingState* per_pixel_lighting) {
  if (!beginSubmission(layout, state, shade, per_pixel_lighting)) return false;
  runShared(layout, shared_params);
  const int points = sequence_points < 0 ? prim.sequence_points : sequence_points;
  // A strip or polygon calls `triangles` once a vertex, each quad twice: calls in proportion to
  // the vertices are the input's, never a runaway's.
  calls_budget_ = kCallsPerIteration * state.iteration_cap + 4 * static_cast<uint64_t>(std::max(points, 0));
  return submitAt(prim, params, vertex_channels, points, 0);
}

void Renderer::submitInstances(const CompiledPrimitive& prim, int instances, const uint32_t* params,
                               size_t param_stride, const float* vertex_channels, size_t vertex_stride,
                               const ChannelLayout& layout, const RasterState& state, const ShadeState& shade,
                               int sequence_points, const uint32_t* const* shared_params,
                               const LightingState* per_pixel_lighting) {
  const size_t nshared = layout.shared.size();
  auto sharedOf = [&](int i) { return shared_params ? shared_params + static_cast<size_t>(i) * nshared : nullptr; };
  if (sequence_points < 0) sequence_points = prim.sequence_points;
  if (!setup_batching_ || !BatchSetupExecutor::batchable(prim) || instances < kMinBatchLanes || !color_) {
    for (int i = 0; i < instances; ++i)
      submit(prim, params + i * param_stride, vertex_channels + i * vertex_stride, layout, state, shade,
             sequence_points, sharedOf(i), per_pixel_lighting);
    return;
  }
  // Each instance's bookkeeping, in order, as submit() would do it: the state, layout and
  // shade, then its shared interpolators. An instance whose bookkeeping appended nothing and
  // flushed nothing leaves the scene as the next one's would find it: that one's would do
  // nothing either (the comparisons are of the same values), unless the records outgrow
  // their bound.
  bool steady = false;
  auto bookkeeping = [&](int i) {
    if (steady && scene_.records.size() <= kMaxRecordWords) {
      calls_this_submission_ = 0;
    } else {
      const size_t appended = scene_.states.size() + scene_.layouts.size() + scene_.shades.size() +
                              scene_.lightings.size();
      const uint64_t flushes = flushes_;
      const uint32_t current_shade = scene_.current_shade;
      if (!beginSubmission(layout, state, shade, per_pixel_lighting)) return false;
      steady = flushes == flushes_ && current_shade == scene_.current_shade &&
               appended == scene_.states.size() + scene_.layouts.size() + scene_.shades.size() +
                               scene_.lightings.size();
    }
    runShared(layout, sharedOf(i));
    return true;
  };
  // Setup, every few batches of kSetupBatchLanes instances a job for the pool (it reads only the
  // instances, the state and the layout, and writes their records and outputs: which thread ran
  // it changes nothing); then each instance in order exactly as submit() would: its
  // bookkeeping, then its record and bins.
  //
  // Where the bookkeeping of the first instances leaves the scene steady and appends no shared
  // records between instances, setup writes the records straight into the scene's, in order,
  // and binning only closes the gaps the instances it drops leave (a copy of every record
  // through a scratch buffer cost more than binning did). The bookkeeping runs first then: it
  // reads nothing setup writes, and every instance here has the same state, layout and shade.
  const size_t words = SetupExecutor::recordWords(prim, layout.count);
  const size_t chunk_words = words * static_cast<size_t>(instances);
  int booked = 0;  // instances whose bookkeeping is done
  bool direct = nshared == 0 && !prim.pixel.code.empty() && prim.callees.empty();
  while (direct && booked < instances && !steady) {
    if (!bookkeeping(booked++)) return;
  }
  direct = direct && steady && scene_.records.size() + chunk_words <= kMaxRecordWords;
  const size_t base = scene_.records.size();
  uint32_t* const records_at = direct ? (scene_.records.resize(base + chunk_words), scene_.records.data() + base)
                                      : (batch_records_.resize(chunk_words + 1), batch_records_.data());
  batch_outputs_.resize(static_cast<size_t>(instances));
  const int batches = (instances + kSetupBatchLanes - 1) / kSetupBatchLanes;
  const NativeSetupFunction native = batch_setups_[0]->nativeFunction(prim, layout, instances);
  auto setupBatch = [&](int b, int worker) {
    const int first = b * kSetupBatchLanes, lanes = std::min(kSetupBatchLanes, instances - first);
    SetupInput in[kSetupBatchLanes];
    uint32_t* records[kSetupBatchLanes];
    for (int l = 0; l < lanes; ++l) {
      const int i = first + l;
      in[l] = SetupInput{params + i * param_stride, vertex_channels + i * vertex_stride, &layout, &state,
                         sequence_points, nullptr, 0};
      records[l] = records_at + words * static_cast<size_t>(i);
    }
    batch_setups_[static_cast<size_t>(worker)]->run(prim, in, lanes, records, batch_outputs_.data() + first, native);
  };
  // Jobs of contiguous batches, a few a thread: a job a batch took the pool's lock and shared
  // cache lines between the threads at every batch, and was slower on two threads than on one.
  const int threads = pool_.threadCount();
  const int jobs = batches >= kMinBatchesPerJob * 2 && threads > 1
                       ? std::min(batches / kMinBatchesPerJob, threads * kSetupJobsPerThread)
                       : 1;
  auto setupJob = [&](int job, int worker) {
    const int from = static_cast<int>(static_cast<int64_t>(batches) * job / jobs);
    const int to = static_cast<int>(static_cast<int64_t>(batches) * (job + 1) / jobs);
    for (int b = from; b < to; ++b) setupBatch(b, worker);
  };
  if (jobs > 1) {
    for (const auto& b : batch_setups_) b->reserveFor(prim, layout);
    // (A closure of one pointer: std::function keeps it without allocating.)
    auto* run = &setupJob;
    pool_.parallelFor(jobs, [run](int job, int worker) { (*run)(job, worker); });
  } else {
    setupJob(0, 0);
  }

  if (direct) {
    size_t end = base;  // the records kept so far end here
    for (int i = 0; i < instances; ++i) {
      if (i >= booked) calls_this_submission_ = 0;  // (the rest of the bookkeeping: the scene is steady)
      const SetupOutput& out = batch_outputs_[static_cast<size_t>(i)];
      ++stats_.instances_submitted;
      stats_.setup_instructions += out.instructions;
      if (out.killed) {
        binInstance(prim, out, end);  // (counts it)
        continue;
      }
      const size_t at = base + words * static_cast<size_t>(i);
      if (at != end) std::memmove(scene_.records.data() + end, scene_.records.data() + at, words * sizeof(uint32_t));
      if (binInstance(prim, out, end)) end += words;
    }
    scene_.records.resize(end);
    return;
  }
  for (int i = 0; i < instances; ++i) {
    if (i >= booked && !bookkeeping(i)) return;
    const SetupOutput& out = batch_outputs_[static_cast<size_t>(i)];
    const uint32_t* record = records_at + words * static_cast<size_t>(i);
    ++stats_.instances_submitted;
    stats_.setup_instructions += out.instructions;
    if (!out.killed && prim.pixel.code.empty()) continue;
    const size_t offset = scene_.records.size();
    if (!out.killed) scene_.records.insert(scene_.records.end(), record, record + words);
    if (!binInstance(prim, out, offset) && !out.killed) scene_.records.resize(offset);
  }
}

SetupBatchCounters Renderer::setupBatchCounters() const {
  SetupBatchCounters sum;
  for (const auto& b : batch_setups_) {
    sum.batches += b->counters.batches;
    sum.lanes_batched += b->counters.lanes_batched;
    sum.lanes_resumed += b->counters.lanes_resumed;
    sum.lanes_scalar += b->counters.lanes_scalar;
    sum.batches_native += b->counters.batches_native;
    sum.lanes_native += b->counters.lanes_native;
  }
  return sum;
}

void Renderer::submitCall(const CompiledPrimitive& callee, const uint32_t* params, const float* vertex_channels,
                          int depth) {
  // Calls inside setup loops multiply: past the budget, the rest of the submission's calls are
  // dropped and reported like a runaway loop (never a hang, never memory without end).
  if (++calls_this_submission_ > calls_budget_ || scene_.records.size() > kMaxRecordWords) {
    ++stats_.iteration_cap_instances;
    ++cap_report_.instances;
    cap_report_.primitive = callee.name;
    return;
  }
  if (depth <= kMaxPrimitiveCallDepth) submitAt(callee, params, vertex_channels, callee.sequence_points, depth);
}

// Setup and binning of one instance, under the state, layout and shade last appended.
bool Renderer::submitAt(const CompiledPrimitive& prim, const uint32_t* params, const float* vertex_channels,
                        int sequence_points, int depth) {
  ++stats_.instances_submitted;
  const RasterState& state = scene_.states.back();
  const ChannelLayout& layout = scene_.layouts.back();
  size_t offset = scene_.records.size();
  const size_t words = SetupExecutor::recordWords(prim, layout.count);
  SetupInput in{params, vertex_channels, &layout, &state, sequence_points, this, depth};
  // Setup writes the record in place, unless it calls other primitives: their records would
  // land in the middle of it, so it goes to scratch first.
  const bool in_place = prim.callees.empty();
  std::vector<uint32_t>& scratch = record_scratch_[depth];
  if (in_place) scene_.records.resize(offset + words);
  else scratch.resize(words);
  SetupOutput out = setups_[depth].run(prim, in, in_place ? scene_.records.data() + offset : scratch.data());
  stats_.setup_instructions += out.instructions;
  if (out.killed || prim.pixel.code.empty()) {
    if (in_place) scene_.records.resize(offset);
  }
  // A primitive whose only work was to call others has nothing to run per pixel.
  if (!out.killed && prim.pixel.code.empty()) return true;
  if (!in_place && !out.killed) {
    offset = scene_.records.size();
    scene_.records.insert(scene_.records.end(), scratch.begin(), scratch.end());
  }
  const bool kept = binInstance(prim, out, offset);
  if (!kept && !out.killed) scene_.records.resize(offset);  // its record, the last, goes
  return kept;
}

// After setup: an instance it killed is counted; a live one, whose record is in the scene at
// `offset`, is binned under the state, layout and shade last appended. False: it is not (killed,
// or no pixel of it in the viewport), and its record is the caller's to drop.
bool Renderer::binInstance(const CompiledPrimitive& prim, const SetupOutput& out, size_t offset) {
  const RasterState& state = scene_.states.back();
  const ChannelLayout& layout = scene_.layouts.back();
  const ShadeState& shade = scene_.shades[scene_.current_shade];
  if (out.killed) {
    ++stats_.instances_killed;
    if (out.iteration_cap_hit) {
      ++stats_.iteration_cap_instances;
      ++cap_report_.instances;
      cap_report_.primitive = prim.name;
    }
    return false;
  }
  Instance inst;
  inst.prim = &prim;
  inst.record_offset = static_cast<uint32_t>(offset);
  inst.state = static_cast<uint16_t>(scene_.states.size() - 1);
  inst.layout = static_cast<uint16_t>(scene_.layouts.size() - 1);
  inst.shared_offset = shared_offset_;
  inst.shade_id = scene_.current_shade + 1 + (out.back_facing && shade.back_color_slot >= 0 ? 1u : 0u);
  // The pixels it may touch: its bound within the viewport and the framebuffer.
  int vx0 = std::max(state.vp_x0, 0), vy0 = std::max(state.vp_y0, 0);
  int vx1 = std::min(state.vp_x1, width_), vy1 = std::min(state.vp_y1, height_);
  if (state.fragment.scissor) {  // the scissor test: pixels outside the box are never run
    vx0 = std::max(vx0, state.fragment.scissor_x0), vy0 = std::max(vy0, state.fragment.scissor_y0);
    vx1 = std::min(vx1, state.fragment.scissor_x1), vy1 = std::min(vy1, state.fragment.scissor_y1);
  }
  if (vx0 >= vx1 || vy0 >= vy1) return false;
  inst.x0 = vx0, inst.x1 = vx1, inst.y0 = vy0, inst.y1 = vy1;
  if (out.has_bound) {
    pixelRange(out.bound[0], out.bound[2], vx0, vx1, inst.x0, inst.x1);
    pixelRange(out.bound[1], out.bound[3], vy0, vy1, inst.y0, inst.y1);
    if (!(out.bound[0] <= out.bound[2]) || !(out.bound[1] <= out.bound[3])) inst.x1 = inst.x0;  // empty or NaN
  }
  // Its depth bound: NaN is none; an empty one draws nothing.
  inst.has_depth_bound = false;
  inst.z_min = inst.z_max = 0;
  if (out.has_depth_bound && out.depth_bound[0] == out.depth_bound[0] && out.depth_bound[1] == out.depth_bound[1]) {
    if (out.depth_bound[0] > out.depth_bound[1]) inst.x1 = inst.x0;
    inst.has_depth_bound = true;
    inst.z_min = out.depth_bound[0];
    inst.z_max = out.depth_bound[1];
  }
  if (inst.x0 >= inst.x1 || inst.y0 >= inst.y1) return false;
  int max_slot = 0;
  for (int s : layout.gbuffer_slot) max_slot = std::max(max_slot, s + 1);
  if (shade.color_slot >= 0) max_slot = std::max(max_slot, shade.color_slot + 4);
  if (shade.back_color_slot >= 0) max_slot = std::max(max_slot, shade.back_color_slot + 4);
  if (layout.surface_slot >= 0) max_slot = std::max(max_slot, layout.surface_slot + 6);
  scene_.gbuffer_slots = std::max(scene_.gbuffer_slots, max_slot);

  uint32_t index = static_cast<uint32_t>(scene_.instances.size());
  scene_.instances.push_back(inst);
  for (int ty = inst.y0 / kTileSize; ty <= (inst.y1 - 1) / kTileSize; ++ty)
    for (int tx = inst.x0 / kTileSize; tx <= (inst.x1 - 1) / kTileSize; ++tx) {
      scene_.bins[static_cast<size_t>(ty) * scene_.tiles_x + tx].instances.push_back(index);
      ++stats_.bin_entries;
    }
  return true;
}

void Renderer::runTile(int tile, WorkerScratch& s) {
  const int tx = tile % scene_.tiles_x, ty = tile / scene_.tiles_x;
  const int x0 = tx * kTileSize, y0 = ty * kTileSize;
  const int w = std::min(kTileSize, width_ - x0), h = std::min(kTileSize, height_ - y0);
  if (scene_.clearing()) clearTile(x0, y0, w, h);

  const TileBin& bin = scene_.bins[tile];
  if (bin.instances.empty()) return;
  ++s.tiles_run;

  // The tile's G-buffer: one plane per slot this frame uses, plus the shading-state ids.
  constexpr size_t kPlane = static_cast<size_t>(kTileSize) * kTileSize;
  s.shade_ids.assign(kPlane, 0u);
  s.gbuffer.resize(kPlane * scene_.gbuffer_slots);
  s.slot_planes.resize(scene_.gbuffer_slots);
  for (int k = 0; k < scene_.gbuffer_slots; ++k) s.slot_planes[k] = s.gbuffer.data() + kPlane * k;

  // (Coarse depth may take the clear depth as known only where the clear covered the tile.)
  const PixelRect& cr = scene_.clear.rect;
  const bool depth_cleared =
      scene_.clear.depth && cr.x0 <= x0 && cr.y0 <= y0 && cr.x1 >= x0 + w && cr.y1 >= y0 + h;
  if (depth_) s.coarse_depth.startTile(depth_, width_, x0, y0, w, h, depth_cleared);
  s.gang.clear();

  BlockTarget target;
  target.depth = depth_;
  target.depth_stride = width_;
  target.shade_ids = s.shade_ids.data();
  target.slots = s.slot_planes.data();
  target.tile_x0 = x0;
  target.tile_y0 = y0;
  if (depth_) target.committed_pixels = s.coarse_depth.committedPixels();

  // The instances of a bin are a sparse, uneven walk through Scene::instances and records
  // (the hardware prefetcher does not follow it): each instance's record -- the uniform values
  // its pixel program reads first -- is fetched two instances ahead, its Instance four ahead.
  // Measured on 100k small spheres: without it, the program's first read of a uniform waited
  // on memory for ~7% of the frame.
  //
  // Ordered draws (fragment_ops.h; docs/architecture.md, "Ordered fragments"): before one
  // runs, the deferred pixels committed so far are shaded (they lie under it); once it has run
  // -- at the next instance, or after the bin -- its own pixels are shaded and written through
  // its fragment operations, the depth put back where the alpha test discarded a fragment.
  const RasterState* ordered = nullptr;  // the ordered draw that ran last, not yet written
  PixelRect ordered_bound;
  bool deferred_pending = false;         // deferred pixels committed and not shaded yet
  const size_t count = bin.instances.size();
  for (size_t k = 0; k < count; ++k) {
    if (ordered) {
      resolveTile(s, x0, y0, w, h, ordered, ordered_bound);
      ordered = nullptr;
    }
    if (k + 4 < count) __builtin_prefetch(&scene_.instances[bin.instances[k + 4]]);
    if (k + 2 < count) {
      const Instance& ahead = scene_.instances[bin.instances[k + 2]];
      // Every line the record's uniforms touch (a record starts anywhere in a line).
      const uint32_t* r = scene_.records.data() + ahead.record_offset;
      const size_t words = ahead.prim->pixel.num_uniform_slots;
      if (words > 0) {
        const uintptr_t first = reinterpret_cast<uintptr_t>(r) & ~uintptr_t{63};
        const uintptr_t last = reinterpret_cast<uintptr_t>(r + words - 1);
        for (uintptr_t line = first; line <= last; line += 64) __builtin_prefetch(reinterpret_cast<const void*>(line));
      }
    }
    const uint32_t index = bin.instances[k];
    const Instance& inst = scene_.instances[index];
    // The instance's pixels within this tile.
    int ix0 = std::max(inst.x0, x0), ix1 = std::min(inst.x1, x0 + w);
    int iy0 = std::max(inst.y0, y0), iy1 = std::min(inst.y1, y0 + h);
    const uint32_t* record = scene_.records.data() + inst.record_offset;
    const ChannelLayout& layout = scene_.layouts[inst.layout];
    const RasterState& inst_state = scene_.states[inst.state];
    const uint32_t* shared = inst.shared_offset == kNoShared ? nullptr : scene_.records.data() + inst.shared_offset;
    if (inst_state.fragment.ordered()) {
      if (!s.gang.empty()) s.gang.run(s.executor, scene_, target, depth_ ? &s.coarse_depth : nullptr, false);
      if (deferred_pending) resolveTile(s, x0, y0, w, h, nullptr, PixelRect{});
      deferred_pending = false;
      ordered = &inst_state;
      ordered_bound = PixelRect{ix0, iy0, ix1, iy1};
      // The depth its fragments may write, kept for those the alpha or stencil test will discard.
      s.depth_before.clear();
      const FragmentOps& f = inst_state.fragment;
      if ((f.alpha_test || (f.stencil.test && stencil_)) && depth_ && inst_state.depth_test && inst_state.depth_write)
        for (int y = iy0; y < iy1; ++y)
          s.depth_before.insert(s.depth_before.end(), depth_ + static_cast<size_t>(y) * width_ + ix0,
                                depth_ + static_cast<size_t>(y) * width_ + ix1);
    } else {
      deferred_pending = true;
    }
    // The instance's pixels within the tile under `state` (the draw's own, or a stencil draw's
    // coverage run's).
    auto runInstance = [&](const RasterState& state) {
      // Coarse depth culling: the tile's blocks (indices within the tile) the instance touches,
      // and whether its depth bound may skip some of them.
      const int cbx0 = (ix0 - x0) / kBlockSize, cbx1 = (ix1 - 1 - x0) / kBlockSize;
      const int cby0 = (iy0 - y0) / kBlockSize, cby1 = (iy1 - 1 - y0) / kBlockSize;
      const bool cull = depth_culling_ && depth_ && inst.has_depth_bound && state.depth_test;
      auto depthFails = [&](int cbx, int cby) {
        if (!s.coarse_depth.fails(state.depth_func, inst.z_min, inst.z_max, cbx, cby)) return false;
        ++s.blocks_depth_culled;
        return true;
      };
      // And per pixel (depthPassMask): the depth a pixel holds now is the one its lane will test
      // (whatever runs before it has run, or -- a gang block's other members -- has none of its
      // pixels), so a pixel where no depth of the bound can pass need not run. Bit i of the
      // result: pixel (x + i, y), for n <= 64 pixels.
      auto mayPass = [&](int x, int y, int n) {
        return depthPassMask(state.depth_func, inst.z_min, inst.z_max, depth_ + static_cast<size_t>(y) * width_ + x, n);
      };
      // Whether some pixel of an aligned block's lanes in `mask` may pass (its rows read only as
      // far as the framebuffer: a block at its right edge hangs past it).
      auto blockMayPass = [&](int bx, int by, uint64_t mask) {
        const int columns = std::min(kBlockSize, width_ - bx);
        for (int row = 0; row < kBlockSize; ++row) {
          const uint64_t lanes = (mask >> (row * kBlockSize)) & ((1u << kBlockSize) - 1u);
          if (lanes && (mayPass(bx, by + row, columns) & lanes)) return true;
        }
        return false;
      };
      // Small bounds run packed: alone (packsBetter), or -- for a program that gangs -- with the
      // pixels of the instances around it in the bin, up to kGangArea pixels each (a gang fills
      // its blocks whatever the bound's shape, so it takes bounds that on aligned blocks would
      // have whole blocks inside).
      const bool packs = pack_small_bounds_ && PixelExecutor::packs(*inst.prim, layout);
      const bool gangs = packs && gang_blocks_ && inst.prim->pixel.gangs && !ordered &&
                         (ix1 - ix0) * (iy1 - iy0) <= kGangArea;
      const GangBlock::Rect rect{ix0, iy0, ix1, iy1};
      // The block being filled runs first unless this instance joins it (the bin's order).
      if (!s.gang.empty() && !(gangs && s.gang.accepts(inst, record, rect)))
        s.gang.run(s.executor, scene_, target, depth_ ? &s.coarse_depth : nullptr, false);
      const uint64_t committed_before = s.executor.counters.lanes_committed;
      if (gangs || (packs && packsBetter(ix0, ix1, iy0, iy1, x0, y0))) {
        // A small bound: its pixels, row by row, fill whole blocks of packed lanes.
        // The blocks' columns it covers, less those coarse depth culling skips.
        uint64_t live = 0;  // bit (cby - cby0) * 8 + (cbx - cbx0)
        for (int cby = cby0; cby <= cby1; ++cby)
          for (int cbx = cbx0; cbx <= cbx1; ++cbx)
            if (!cull || !depthFails(cbx, cby)) live |= 1ull << ((cby - cby0) * CoarseDepth::kBlocksPerSide + cbx - cbx0);
        if (!live) return;
        // Row y's pixels to run, bit x - ix0: those in live blocks that may pass the depth test.
        // (A block column's pixels are a byte of the row, shifted to where the column starts.)
        const int width = ix1 - ix0;
        const uint64_t whole_row = width >= 64 ? ~0ull : (1ull << width) - 1;
        const uint64_t all_columns = (1ull << (cbx1 - cbx0 + 1)) - 1;
        const int column0 = x0 + cbx0 * kBlockSize - ix0;  // the first column's first pixel: <= 0
        auto rowPixels = [&](int y) {
          const uint64_t live_row =
              (live >> ((y - y0) / kBlockSize - cby0) * CoarseDepth::kBlocksPerSide) & all_columns;
          uint64_t row = whole_row;
          if (live_row != all_columns) {
            row = 0;
            for (uint64_t m = live_row; m; m &= m - 1) {
              const int first = column0 + __builtin_ctzll(m) * kBlockSize;
              row |= first >= 0 ? 0xffull << first : 0xffull >> -first;
            }
            row &= whole_row;
          }
          if (cull) {
            const uint64_t pass = mayPass(ix0, y, ix1 - ix0);
            // (Counted with laneCount, not a loop over the bits: overlapping small instances
            // cull most of their rows' pixels.)
            s.pixels_depth_culled += static_cast<uint64_t>(laneCount(row & ~pass));
            row &= pass;
          }
          return row;
        };
        if (gangs) {
          s.gang.join(inst, record, rect);
          for (int y = iy0; y < iy1; ++y)
            for (uint64_t m = rowPixels(y); m; m &= m - 1) {
              if (s.gang.full()) s.gang.run(s.executor, scene_, target, depth_ ? &s.coarse_depth : nullptr, true);
              s.gang.add(ix0 + __builtin_ctzll(m), y);
            }
          return;  // its depth writes mark the coarse depth when its block runs
        }
        PackedLanes& lanes = s.packed_lanes;
        int n = 0;
        for (int y = iy0; y < iy1; ++y)
          for (uint64_t m = rowPixels(y); m; m &= m - 1) {
            lanes.x[n] = ix0 + __builtin_ctzll(m);
            lanes.y[n] = y;
            if (++n == kLanes) {
              s.executor.runPackedBlock(*inst.prim, record, layout, state, inst.shade_id, lanes, ~0ull, target, shared);
              n = 0;
            }
          }
        if (n > 0)
          s.executor.runPackedBlock(*inst.prim, record, layout, state, inst.shade_id, lanes, (1ull << n) - 1, target,
                                    shared);
      } else {
        // Blocks are aligned to the tile; lanes outside the instance's pixels start retired. A
        // bound larger than a rejection region is walked a region at a time, and a region block
        // rejection rejects is skipped whole (its verdict holds for partly covered blocks too).
        const bool by_regions = iy1 - iy0 >= kRejectionRegion && ix1 - ix0 >= kRejectionRegion;
        const int step = by_regions ? kRejectionRegion : kTileSize;
        const int rx0 = (ix0 - x0) / step * step + x0, ry0 = (iy0 - y0) / step * step + y0;
        // The blocks to run, collected and run together (PixelExecutor::runBlocks).
        PixelExecutor::AlignedBlocks& aligned = s.aligned_blocks;
        aligned.count = 0;
        // A bound over 2x2 regions or more is first judged whole, in one walk: a large triangle
        // is rejected or accepted over most tiles it touches, where a walk per region would
        // cost four (the walk costs about what a block does). Undecided, its regions are judged
        // one by one.
        RegionVerdict whole = RegionVerdict::Unknown;
        if (by_regions && (ix1 - 1 - rx0) / kRejectionRegion >= 1 && (iy1 - 1 - ry0) / kRejectionRegion >= 1) {
          whole = s.executor.boundVerdict(*inst.prim, record, state, ix0, iy0, ix1, iy1);
          if (whole == RegionVerdict::Rejected) {
            s.executor.counters.blocks_rejected += static_cast<uint64_t>(cbx1 - cbx0 + 1) * (cby1 - cby0 + 1);
            return;
          }
        }
        for (int ry = ry0; ry < iy1; ry += step)
          for (int rx = rx0; rx < ix1; rx += step) {
            const int rbx0 = std::max(x0 + cbx0 * kBlockSize, rx), rby0 = std::max(y0 + cby0 * kBlockSize, ry);
            const int rbx1 = std::min(ix1, rx + step), rby1 = std::min(iy1, ry + step);
            if (by_regions && whole != RegionVerdict::Accepted) {
              const uint64_t blocks = static_cast<uint64_t>((rbx1 - rbx0 + kBlockSize - 1) / kBlockSize) *
                                      static_cast<uint64_t>((rby1 - rby0 + kBlockSize - 1) / kBlockSize);
              if (s.executor.rejectsRegion(*inst.prim, record, state, rx, ry, blocks)) continue;
            }
        for (int by = rby0; by < rby1; by += kBlockSize) {
          for (int bx = rbx0; bx < rbx1; bx += kBlockSize) {
            if (cull && depthFails((bx - x0) / kBlockSize, (by - y0) / kBlockSize)) continue;
            // The columns [ix0, ix1) of a row, then that row in every row of [iy0, iy1).
            const int c0 = std::max(ix0 - bx, 0), c1 = std::min(ix1 - bx, kBlockSize);
            const uint64_t row = ((1ull << c1) - 1) & ~((1ull << c0) - 1);
            uint64_t mask = 0;
            for (int ly = std::max(iy0 - by, 0); ly < std::min(iy1 - by, kBlockSize); ++ly)
              mask |= row << (ly * kBlockSize);
            // Skipped too where no pixel of it can pass (the block's other pixels, outside the
            // instance, may hold the clear depth that keeps the coarse test from saying so).
            if (cull && mask && !blockMayPass(bx, by, mask)) {
              ++s.blocks_depth_culled;
              continue;
            }
            if (mask) aligned.add(bx, by, mask);
          }
        }
          }
        s.executor.runBlocks(*inst.prim, record, layout, state, inst.shade_id, aligned, target, shared, whole);
      }
      // What it wrote to the depth buffer: those blocks' ranges are stale.
      if (depth_ && state.depth_test && state.depth_write && s.executor.counters.lanes_committed != committed_before)
        s.coarse_depth.written(ix0 - x0, iy0 - y0, ix1 - x0, iy1 - y0);
    };
    if (inst_state.fragment.stencil.test && stencil_) {
      // A stencil draw: its covered pixels first (no depth test), then the real run.
      RasterState cover = inst_state;
      cover.depth_test = false;
      cover.depth_write = false;
      runInstance(cover);
      coverStencil(s, x0, y0, w, h, inst_state, ordered_bound);
      runInstance(inst_state);
      applyStencil(s, x0, y0, inst_state, ordered_bound);
    } else {
      runInstance(inst_state);
    }
  }
  s.gang.run(s.executor, scene_, target, depth_ ? &s.coarse_depth : nullptr, false);
  if (ordered) resolveTile(s, x0, y0, w, h, ordered, ordered_bound);
  else if (deferred_pending) resolveTile(s, x0, y0, w, h, nullptr, PixelRect{});
}

void Renderer::flush() {
  ++flushes_;
  if (scene_.empty() || !color_) {
    scene_.reset();
    return;
  }
  const int tiles = scene_.tiles_x * scene_.tiles_y;
  for (auto& s : scratch_) s->executor.startFrame();
  try {
    pool_.parallelFor(tiles, [this](int tile, int worker) { runTile(tile, *scratch_[worker]); });
  } catch (...) {  // a failed allocation in a tile: the frame is dropped, the renderer stays usable
    discardPending();
    throw;
  }
  constexpr uint64_t kPlaneBytes = static_cast<uint64_t>(kTileSize) * kTileSize * 4;
  stats_.tiles_skipped += static_cast<uint64_t>(tiles);  // less the tiles run, below
  for (auto& s : scratch_) {
    stats_.blocks_run += s->executor.counters.blocks_run;
    stats_.blocks_rejected += s->executor.counters.blocks_rejected;
    stats_.lanes_started += s->executor.counters.lanes_started;
    stats_.lanes_committed += s->executor.counters.lanes_committed;
    stats_.blocks_covered += s->executor.counters.blocks_covered;
    stats_.blocks_accepted += s->executor.counters.blocks_accepted;
    stats_.blocks_walked += s->executor.counters.blocks_walked;
    stats_.region_walks += s->executor.counters.region_walks;
    stats_.blocks_packed += s->executor.counters.blocks_packed;
    stats_.blocks_native += s->executor.counters.blocks_native;
    stats_.blocks_ganged += s->executor.counters.blocks_ganged;
    stats_.blocks_depth_culled += s->blocks_depth_culled;
    stats_.pixels_depth_culled += s->pixels_depth_culled;
    stats_.pixel_instructions += s->executor.counters.instructions;
    stats_.pixels_shaded += s->pixels_shaded;
    stats_.tiles_run += s->tiles_run;
    stats_.iteration_cap_pixels += s->executor.counters.iteration_cap_lanes;
    stats_.field.add(s->executor.counters.field);
    stats_.unknown_field_lanes += s->executor.counters.unknown_field_lanes;
    if (s->executor.counters.iteration_cap_lanes) {
      cap_report_.pixels += s->executor.counters.iteration_cap_lanes;
      if (const CompiledPrimitive* who = s->executor.counters.cap_primitive) cap_report_.primitive = who->name;
    }
    stats_.gbuffer_bytes += s->tiles_run * (static_cast<uint64_t>(scene_.gbuffer_slots) + 1) * kPlaneBytes;
    stats_.tiles_skipped -= s->tiles_run;
    s->executor.counters = BlockCounters{};
    s->pixels_shaded = 0;
    s->tiles_run = 0;
    s->blocks_depth_culled = 0;
    s->pixels_depth_culled = 0;
  }
  scene_.reset();
}

void Renderer::setNativeCode(bool on) {
  native_code_ = on;
  for (auto& s : scratch_) s->executor.use_native = on;
  for (auto& b : batch_setups_) b->use_native = on;
}

void Renderer::discardPending() {
  for (auto& s : scratch_) {
    s->executor.counters = BlockCounters{};
    s->pixels_shaded = 0;
    s->tiles_run = 0;
    s->blocks_depth_culled = 0;
    s->pixels_depth_culled = 0;
  }
  scene_.reset();
}

}  // namespace pf
