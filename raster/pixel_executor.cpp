// The SIMD pixel executor (see pixel_executor.h): which program runs each block and how --
// block rejection's verdicts (by region, or over an instance's bound), the covered variant,
// native code (raster/native_blocks.h) or the interpreter (pixel_interpreter.cpp) -- and the
// bookkeeping of what a block committed. Packed and gang blocks are dispatched here too.
#include "raster/pixel_executor.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "compiler/native/native_cache.h"
#include "compiler/record_reads.h"
#include "compiler/scalar_ops.h"
#include "raster/lane_count.h"
#include "raster/setup_executor.h"

namespace pf {

// Block rejection by regions of kRejectionRegion x kRejectionRegion pixels: one interval
// evaluation answers for all the blocks of a region an instance touches. The verdicts of the
// tile's regions are remembered (one slot each) with the program and uniform values they were
// made for -- compared by content, since a later frame may put other values at the same
// address. (The state is not part of it: the evaluated prefix stops at the first loop, and
// pixel programs read the state only inside loops.)
PixelExecutor::RegionMemo& PixelExecutor::regionMemo(const PixelProgram& program, const uint32_t* record,
                                                     const RasterState& state, int bx, int by) {
  const int rx = bx / kRejectionRegion * kRejectionRegion, ry = by / kRejectionRegion * kRejectionRegion;
  constexpr int kPerRow = kTileSize / kRejectionRegion;
  RegionMemo& v = region_memos_[(rx / kRejectionRegion) % kPerRow + (ry / kRejectionRegion) % kPerRow * kPerRow];
  const size_t words = program.num_uniform_slots;
  // The same record (by address: records do not change while a frame runs, and startFrame
  // forgets the memos), else the same values.
  if (v.program == &program && v.x == rx && v.y == ry && v.record_address == record) return v;
  if (v.program != &program || v.x != rx || v.y != ry || v.record.size() != words ||
      !std::equal(v.record.begin(), v.record.end(), record)) {
    // The verdict before the key: if evaluating fails (std::bad_alloc), no key names a stale one.
    v.program = nullptr;
    // Native code walks the tile's regions at once, where it can (the instance's blocks in the
    // tile ask for each region in turn).
    if (use_native && walkTileRegions(program, record, state, rx, ry)) return v;
    // Native code's walk where there is some (the same verdict), else the interpreter's.
    const double region[4] = {rx + 0.5, rx + kRejectionRegion - 0.5, ry + 0.5, ry + kRejectionRegion - 0.5};
    uint32_t native = 0;
    const RegionVerdict verdict =
        use_native && native_.verdict(program, record, state, region, native)
            ? static_cast<RegionVerdict>(native)
            : rejection_.verdict(program, record, state, rx, ry, rx + kRejectionRegion, ry + kRejectionRegion);
    v.remember(program, record, words, rx, ry, verdict);
  }
  v.record_address = record;
  return v;
}

bool PixelExecutor::walkTileRegions(const PixelProgram& program, const uint32_t* record, const RasterState& state,
                                    int rx, int ry) {
  constexpr int kPerRow = kTileSize / kRejectionRegion;
  static_assert(kPerRow * kPerRow == kNativeRegionLanes, "a tile's regions are one walk's lanes");
  const int tx = rx / kTileSize * kTileSize, ty = ry / kTileSize * kTileSize;
  // The pixel centres of each region: x_lo, x_hi, y_lo, y_hi, each for every region.
  double bounds[4][kNativeRegionLanes];
  for (int i = 0; i < kNativeRegionLanes; ++i) {
    const int x = tx + i % kPerRow * kRejectionRegion, y = ty + i / kPerRow * kRejectionRegion;
    bounds[0][i] = x + 0.5;
    bounds[1][i] = x + kRejectionRegion - 0.5;
    bounds[2][i] = y + 0.5;
    bounds[3][i] = y + kRejectionRegion - 0.5;
  }
  uint8_t verdicts[kNativeRegionLanes];
  if (!native_.verdicts(program, record, state, kNativeRegionLanes, &bounds[0][0], verdicts)) return false;
  const size_t words = program.num_uniform_slots;
  for (int i = 0; i < kNativeRegionLanes; ++i) {
    RegionMemo& m = region_memos_[i];  // (region i of a tile has memo i: tiles hold kPerRow regions a row)
    m.remember(program, record, words, tx + i % kPerRow * kRejectionRegion, ty + i / kPerRow * kRejectionRegion,
               verdicts[i] <= static_cast<uint8_t>(RegionVerdict::Accepted) ? static_cast<RegionVerdict>(verdicts[i])
                                                                           : RegionVerdict::Unknown);
    m.record_address = record;
  }
  return true;
}

RegionVerdict PixelExecutor::blockVerdict(const PixelProgram& program, const uint32_t* record, const RasterState& state,
                                          int bx, int by) {
  RegionMemo& v = regionMemo(program, record, state, bx, by);
  if (v.verdict != RegionVerdict::Unknown || !use_native) return v.verdict;
  static_assert(kBlocksPerRegion == kNativeVerdictLanes, "a region's blocks are one walk's lanes");
  constexpr int kPerRow = kRejectionRegion / kBlockSize;
  if (!v.blocks_known) {
    // The pixel centres of each block: x_lo, x_hi, y_lo, y_hi, each for every block.
    double bounds[4][kBlocksPerRegion];
    for (int i = 0; i < kBlocksPerRegion; ++i) {
      const int x = v.x + i % kPerRow * kBlockSize, y = v.y + i / kPerRow * kBlockSize;
      bounds[0][i] = x + 0.5;
      bounds[1][i] = x + kBlockSize - 0.5;
      bounds[2][i] = y + 0.5;
      bounds[3][i] = y + kBlockSize - 0.5;
    }
    BlockWalkTally& tally = blockWalkTally(program);
    if (tally.walks >= kProbeWalks && 2 * tally.decided < tally.walks * kBlocksPerRegion) return RegionVerdict::Unknown;
    if (!native_.verdicts(program, record, state, kNativeVerdictLanes, &bounds[0][0], v.blocks))
      return RegionVerdict::Unknown;
    ++tally.walks;
    ++counters.region_walks;
    for (uint8_t b : v.blocks)
      tally.decided += b == static_cast<uint8_t>(RegionVerdict::Rejected) || b == static_cast<uint8_t>(RegionVerdict::Accepted);
    v.blocks_known = true;
  }
  const uint8_t b = v.blocks[(by - v.y) / kBlockSize * kPerRow + (bx - v.x) / kBlockSize];
  if (b != static_cast<uint8_t>(RegionVerdict::Rejected) && b != static_cast<uint8_t>(RegionVerdict::Accepted))
    return RegionVerdict::Unknown;
  ++counters.blocks_walked;
  return static_cast<RegionVerdict>(b);
}

PixelExecutor::BlockWalkTally& PixelExecutor::blockWalkTally(const PixelProgram& program) {
  for (size_t i = 0; i < block_walk_tallies_live_; ++i) {
    BlockWalkTally& t = block_walk_tallies_[i];
    if (t.program == &program && t.code == program.code.data()) return t;
  }
  if (block_walk_tallies_live_ == block_walk_tallies_.size()) block_walk_tallies_.emplace_back();
  BlockWalkTally& t = block_walk_tallies_[block_walk_tallies_live_++];
  t = BlockWalkTally{&program, program.code.data(), 0, 0};
  return t;
}

void PixelExecutor::startFrame() {
  block_walk_tallies_live_ = 0;
  for (RegionMemo& m : region_memos_) m.program = nullptr;  // a program may be freed, its address reused
  decoded_live_ = 0;
  decoded_last_[0] = decoded_last_[1] = 0;
  native_.startFrame();
  gang_runs_live_ = 0;
  if (shared_) shared_->startFrame();  // the shared interpolators' programs, decoded by it
}

const DecodedProgram& PixelExecutor::decoded(const PixelProgram& program, const LaneIsaTables& isa,
                                             bool wide_uniforms) {
  // (A program runs both ways in a frame of gangs: each way remembers its own last.)
  size_t& last = decoded_last_[wide_uniforms ? 1 : 0];
  if (last < decoded_live_ && decoded_[last].decodes(program, isa, wide_uniforms)) return decoded_[last];
  for (size_t i = 0; i < decoded_live_; ++i)
    if (decoded_[i].decodes(program, isa, wide_uniforms)) {
      last = i;
      return decoded_[i];
    }
  if (decoded_live_ == decoded_.size()) decoded_.emplace_back();
  decodeProgram(program, isa, decoded_[decoded_live_], wide_uniforms);
  last = decoded_live_++;
  return decoded_[last];
}

bool PixelExecutor::blockRejectionWanted() { return std::getenv("PF_NO_BLOCK_REJECTION") == nullptr; }

bool PixelExecutor::nativeWanted() { return nativeCodeWantedByEnvironment(); }

bool PixelExecutor::rejectsRegion(const CompiledPrimitive& prim, const uint32_t* record, const RasterState& state, int x,
                                  int y, uint64_t blocks) {
  if (prim.pixel.last_early_retire < 0 || !use_block_rejection) return false;
  if (regionVerdict(prim.pixel, record, state, x, y) != RegionVerdict::Rejected) return false;
  counters.blocks_rejected += blocks;
  return true;
}

RegionVerdict PixelExecutor::boundVerdict(const CompiledPrimitive& prim, const uint32_t* record,
                                          const RasterState& state, int x0, int y0, int x1, int y1) {
  const PixelProgram& program = prim.pixel;
  if (program.last_early_retire < 0 || !use_block_rejection) return RegionVerdict::Unknown;
  const double region[4] = {x0 + 0.5, x1 - 0.5, y0 + 0.5, y1 - 0.5};
  uint32_t native = 0;
  return use_native && native_.verdict(program, record, state, region, native)
             ? static_cast<RegionVerdict>(native)
             : rejection_.verdict(program, record, state, x0, y0, x1, y1);
}

const PixelProgram* PixelExecutor::blockProgram(const CompiledPrimitive& prim, const uint32_t* record,
                                                const RasterState& state, int bx, int by, uint64_t mask,
                                                RegionVerdict known) {
  // Only blocks that start full are tested: an instance whose bound cuts every block it touches
  // (a small triangle) would pay for the test and rarely gain (measured: docs/performance.md).
  // A region certainly retired is skipped; one where no coverage test can fail runs the program
  // without them.
  if (known == RegionVerdict::Accepted && prim.pixel.covered) {
    ++counters.blocks_accepted;
    return prim.pixel.covered.get();
  }
  if (mask == ~0ull && prim.pixel.last_early_retire >= 0 && use_block_rejection) {
    const RegionVerdict v = blockVerdict(prim.pixel, record, state, bx, by);
    if (v == RegionVerdict::Rejected) {
      ++counters.blocks_rejected;
      return nullptr;
    }
    if (v == RegionVerdict::Accepted && prim.pixel.covered) {
      ++counters.blocks_accepted;
      return prim.pixel.covered.get();
    }
  }
  return &prim.pixel;
}

void PixelExecutor::runBlock(const CompiledPrimitive& prim, const uint32_t* record,
                             const ChannelLayout& layout, const RasterState& state,
                             uint32_t shade_id, int bx, int by, uint64_t mask,
                             const BlockTarget& target, const uint32_t* shared_records) {
  if (const PixelProgram* program = blockProgram(prim, record, state, bx, by, mask, RegionVerdict::Unknown))
    runAndCommit(prim, *program, record, layout, state, shade_id, bx, by, nullptr, mask, target, shared_records);
}

void PixelExecutor::runBlocks(const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout,
                              const RasterState& state, uint32_t shade_id, const AlignedBlocks& blocks,
                              const BlockTarget& target, const uint32_t* shared_records, RegionVerdict known) {
  // As runBlock each, but native code's function (one per program: prim.pixel and its covered
  // variant) is looked up, and its arguments set up, once for the run rather than per block.
  NativeBlockFunction fns[2];
  bool prepared = false;
  for (int i = 0; i < blocks.count; ++i) {
    const int bx = blocks.bx[i], by = blocks.by[i];
    const uint64_t mask = blocks.mask[i];
    const PixelProgram* program = blockProgram(prim, record, state, bx, by, mask, known);
    if (!program) continue;
    const int which = program == &prim.pixel ? 0 : 1;
    // (Looked up again while null: each block counts towards the compile threshold.)
    if (use_native && !fns[which]) fns[which] = native_.find(prim, *program, layout, false);
    if (!fns[which]) {
      runAndCommit(prim, *program, record, layout, state, shade_id, bx, by, nullptr, mask, target, shared_records);
      continue;
    }
    if (!prepared) {
      native_.prepare(native_call_, prim, record, layout, state, shade_id, nullptr, target, shared_records);
      prepared = true;
    }
    ++counters.blocks_run;
    counters.lanes_started += static_cast<uint64_t>(laneCount(mask));
    const uint64_t alive = native_.call(fns[which], native_call_, bx, by, mask, counters.iteration_cap_lanes,
                                        counters.cap_primitive);
    noteCommitted(nullptr, bx, by, alive, target);
    ++counters.blocks_native;
  }
}

void PixelExecutor::noteCommitted(const PackedLanes* packed, int bx, int by, uint64_t alive, const BlockTarget& target) {
  counters.lanes_committed += static_cast<uint64_t>(laneCount(alive));
  if (target.committed_pixels && alive) {
    constexpr int kBlocksPerRow = kTileSize / kBlockSize;
    if (packed) {
      // (Unsigned: a lane's pixel lies in the tile, and the divisions by 8 become shifts.)
      for (uint64_t m = alive; m; m &= m - 1) {
        const int i = __builtin_ctzll(m);
        const unsigned x = static_cast<unsigned>(packed->x[i] - target.tile_x0);
        const unsigned y = static_cast<unsigned>(packed->y[i] - target.tile_y0);
        target.committed_pixels[(y / kBlockSize) * kBlocksPerRow + x / kBlockSize] |=
            1ull << ((y % kBlockSize) * kBlockSize + x % kBlockSize);
      }
    } else {
      target.committed_pixels[((by - target.tile_y0) / kBlockSize) * kBlocksPerRow + (bx - target.tile_x0) / kBlockSize] |=
          alive;
    }
  }
  if (alive == ~0ull) ++counters.blocks_covered;
}

void PixelExecutor::runPackedBlock(const CompiledPrimitive& prim, const uint32_t* record,
                                   const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
                                   const PackedLanes& lanes, uint64_t mask, const BlockTarget& target,
                                   const uint32_t* shared_records) {
  // A program casting an aligned block's rays cannot run here (the renderer asks packs() first).
  if (!packs(prim, layout)) throw std::logic_error("runPackedBlock: " + prim.name + " casts block rays");
  ++counters.blocks_packed;
  runAndCommit(prim, prim.pixel, record, layout, state, shade_id, 0, 0, &lanes, mask, target, shared_records);
}

void PixelExecutor::runGangBlock(const CompiledPrimitive& prim, const GangMember* members, int member_count,
                                 const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
                                 const PackedLanes& lanes, uint64_t mask, const BlockTarget& target,
                                 const uint32_t* shared_records) {
  if (!prim.pixel.gangs || !packs(prim, layout)) throw std::logic_error("runGangBlock: " + prim.name + " does not gang");
  if (member_count == 1) {  // one instance: its record as it is
    runPackedBlock(prim, members[0].record, layout, state, shade_id, lanes, mask, target, shared_records);
    return;
  }
  // Each record word the program reads on the members' paths spread over its instance's lanes
  // (the last member's to the block's end: lanes outside `mask` compute too, on some instance's
  // values). The members agree on the slots the program branches on, so the words their
  // branches read are known before the block runs (compiler/record_reads.h).
  const size_t words = SetupExecutor::recordWords(prim, layout.count);
  if (gang_record_.size() < words * kLanes) gang_record_.resize(words * kLanes);
  const std::vector<RecordWordRun>& runs = gangWordRuns(prim.pixel, layout.count, members[0].record);
  const uint32_t* records[kLanes];
  int first[kLanes];
  for (int m = 0; m < member_count; ++m) first[m] = members[m].first_lane;
  const LaneMaskOps& masks = laneIsaTables().masks;
  for (const RecordWordRun& run : runs) {
    for (int m = 0; m < member_count; ++m) records[m] = members[m].record + run.first;
    masks.spread(gang_record_.data() + static_cast<size_t>(run.first) * kLanes, records, first, member_count, run.count);
  }
  ++counters.blocks_packed;
  ++counters.blocks_ganged;
  runAndCommit(prim, prim.pixel, gang_record_.data(), layout, state, shade_id, 0, 0, &lanes, mask, target,
               shared_records, true);
}

const std::vector<RecordWordRun>& PixelExecutor::gangWordRuns(const PixelProgram& program, int channels,
                                                              const uint32_t* record) {
  for (size_t i = 0; i < gang_runs_live_; ++i) {
    GangWordRuns& g = gang_runs_[i];
    if (g.program != &program || g.code != program.code.data() || g.channels != channels) continue;
    bool same = true;
    for (size_t k = 0; k < program.branch_slots.size() && same; ++k)
      same = g.branch_values[k] == record[program.branch_slots[k]];
    if (same) return g.runs;
  }
  if (gang_runs_live_ == gang_runs_.size()) gang_runs_.emplace_back();
  GangWordRuns& g = gang_runs_[gang_runs_live_++];
  g.program = &program;
  g.code = program.code.data();
  g.channels = channels;
  g.branch_values.clear();
  for (uint32_t slot : program.branch_slots) g.branch_values.push_back(record[slot]);
  recordWordsRead(program, channels, record, g.runs, record_reads_scratch_);
  return g.runs;
}

bool PixelExecutor::packs(const CompiledPrimitive& prim, const ChannelLayout& layout) {
  if (prim.pixel.casts_block_rays) return false;
  for (const ChannelLayout::SharedInterpolator& s : layout.shared)
    if (s.program->pixel.casts_block_rays) return false;
  return true;
}

void PixelExecutor::runAndCommit(const CompiledPrimitive& prim, const PixelProgram& program, const uint32_t* record,
                                 const ChannelLayout& layout, const RasterState& state, uint32_t shade_id, int bx,
                                 int by, const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
                                 const uint32_t* shared_records, bool wide_record) {
  const int nch = layout.count;
  ++counters.blocks_run;
  counters.lanes_started += static_cast<uint64_t>(laneCount(mask));
  // Native code, where there is some for the program: the block whole, commit included.
  NativeBlockFunction native;
  if (use_native)
    native = native_.find(prim, program, layout, wide_record);
  const uint64_t alive = native ? native_.run(native, prim, record, layout, state, shade_id, bx, by, packed, mask, target,
                                              shared_records, counters.iteration_cap_lanes, counters.cap_primitive)
                                : execute(prim, program, record, layout, state, bx, by, packed, mask, target,
                                          shared_records, nullptr, wide_record);

  // Commit: the lanes still alive are this instance's pixels.
  noteCommitted(packed, bx, by, alive, target);
  if (native) {
    ++counters.blocks_native;
    return;
  }
  // Per-pixel lighting's surface: P (divided by w) and N. (An instance that does not set N --
  // a callee of one that does -- has no surface: 0.)
  // (P only where the lighting reads it: ChannelLayout::surface_eye.)
  const bool commit_surface = layout.surface_slot >= 0 && !layout.surface_interpolated;
  auto commitSurface = [&](int i, size_t t) {
    const bool has = prim.writes_normal;
    if (layout.surface_eye) {
      const float w = has ? asF(surface_[3 * kLanes + i]) : 1.0f;
      for (int k = 0; k < 3; ++k)
        target.slots[layout.surface_slot + k][t] = has ? asF(surface_[static_cast<size_t>(k) * kLanes + i]) / w : 0.0f;
    }
    for (int k = 0; k < 3; ++k)
      target.slots[layout.surface_slot + 3 + k][t] = has ? asF(surface_[static_cast<size_t>(4 + k) * kLanes + i]) : 0.0f;
  };
  // The channels' G-buffer planes, looked up once (a layout has at most kMaxChannels channels:
  // the API refuses more, and so does Renderer::beginSubmission).
  float* planes[kMaxChannels];
  const int hoisted = std::min(nch, kMaxChannels);
  for (int ch = 0; ch < hoisted; ++ch) planes[ch] = target.slots[layout.gbuffer_slot[ch]];
  // Lane i to the tile's G-buffer entry t.
  auto commitLane = [&](int i, size_t t) {
    target.shade_ids[t] = shade_id;
    for (int ch = 0; ch < hoisted; ++ch) planes[ch][t] = asF(staging_[static_cast<size_t>(ch) * kLanes + i]);
    if (commit_surface) commitSurface(i, t);
  };
  if (packed) {  // lane by lane, each to its own pixel
    for (uint64_t m = alive; m; m &= m - 1) {
      const int i = __builtin_ctzll(m);
      commitLane(i, static_cast<size_t>(packed->y[i] - target.tile_y0) * kTileSize +
                        static_cast<size_t>(packed->x[i] - target.tile_x0));
    }
    return;
  }
  // Row by row: a whole row's channels are copied at once.
  for (int row = 0; row < kBlockSize; ++row) {
    const unsigned row_mask = static_cast<unsigned>(alive >> (row * kBlockSize)) & ((1u << kBlockSize) - 1u);
    if (row_mask == 0) continue;
    const int i0 = row * kBlockSize;
    const size_t t0 = static_cast<size_t>(by + row - target.tile_y0) * kTileSize + static_cast<size_t>(bx - target.tile_x0);
    if (row_mask == (1u << kBlockSize) - 1u) {
      std::fill_n(target.shade_ids + t0, kBlockSize, shade_id);
      for (int ch = 0; ch < hoisted; ++ch)
        std::memcpy(planes[ch] + t0, staging_.data() + static_cast<size_t>(ch) * kLanes + i0, sizeof(float) * kBlockSize);
      if (commit_surface)
        for (int lx = 0; lx < kBlockSize; ++lx) commitSurface(i0 + lx, t0 + static_cast<size_t>(lx));
      continue;
    }
    for (int lx = 0; lx < kBlockSize; ++lx)
      if ((row_mask >> lx) & 1u) commitLane(i0 + lx, t0 + static_cast<size_t>(lx));
  }
}

}  // namespace pf
