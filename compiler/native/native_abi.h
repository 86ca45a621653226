// The calling convention between native pixel programs (compiler/native/pixel_codegen.h) and
// the rasterizer that runs them: plain data only, no LLVM. A compiled pixel program is one
// function over one 8x8 pixel block -- its X/Y/Z set-up, the program, the depth test and write,
// and the commit of the surviving lanes to the tile's G-buffer -- specialised on what is known
// when the block is drawn (NativePixelVariant); what changes per block arrives in
// NativeBlockArgs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pf {

struct PixelProgram;

// Lanes of a block (8x8) and of the tile's G-buffer planes (64x64): raster/limits.h's values,
// repeated here because the compiler does not include the rasterizer (checked there).
constexpr int kNativeBlockSize = 8;
constexpr int kNativeLanes = 64;
constexpr int kNativeTileSize = 64;

// The instruction set native code is generated for, and so its vector width (lanes per
// vector register of 32-bit values): the same three sets as the interpreter's kernels.
enum class NativeIsa : uint8_t { Sse2, Avx2, Avx512 };
constexpr int nativeVectorWidth(NativeIsa isa) { return isa == NativeIsa::Avx512 ? 16 : isa == NativeIsa::Avx2 ? 8 : 4; }
const char* nativeIsaName(NativeIsa isa);

// A block's lanes are an aligned 8x8 block at (bx, by) or packed lanes, each its own pixel
// (lane_x, lane_y): one function runs both, told by NativeBlockArgs::lane_x. A gang block
// (packed lanes of several instances) reads a record holding kNativeLanes words per slot, one
// per lane's instance: a variant of its own.

// ztest(z): the outcomes of comparing z with the depth buffer's d that pass (GL's depth
// function; all four when the test is off): NativeBlockArgs::depth_pass.
constexpr uint32_t kDepthPassLess = 1, kDepthPassEqual = 2, kDepthPassGreater = 4, kDepthPassUnordered = 8;

// What a native pixel program is specialised on (part of its cache key with the program's
// content): the instruction set, the record's shape and the instance's channel layout.
struct NativePixelVariant {
  NativeIsa isa = NativeIsa::Sse2;
  bool gang = false;  // the record holds each lane's instance's values (a gang block)
  // The channels (raster's ChannelLayout): how many, and each interpolation kind's range.
  int channels = 0;
  int kind_begin[3] = {0, 0, 0};
  int kind_end[3] = {0, 0, 0};
  // Per-pixel lighting's surface (P's 3 slots when surface_eye, then N's 3) for the lanes that
  // commit; writes_normal: the primitive sets N (else the slots get zeros).
  bool commit_surface = false;
  bool surface_eye = false;
  bool writes_normal = false;
  // The layout's shared interpolators, in order: their pixel program, first channel and
  // record offset among the instance's shared records; `named_index`: the entry of the
  // primitive's named_interpolators that names it -- the primitive fills those channels itself
  // (a `name:` label) and the interpolator does not run -- or -1.
  struct Shared {
    const PixelProgram* pixel = nullptr;
    int first = 0;
    uint32_t record_offset = 0;
    int named_index = -1;
  };
  std::vector<Shared> shared;
  // Per entry of the primitive's named_interpolators: whether the layout binds it.
  std::vector<bool> named_bound;
};

// The per-block arguments of a native pixel program.
struct NativeBlockArgs {
  const uint32_t* record = nullptr;          // the instance's uniform record (a gang's: wide)
  const uint32_t* shared_records = nullptr;  // the layout's shared interpolators' records
  const int32_t* lane_x = nullptr;           // packed lanes: each lane's pixel; null: aligned at (bx, by)
  const int32_t* lane_y = nullptr;
  float* depth = nullptr;  // the depth buffer (whole framebuffer), or null: Z starts at 0
  const float* state_values = nullptr;  // compiler/isa.h's StateValue order (LoadState)
  uint32_t* shade_ids = nullptr;        // the tile's G-buffer: shading state per pixel
  float* const* planes = nullptr;       // per channel, its G-buffer plane (64x64 floats)
  float* const* surface_planes = nullptr;  // the 6 surface planes, when commit_surface
  uint64_t mask = 0;         // the lanes that start (bit i: lane i)
  uint64_t cap_lanes = 0;    // out: lanes the iteration cap stopped
  int32_t cap_source = -1;   // out: who hit it: -1 the primitive, k the layout's shared interpolator k
  int32_t bx = 0, by = 0;    // an aligned block's lower-left pixel
  int32_t depth_stride = 0;  // floats per row of the depth buffer
  int32_t tile_x0 = 0, tile_y0 = 0;
  uint32_t shade_id = 0;
  uint32_t iteration_cap = 0;
  uint32_t depth_pass = 0;   // kDepthPass* bits
  uint32_t depth_write = 0;  // 1: ZCommit writes (a depth buffer, the depth test on, depth writes on)
  // User clip planes ztest() applies: clip_plane_count window-space planes (a, b, c, d), 4 floats
  // each (raster's RasterState::clip_planes); a fragment at (X, Y, z) passes where
  // ((a * X + b * Y) + c * z) + d >= 0 for every one.
  const float* clip_planes = nullptr;
  uint32_t clip_plane_count = 0;
  // The polygon stipple polygon_ztest() applies (a ZTest whose imm is 1): 32 rows, bit
  // 31 - (x mod 32) of row y mod 32 keeps the fragment at (x, y) (raster's
  // RasterState::stipple_rows); null when GL_POLYGON_STIPPLE is off.
  const uint32_t* polygon_stipple = nullptr;
};

// The most clip planes NativeBlockArgs::clip_planes holds (RasterState::kMaxClipPlanes).
constexpr int kNativeMaxClipPlanes = 8;

// A compiled pixel program: returns the lanes that committed (alive at the end).
using NativePixelFunction = uint64_t (*)(NativeBlockArgs* args);

// --- Setup programs ------------------------------------------------------------------------
// A compiled setup program runs a batch of up to kNativeSetupLanes instances of one primitive,
// one per lane (raster/setup_batch.h), for as long as they take the same path: the native
// counterpart of the batched interpreter's loop. Where the lanes disagree at a conditional
// jump, or at an instruction it does not run (calls of other primitives), it stops before that
// instruction with every register written back, and the batched interpreter goes on from
// there exactly as if it had run the batch so far itself.
constexpr int kNativeSetupLanes = 16;
constexpr int kNativeSetupMaxLoops = 64;  // open loops (compiler/isa.h's kMaxProgramNesting)

// What a native setup program is specialised on besides its content: the instruction set and
// the instances' channel layout (raster's ChannelLayout).
struct NativeSetupVariant {
  NativeIsa isa = NativeIsa::Sse2;
  int channels = 0;
  int kind_begin[3] = {0, 0, 0};
  int kind_end[3] = {0, 0, 0};
  // Per entry of the primitive's named_interpolators: whether the layout binds it (HasNamed).
  std::vector<bool> named_bound;
};

enum class NativeSetupStatus : uint32_t {
  Done = 0,    // the program ran to its end: each lane's record written
  Killed = 1,  // every lane was killed (Kill)
  CapHit = 2,  // a loop ran past the cap: every lane killed
  Left = 3,    // stopped before instruction `pc`: the interpreter goes on from there
};

// The arguments of one batch. Where it stops before the end (Left), the registers are written
// to the batched interpreter's file, lane-major: register r of lane l at
// regs[r * kNativeSetupLanes + l]; interp register i, channel c of lane l at
// interp[(i * channels + c) * kNativeSetupLanes + l]. At the end (Done) it writes each lane's
// record itself (the exports: SetupProgram::scalar_exports, then interp_exports' channels).
struct NativeSetupArgs {
  uint32_t* regs = nullptr;              // out: the registers (num_regs rows)
  float* interp = nullptr;               // out: the interp registers
  const float* state_values = nullptr;   // compiler/isa.h's StateValue order (LoadState)
  // Each lane's parameter block, sequence points' channels and record (lanes past the batch:
  // lane 0's blocks, and no record).
  const uint32_t* params[kNativeSetupLanes] = {};
  const float* vertex_channels[kNativeSetupLanes] = {};
  uint32_t* records[kNativeSetupLanes] = {};
  uint64_t iteration_cap = 0;   // a loop's iterations before the lanes are killed
  int64_t param_words = 0;      // words in each parameter block (LoadParamAt past them: 0)
  uint32_t active = 0;          // the batch's lanes (bit l: lane l), from lane 0 up
  int32_t sequence_points = 0;
  // Out: where it stopped, the instructions run (the same for every lane), the loops open.
  uint32_t pc = 0;
  uint32_t instructions = 0;
  int32_t loop_depth = 0;
  uint32_t loop_counters[kNativeSetupMaxLoops] = {};
  // Out: the effects, each lane's (set: the instruction ran; the last one's values).
  uint32_t has_bound = 0, has_depth_bound = 0, has_facing = 0;
  float bound[4][kNativeSetupLanes] = {};
  float depth_bound[2][kNativeSetupLanes] = {};
  uint32_t back_facing[kNativeSetupLanes] = {};
};

using NativeSetupFunction = NativeSetupStatus (*)(NativeSetupArgs* args);

}  // namespace pf
