// Runs a primitive's pixel program over one pixel block (kBlockSize x kBlockSize lanes): wide
// registers hold one value per lane, an execution mask says which lanes run each instruction.
// `return` retires lanes; a block whose lanes have all retired stops. At the end, the lanes
// still alive commit: their shading channels go to the tile's G-buffer with the instance's
// shading state (deferred shading), and ZCommit has already written their depth.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "compiler/compiler.h"
#include "compiler/record_reads.h"
#include "raster/block_rejection.h"
#include "raster/decoded_program.h"
#include "raster/field/float_evaluator.h"
#include "raster/field/gradient_evaluator.h"
#include "raster/field/ray_caster.h"
#include "raster/limits.h"
#include "raster/native_blocks.h"
#include "raster/raster_state.h"

namespace pf {

// Where a block's results go.
struct BlockTarget {
  float* depth = nullptr;    // depth buffer (whole framebuffer), may be null
  int depth_stride = 0;      // floats per row
  uint32_t* shade_ids = nullptr;  // tile G-buffer: shading state per pixel (0 = not drawn)
  float* const* slots = nullptr;  // tile G-buffer: one kTileSize^2 plane per channel slot
  int tile_x0 = 0, tile_y0 = 0;   // window coordinates of the tile's first pixel
  // Per 8x8 block of the tile (row-major), a bit per pixel (row-major in the block) set as
  // lanes commit there (CoarseDepth: which blocks still hold cleared pixels); may be null.
  uint64_t* committed_pixels = nullptr;
};

// The pixels of a packed block: lane i is pixel (x[i], y[i]) -- any pixels of one tile, each
// at most once. A small instance's bound cuts the aligned blocks it touches (a sphere 10 pixels
// across touches 4-9 of them, most lanes outside it); packed, its pixels fill whole blocks
// (Renderer::runTile decides). Every lane computes the same bits wherever it sits.
struct PackedLanes {
  int32_t x[kLanes];
  int32_t y[kLanes];
};

// One instance of a gang block: its uniform record, and the first of its lanes (its lanes run
// to the next member's first, the last member's to the block's end).
struct GangMember {
  const uint32_t* record;
  int first_lane;
};

struct BlockCounters {
  uint64_t blocks_run = 0;
  uint64_t blocks_rejected = 0;  // skipped whole by block_rejection.h (not in blocks_run)
  uint64_t blocks_accepted = 0;  // run by the covered program, without coverage tests (in blocks_run)
  // rejected or accepted by their own verdict where their region's was undecided (native
  // code's walk over a region's blocks; in blocks_rejected or blocks_accepted)
  uint64_t blocks_walked = 0;
  uint64_t region_walks = 0;     // native code's walks over an undecided region's blocks
  uint64_t blocks_packed = 0;    // run on packed lanes (in blocks_run)
  uint64_t blocks_ganged = 0;    // packed blocks holding lanes of several instances (in blocks_packed)
  uint64_t lanes_started = 0;
  uint64_t lanes_committed = 0;
  uint64_t blocks_covered = 0;  // blocks whose every lane committed (the instance covers them whole)
  uint64_t blocks_native = 0;  // run by native code (compiler/native/; in blocks_run)
  uint64_t instructions = 0;  // executed by the interpreter, once per block (each covers every lane)
  uint64_t iteration_cap_lanes = 0;  // lanes stopped by the iteration cap
  const CompiledPrimitive* cap_primitive = nullptr;  // the last primitive that hit it
  field::FieldCounters field;          // implicit surfaces: work of field_hit()
  uint64_t unknown_field_lanes = 0;    // field_hit() / field_gradient() lanes naming no field
};

// The context's field with id `id` (1-based, a whole number), or null.
const field::ImplicitField* fieldById(const RasterState& state, float id);
// What FieldHit casts: field `f`'s surface along the state's pixel rays inside the staged box
// (min xyz, max xyz), by the method its operand names (anything else: auto) and its parameter.
field::CastRequest fieldCastRequest(const RasterState& state, const field::ImplicitField* f, const float box[6],
                                    float method, float param);
// Component `axis` of the gradient of the evaluator's field at q: derived, or by central
// differences (FieldGradient's imm & 4).
float fieldGradientAt(field::GradientEvaluator& ge, const float q[3], int axis, bool by_differences);

class PixelExecutor {
 public:
  // Runs the block whose lower-left pixel is (bx, by) for the lanes set in `mask` (bit i is
  // lane i = (bx + i % 8, by + i / 8)). `shared_records`: the uniform records of the layout's
  // shared interpolators (ChannelLayout::shared), if it has any.
  void runBlock(const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout,
                const RasterState& state, uint32_t shade_id, int bx, int by, uint64_t mask,
                const BlockTarget& target, const uint32_t* shared_records = nullptr);
  // Aligned blocks of one instance within a tile, in the order they run (at most the tile's).
  struct AlignedBlocks {
    static constexpr int kBlocksPerTile = (kTileSize / kBlockSize) * (kTileSize / kBlockSize);
    int count = 0;
    int bx[kBlocksPerTile], by[kBlocksPerTile];
    uint64_t mask[kBlocksPerTile];
    void add(int x, int y, uint64_t m) {
      bx[count] = x;
      by[count] = y;
      mask[count++] = m;
    }
  };
  // runBlock for each of `blocks` (the same pixels, counters and images), set up once.
  // `known`: a verdict already made for a rectangle holding all their lanes (boundVerdict):
  // Accepted runs the covered program whatever the mask, with no region verdict looked up.
  void runBlocks(const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout,
                 const RasterState& state, uint32_t shade_id, const AlignedBlocks& blocks, const BlockTarget& target,
                 const uint32_t* shared_records = nullptr, RegionVerdict known = RegionVerdict::Unknown);
  // Runs the pixels `lanes` names, for the lanes set in `mask`, as runBlock runs an aligned
  // block (without block rejection, which answers for aligned regions). Only for a primitive,
  // and shared interpolators, that packs (packs()).
  void runPackedBlock(const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout,
                      const RasterState& state, uint32_t shade_id, const PackedLanes& lanes, uint64_t mask,
                      const BlockTarget& target, const uint32_t* shared_records = nullptr);
  // Runs a packed block whose lanes belong to several instances of `prim` under one state,
  // layout, shade and shared interpolators, which do not share a pixel: `members` (in lane
  // order, the first at lane 0) say whose each lane is. Each lane reads its own instance's
  // uniforms (the program decoded with wide uniforms), so it computes the same bits as on a
  // block of its instance alone. Only for a primitive whose pixel program gangs
  // (PixelProgram::gangs) and whose members agree on its branch_slots.
  void runGangBlock(const CompiledPrimitive& prim, const GangMember* members, int member_count,
                    const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
                    const PackedLanes& lanes, uint64_t mask, const BlockTarget& target,
                    const uint32_t* shared_records = nullptr);
  // Whether block rejection proves that `prim` draws no pixel of the kRejectionRegion square
  // region holding (x, y) (block_rejection.h; the verdict is remembered for the region's
  // blocks): the renderer then skips the region's blocks at once. Counts them as rejected.
  bool rejectsRegion(const CompiledPrimitive& prim, const uint32_t* record, const RasterState& state, int x, int y,
                     uint64_t blocks);
  // Block rejection's verdict for the pixels [x0, x1) x [y0, y1) -- an instance's bound within
  // a tile -- in one walk, not remembered (an instance meets a tile once); Unknown where block
  // rejection does not apply. A decisive verdict answers for every region of the rectangle.
  RegionVerdict boundVerdict(const CompiledPrimitive& prim, const uint32_t* record, const RasterState& state, int x0,
                             int y0, int x1, int y1);
  // Whether `prim` drawn with `layout` may run on packed lanes: none of its programs casts the
  // rays of an aligned block (FieldHit).
  static bool packs(const CompiledPrimitive& prim, const ChannelLayout& layout);

  BlockCounters counters;
  // Forgets the region verdicts remembered from earlier frames (keyed by program address: a
  // program replaced since may have been freed and another made at its address).
  void startFrame();
  // Skip blocks the program certainly retires whole (block_rejection.h); off only to measure
  // what it saves and to check that images do not change.
  // PF_NO_BLOCK_REJECTION in the environment turns it off for the executors made afterwards.
  bool use_block_rejection = blockRejectionWanted();
  static bool blockRejectionWanted();
  // How many walks over an undecided region's blocks a program makes in a frame (on one
  // thread) before its tally decides whether more pay (BlockWalkTally, below).
  static constexpr uint32_t kProbeWalks = 32;
  // Run pixel programs as native code where it can (raster/native_blocks.h), else the
  // interpreter; on unless the environment says PF_JIT=0. Images are identical either way.
  bool use_native = nativeWanted();
  static bool nativeWanted();

 private:
  // Runs a program over the block; returns the lanes alive at its end. `p_in`: P's 4 components
  // (kLanes each) for a shared interpolator, null for a primitive (P starts at (0, 0, 0, 1)).
  // `program` is prim.pixel, or its covered variant (block_rejection.h). `packed`: the lanes'
  // pixels, or null for the aligned block at (bx, by). `wide_record`: `record` holds kLanes
  // values per slot, one per lane (a gang block's), instead of one.
  uint64_t execute(const CompiledPrimitive& prim, const PixelProgram& program, const uint32_t* record,
                   const ChannelLayout& layout, const RasterState& state, int bx, int by, const PackedLanes* packed,
                   uint64_t mask, const BlockTarget& target, const uint32_t* shared_records, const uint32_t* p_in,
                   bool wide_record = false);
  // The program runBlock runs for the block: prim.pixel, its covered variant, or null where
  // block rejection rejects it (counted).
  const PixelProgram* blockProgram(const CompiledPrimitive& prim, const uint32_t* record, const RasterState& state,
                                   int bx, int by, uint64_t mask, RegionVerdict known);
  // The counters and the coarse depth's committed pixels for the lanes `alive` of a block.
  void noteCommitted(const PackedLanes* packed, int bx, int by, uint64_t alive, const BlockTarget& target);
  // Runs `program` over the lanes and commits the lanes still alive to the target.
  void runAndCommit(const CompiledPrimitive& prim, const PixelProgram& program, const uint32_t* record,
                    const ChannelLayout& layout, const RasterState& state, uint32_t shade_id, int bx, int by,
                    const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
                    const uint32_t* shared_records, bool wide_record = false);
  // Runs the layout's shared interpolators for the `exec` lanes at surface point P (4 operands)
  // into their staging channels -- all but those `prim` computes itself (its `name:` labels).
  void runSharedInterpolators(const CompiledPrimitive& prim, const ChannelLayout& layout, const RasterState& state,
                              int bx, int by, const PackedLanes* packed, uint64_t exec, const uint32_t* const p[4], const bool p_wide[4],
                              const uint32_t* shared_records);

  // field_hit(): the box FieldBox staged, then the search over the block's `exec` lanes into t
  // (raster/field_ops.cpp). field_gradient(): component `axis` at the lanes' points.
  void fieldHit(const RasterState& state, int bx, int by, uint64_t exec, float field, float method, float param,
                float* t);
  void fieldGradient(const RasterState& state, uint64_t exec, float field, int axis, bool by_differences,
                     const float* const p[3], const bool p_wide[3], float* out);
  // field_color(): colour component `component` (0 red, 1 green, 2 blue) of the field's
  // attributes at the lanes' points; 1 where the field defines no such attribute.
  void fieldColor(const RasterState& state, uint64_t exec, float field, int component, const float* const p[3],
                  const bool p_wide[3], float* out);
  const field::ImplicitField* lookUpField(const RasterState& state, float id, uint64_t exec);

  // The programs this frame ran, decoded (decoded_program.h); startFrame() forgets them but
  // keeps their storage. Few per frame: found by a linear search from the last one used.
  const DecodedProgram& decoded(const PixelProgram& program, const LaneIsaTables& isa, bool wide_uniforms);
  std::vector<DecodedProgram> decoded_;
  size_t decoded_live_ = 0;
  size_t decoded_last_[2] = {0, 0};  // the last found, per decoding (scalar, wide uniforms)

  NativeBlocks native_;
  NativeBlocks::PreparedCall native_call_;  // runBlocks' arguments
  field::FieldRayCaster caster_;
  BlockRejection rejection_;
  // The verdicts of a tile's regions (regionVerdict) and what each was computed for.
  static constexpr int kBlocksPerRegion = (kRejectionRegion / kBlockSize) * (kRejectionRegion / kBlockSize);
  struct RegionMemo {
    const PixelProgram* program = nullptr;
    int x = -1, y = -1;
    std::vector<uint32_t> record;
    const uint32_t* record_address = nullptr;  // the record last found to hold those values
    RegionVerdict verdict = RegionVerdict::Unknown;
    // Where the region's verdict is Unknown: its blocks' own (blockVerdict), once asked for.
    bool blocks_known = false;
    uint8_t blocks[kBlocksPerRegion];
    // Remembers `verdict` for region (x, y) of `program` with the record's `words` values.
    void remember(const PixelProgram& p, const uint32_t* rec, size_t words, int rx, int ry, RegionVerdict v) {
      program = nullptr;  // (the key last: if copying the record fails, no key names a stale one)
      record.assign(rec, rec + words);
      x = rx;
      y = ry;
      verdict = v;
      blocks_known = false;
      program = &p;
    }
  };
  RegionMemo region_memos_[(kTileSize / kRejectionRegion) * (kTileSize / kRejectionRegion)];
  RegionMemo& regionMemo(const PixelProgram& program, const uint32_t* record, const RasterState& state, int bx,
                         int by);
  // Fills the memos of the tile holding region (rx, ry) with native code's walk over its
  // regions at once; false (nothing filled) where there is none yet.
  bool walkTileRegions(const PixelProgram& program, const uint32_t* record, const RasterState& state, int rx, int ry);
  RegionVerdict regionVerdict(const PixelProgram& program, const uint32_t* record, const RasterState& state, int bx,
                              int by) {
    return regionMemo(program, record, state, bx, by).verdict;
  }
  // The verdict for the block at (bx, by): its region's, or where that is Unknown, the block's
  // own -- from native code's walk over the region's blocks at once, where there is one (a walk
  // per block on the interpreter costs more than the blocks it saves: docs/performance.md).
  RegionVerdict blockVerdict(const PixelProgram& program, const uint32_t* record, const RasterState& state, int bx,
                             int by);
  // Whether walking a region's blocks pays for a program, learnt in each frame: the walk costs
  // about what running a few blocks does, so it pays only where it decides most of the 16 --
  // triangles, tori, quadrics decide about three in four; a sphere's silhouette one in four
  // or five, and spheres drew faster without the walks (docs/performance.md). A program's first
  // kProbeWalks walks of the frame (on this thread) are made; after them, a region's blocks are
  // walked only while the walks so far decided at least half of their blocks. Which blocks run
  // changes, never the image (the blocks not decided run the full program).
  struct BlockWalkTally {
    const PixelProgram* program = nullptr;
    const Instr* code = nullptr;
    uint32_t walks = 0;    // walks over a region's blocks this frame
    uint32_t decided = 0;  // the blocks they rejected or accepted
  };
  std::vector<BlockWalkTally> block_walk_tallies_;
  size_t block_walk_tallies_live_ = 0;
  BlockWalkTally& blockWalkTally(const PixelProgram& program);
  float field_box_[6] = {0, 0, 0, 0, 0, 0};
  std::unordered_map<const field::ImplicitField*, std::unique_ptr<field::GradientEvaluator>> gradients_;
  // The float form of each field's attribute tapes (field_color()), built when first asked.
  std::unordered_map<const field::FieldTape*, std::unique_ptr<field::FloatEvaluator>> attribute_evaluators_;
  // The gradient of a short tape (HitTapes): one evaluator per executor -- so per rasterizer
  // thread -- reset() for each tape in turn, its storage reused.
  field::GradientEvaluator short_gradient_;
  // The last FieldHit of this program run: its field, its hit lanes and the tapes that found
  // them (the gradient at a point inside a lane's box runs that lane's short tape).
  uint64_t run_serial_ = 0;  // counts program runs
  uint64_t hit_serial_ = 0;
  const field::ImplicitField* hit_field_ = nullptr;
  uint64_t hit_lanes_ = 0;
  field::HitTapes hit_tapes_;
  // The last gradient computed (all three components, for the lanes in `lanes`): the three
  // FieldGradient instructions of one field_gradient() share it.
  struct GradientCache {
    const field::ImplicitField* field = nullptr;
    bool by_differences = false;
    uint64_t lanes = 0;
    float q[3][kLanes];  // the points
    float g[3][kLanes];
    std::vector<std::pair<const field::FieldTape*, uint64_t>> groups;  // scratch: lanes per tape
  } gradient_cache_;

  std::unique_ptr<PixelExecutor> shared_;  // runs shared interpolators (their own registers)
  std::vector<uint32_t> shade_out_;        // 4 x kLanes: a shared interpolator's value
  std::vector<uint32_t> surface_ = std::vector<uint32_t>(8 * kLanes);  // P (4), N (3) per lane
  std::vector<uint32_t> regs_;     // num_regs x kLanes
  std::vector<uint32_t> xregs_;    // num_interp_regs x channels x kLanes
  std::vector<uint32_t> staging_;  // channels x kLanes: interpolator_return results
  std::vector<uint32_t> gang_record_;  // a gang block's uniforms: kLanes per record word
  // The record words a gang's program reads, per program and values of its branch slots, for
  // the frame (startFrame forgets them; their storage is kept).
  struct GangWordRuns {
    const PixelProgram* program = nullptr;
    const Instr* code = nullptr;
    int channels = 0;
    std::vector<uint32_t> branch_values;
    std::vector<RecordWordRun> runs;
  };
  RecordReadsScratch record_reads_scratch_;
  std::vector<GangWordRuns> gang_runs_;
  size_t gang_runs_live_ = 0;
  const std::vector<RecordWordRun>& gangWordRuns(const PixelProgram& program, int channels, const uint32_t* record);
};

}  // namespace pf
