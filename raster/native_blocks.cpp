// Native pixel programs from the rasterizer's side (see native_blocks.h).
#include "raster/native_blocks.h"

#include "compiler/native/native_cache.h"
#include "raster/lane_kernels.h"
#include "raster/limits.h"
#include "raster/pixel_executor.h"

namespace pf {

static_assert(kNativeBlockSize == kBlockSize && kNativeLanes == kLanes && kNativeTileSize == kTileSize,
              "compiler/native/native_abi.h repeats the rasterizer's sizes");
static_assert(RasterState::kMaxClipPlanes == kNativeMaxClipPlanes, "native code reads every clip plane");

namespace {

// The entry of `items` that `matches` -- the last one found first -- or null.
template <class T, class Matches>
T* findRemembered(std::vector<T>& items, size_t& last, const Matches& matches) {
  if (last < items.size() && matches(items[last])) return &items[last];
  for (size_t i = 0; i < items.size(); ++i)
    if (matches(items[i])) {
      last = i;
      return &items[i];
    }
  return nullptr;
}

bool readsState(const PixelProgram& p) {
  for (const Instr& in : p.code)
    if (in.op == Op::LoadState) return true;
  return false;
}

}  // namespace

NativeIsa nativeIsaOf(LaneIsa isa) {
  switch (isa) {
    case LaneIsa::Avx512: return NativeIsa::Avx512;
    case LaneIsa::Avx2: return NativeIsa::Avx2;
    case LaneIsa::Baseline: break;
  }
  return NativeIsa::Sse2;
}

void NativeBlocks::startFrame() {
  found_.clear();
  last_ = 0;
  walks_.clear();
  last_walk_ = 0;
  values_valid_ = false;
}

uint32_t NativeBlocks::depthPass(const RasterState& s) {
  constexpr uint32_t kAll = kDepthPassLess | kDepthPassEqual | kDepthPassGreater | kDepthPassUnordered;
  if (!s.depth_test) return kAll;
  switch (s.depth_func) {
    case DepthFunc::Never: return 0;
    case DepthFunc::Less: return kDepthPassLess;
    case DepthFunc::Equal: return kDepthPassEqual;
    case DepthFunc::LessEqual: return kDepthPassLess | kDepthPassEqual;
    case DepthFunc::Greater: return kDepthPassGreater;
    case DepthFunc::NotEqual: return kDepthPassLess | kDepthPassGreater | kDepthPassUnordered;
    case DepthFunc::GreaterEqual: return kDepthPassGreater | kDepthPassEqual;
    case DepthFunc::Always: break;
  }
  return kAll;
}

const NativePixelVariant& NativeBlocks::variantFor(const CompiledPrimitive& prim, const ChannelLayout& layout, bool gang,
                                                   NativeIsa isa) {
  NativePixelVariant& v = variant_;
  v.shared.clear();
  v.named_bound.clear();
  v.isa = isa;
  v.gang = gang;
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
  return v;
}

NativeBlockFunction NativeBlocks::find(const CompiledPrimitive& prim, const PixelProgram& program,
                                       const ChannelLayout& layout, bool gang) {
  const NativeIsa isa = nativeIsaOf(laneIsa());
  auto matches = [&](const Found& f) {
    return f.program == &program && f.code == program.code.data() && f.code_size == program.code.size() &&
           f.layout == &layout && f.gang == gang && f.isa == isa;
  };
  Found* found = findRemembered(found_, last_, matches);
  if (!found) {
    NativeProgramCache::Entry* e = NativeProgramCache::instance().pixelEntry(program, variantFor(prim, layout, gang, isa));
    found_.push_back(Found{&program, program.code.data(), program.code.size(), &layout, gang, isa, e, {}, false});
    last_ = found_.size() - 1;
    found = &found_.back();
    found->fn.reads_state = readsState(program);
  }
  if (found->fn.fn || found->never) return found->fn;
  // Not compiled yet: this block counts towards the threshold (and may compile it).
  NativeProgramCache& cache = NativeProgramCache::instance();
  auto f = reinterpret_cast<NativePixelFunction>(found->entry->function());
  if (!f && cache.drawn(found->entry, 1))
    f = reinterpret_cast<NativePixelFunction>(
        cache.compile(found->entry, program, &variantFor(prim, layout, gang, isa)));
  found->fn.fn = f;
  found->never = !f && found->entry->settled();
  return found->fn;
}

const float* NativeBlocks::stateValues(const RasterState& state) {
  if (!values_valid_ || !(values_state_ == state)) {
    for (int k = 0; k < kStateValueCount; ++k) state_values_[k] = stateValue(state, static_cast<uint16_t>(k));
    values_state_ = state;
    values_valid_ = true;
  }
  return state_values_;
}

NativeBlocks::FoundWalk* NativeBlocks::walkFor(const PixelProgram& program, int lanes) {
  const NativeIsa isa = nativeIsaOf(laneIsa());
  auto matches = [&](const FoundWalk& f) {
    return f.program == &program && f.code == program.code.data() && f.code_size == program.code.size() &&
           f.lanes == lanes && (lanes == 1 || f.isa == isa);
  };
  FoundWalk* found = findRemembered(walks_, last_walk_, matches);
  if (!found) {
    NativeProgramCache& cache = NativeProgramCache::instance();
    NativeProgramCache::Entry* e =
        lanes == 1 ? cache.verdictEntry(program) : cache.blockVerdictsEntry(program, isa, lanes);
    walks_.push_back(FoundWalk{&program, program.code.data(), program.code.size(), isa, lanes, e, nullptr, false,
                               readsState(program)});
    last_walk_ = walks_.size() - 1;
    found = &walks_.back();
  }
  if (!found->fn && !found->never) {
    // (A walk costs about what a block does, and compiles slower than a pixel program: each
    // counts as one block towards the threshold.)
    NativeProgramCache& cache = NativeProgramCache::instance();
    void* f = found->entry->function();
    if (!f && cache.drawn(found->entry, 1))
      f = lanes == 1 ? cache.compile(found->entry, program, nullptr)
                     : cache.compileBlockVerdicts(found->entry, program, isa, lanes);
    found->fn = f;
    found->never = !f && found->entry->settled();
  }
  return found;
}

bool NativeBlocks::verdict(const PixelProgram& program, const uint32_t* record, const RasterState& state,
                           const double region[4], uint32_t& out) {
  const FoundWalk* found = walkFor(program, 1);
  if (!found->fn) return false;
  out = reinterpret_cast<NativeVerdictFunction>(found->fn)(record, found->reads_state ? stateValues(state) : nullptr,
                                                           region);
  return true;
}

bool NativeBlocks::verdicts(const PixelProgram& program, const uint32_t* record, const RasterState& state, int lanes,
                            const double* regions, uint8_t* verdicts) {
  const FoundWalk* found = walkFor(program, lanes);
  if (!found->fn) return false;
  reinterpret_cast<NativeBlockVerdictsFunction>(found->fn)(record, found->reads_state ? stateValues(state) : nullptr,
                                                           regions, verdicts);
  return true;
}

void NativeBlocks::prepare(PreparedCall& call, const CompiledPrimitive& prim, const uint32_t* record,
                           const ChannelLayout& layout, const RasterState& state, uint32_t shade_id,
                           const PackedLanes* packed, const BlockTarget& target, const uint32_t* shared_records) {
  NativeBlockArgs& a = call.args;
  a = NativeBlockArgs{};
  a.record = record;
  a.shared_records = shared_records;
  if (packed) {
    a.lane_x = packed->x;
    a.lane_y = packed->y;
  }
  a.depth = target.depth;
  a.depth_stride = target.depth_stride;
  a.shade_ids = target.shade_ids;
  const int channels = std::min(layout.count, kMaxChannels);
  for (int ch = 0; ch < channels; ++ch) call.planes[ch] = target.slots[layout.gbuffer_slot[static_cast<size_t>(ch)]];
  a.planes = call.planes;
  if (layout.surface_slot >= 0 && !layout.surface_interpolated) a.surface_planes = target.slots + layout.surface_slot;
  a.tile_x0 = target.tile_x0;
  a.tile_y0 = target.tile_y0;
  a.shade_id = shade_id;
  a.iteration_cap = state.iteration_cap;
  a.depth_pass = depthPass(state);
  a.clip_planes = &state.clip_planes[0][0];
  a.clip_plane_count = static_cast<uint32_t>(state.clip_plane_count);
  a.polygon_stipple = state.polygon_stipple ? state.stipple_rows : nullptr;
  a.depth_write = target.depth && state.depth_test && state.depth_write ? 1u : 0u;
  call.state = &state;
  call.prim = &prim;
  call.layout = &layout;
}

uint64_t NativeBlocks::call(const NativeBlockFunction& fn, PreparedCall& call, int bx, int by, uint64_t mask,
                            uint64_t& cap_lanes, const CompiledPrimitive*& cap_primitive) {
  NativeBlockArgs& a = call.args;
  if (fn.reads_state && !a.state_values) a.state_values = stateValues(*call.state);
  a.mask = mask;
  a.bx = bx;
  a.by = by;
  a.cap_lanes = 0;
  a.cap_source = -1;
  const uint64_t alive = fn.fn(&a);
  if (a.cap_lanes) {
    cap_lanes += a.cap_lanes;
    cap_primitive = a.cap_source < 0 ? call.prim : call.layout->shared[static_cast<size_t>(a.cap_source)].program;
  }
  return alive;
}

uint64_t NativeBlocks::run(const NativeBlockFunction& fn, const CompiledPrimitive& prim, const uint32_t* record,
                           const ChannelLayout& layout, const RasterState& state, uint32_t shade_id, int bx, int by,
                           const PackedLanes* packed, uint64_t mask, const BlockTarget& target,
                           const uint32_t* shared_records, uint64_t& cap_lanes,
                           const CompiledPrimitive*& cap_primitive) {
  prepare(single_, prim, record, layout, state, shade_id, packed, target, shared_records);
  return call(fn, single_, bx, by, mask, cap_lanes, cap_primitive);
}

}  // namespace pf
