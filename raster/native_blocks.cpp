// Native pixel programs from the rasterizer's side (see native_blocks.h).
#include "raster/native_blocks.h"

#include "compiler/native/native_cache.h"
#include "raster/lane_kernels.h"
#include "raster/limits.h"
#include "raster/pixel_executor.h"

namespace pf {

static_assert(kNativeBlockSize == kBlockSize && kNativeLanes == kLanes && kNativeTileSize == kTileSize,
              "compiler/native/native_abi.h repeats the rasterizer's sizes");

namespace {

NativeIsa nativeIsaOf(LaneIsa isa) {
  switch (isa) {
    case LaneIsa::Avx512: return NativeIsa::Avx512;
    case LaneIsa::Avx2: return NativeIsa::Avx2;
    case LaneIsa::Baseline: break;
  }
  return NativeIsa::Sse2;
}

NativeDepthCompare depthCompareOf(const RasterState& s) {
  if (!s.depth_test) return NativeDepthCompare::Always;
  switch (s.depth_func) {
    case DepthFunc::Never: return NativeDepthCompare::Never;
    case DepthFunc::Less: return NativeDepthCompare::Less;
    case DepthFunc::Equal: return NativeDepthCompare::Equal;
    case DepthFunc::LessEqual: return NativeDepthCompare::LessEqual;
    case DepthFunc::Greater: return NativeDepthCompare::Greater;
    case DepthFunc::NotEqual: return NativeDepthCompare::NotEqual;
    case DepthFunc::GreaterEqual: return NativeDepthCompare::GreaterEqual;
    case DepthFunc::Always: break;
  }
  return NativeDepthCompare::Always;
}

bool readsState(const PixelProgram& p) {
  for (const Instr& in : p.code)
    if (in.op == Op::LoadState) return true;
  return false;
}

}  // namespace

void NativeBlocks::startFrame() {
  found_.clear();
  last_ = 0;
  values_valid_ = false;
}

NativeBlockFunction NativeBlocks::find(const CompiledPrimitive& prim, const PixelProgram& program,
                                       const ChannelLayout& layout, const RasterState& state, const BlockTarget& target,
                                       NativeBlockShape shape) {
  const NativeDepthCompare compare = depthCompareOf(state);
  const bool has_depth = target.depth != nullptr;
  const bool depth_commit = has_depth && state.depth_test && state.depth_write;
  const uint8_t depth = static_cast<uint8_t>(static_cast<unsigned>(compare) | (has_depth ? 16u : 0u) | (depth_commit ? 32u : 0u));
  const NativeIsa isa = nativeIsaOf(laneIsa());
  auto matches = [&](const Found& f) {
    return f.program == &program && f.code == program.code.data() && f.code_size == program.code.size() &&
           f.layout == &layout && f.depth == depth && f.shape == shape && f.isa == isa;
  };
  if (last_ < found_.size() && matches(found_[last_])) return found_[last_].fn;
  for (size_t i = 0; i < found_.size(); ++i)
    if (matches(found_[i])) {
      last_ = i;
      return found_[i].fn;
    }

  NativePixelVariant& v = variant_;
  v.shared.clear();
  v.named_bound.clear();
  v.isa = isa;
  v.shape = shape;
  v.depth_compare = compare;
  v.has_depth_buffer = has_depth;
  v.depth_commit = depth_commit;
  v.channels = layout.count;
  for (int k = 0; k < kInterpKindCount; ++k) {
    v.kind_begin[k] = layout.kind_begin[k];
    v.kind_end[k] = layout.kind_end[k];
  }
  v.commit_surface = layout.surface_slot >= 0 && !layout.surface_interpolated;
  v.surface_eye = layout.surface_eye;
  v.writes_normal = prim.writes_normal;
  for (const ChannelLayout::SharedInterpolator& s : layout.shared) {
    NativePixelVariant::Shared n;
    n.pixel = &s.program->pixel;
    n.first = s.first;
    n.record_offset = s.record_offset;
    for (size_t k = 0; k < prim.named_interpolators.size(); ++k)
      if (prim.named_interpolators[k] == s.program->name) {
        n.named_index = static_cast<int>(k);
        break;
      }
    v.shared.push_back(n);
  }
  for (const std::string& name : prim.named_interpolators) v.named_bound.push_back(layout.bindsInterpolator(name));
  NativeBlockFunction fn;
  fn.fn = NativeProgramCache::instance().pixelFunction(program, v);
  fn.reads_state = readsState(program);
  found_.push_back(Found{&program, program.code.data(), program.code.size(), &layout, depth, shape, isa, fn});
  last_ = found_.size() - 1;
  return fn;
}

uint64_t NativeBlocks::run(const NativeBlockFunction& fn, const CompiledPrimitive& prim, const uint32_t* record, const ChannelLayout& layout, const RasterState& state,
                           uint32_t shade_id, int bx, int by, const PackedLanes* packed, uint64_t mask,
                           const BlockTarget& target, const uint32_t* shared_records, uint64_t& cap_lanes,
                           const CompiledPrimitive*& cap_primitive) {
  NativeBlockArgs a;
  a.record = record;
  a.shared_records = shared_records;
  if (packed) {
    a.lane_x = packed->x;
    a.lane_y = packed->y;
  }
  a.depth = target.depth;
  a.depth_stride = target.depth_stride;
  if (fn.reads_state) {
    if (!values_valid_ || !(values_state_ == state)) {
      for (int k = 0; k < kStateValueCount; ++k) state_values_[k] = stateValue(state, static_cast<uint16_t>(k));
      values_state_ = state;
      values_valid_ = true;
    }
    a.state_values = state_values_;
  }
  a.shade_ids = target.shade_ids;
  float* planes[kMaxChannels];
  const int channels = std::min(layout.count, kMaxChannels);
  for (int ch = 0; ch < channels; ++ch) planes[ch] = target.slots[layout.gbuffer_slot[static_cast<size_t>(ch)]];
  a.planes = planes;
  if (layout.surface_slot >= 0 && !layout.surface_interpolated) a.surface_planes = target.slots + layout.surface_slot;
  a.mask = mask;
  a.bx = bx;
  a.by = by;
  a.tile_x0 = target.tile_x0;
  a.tile_y0 = target.tile_y0;
  a.shade_id = shade_id;
  a.iteration_cap = state.iteration_cap;
  const uint64_t alive = fn.fn(&a);
  if (a.cap_lanes) {
    cap_lanes += a.cap_lanes;
    cap_primitive = a.cap_source < 0 ? &prim : layout.shared[static_cast<size_t>(a.cap_source)].program;
  }
  return alive;
}

}  // namespace pf
