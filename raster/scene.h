// A frame's worth of binned work (llvmpipe's "scene"): the instances submitted since the last
// flush, their uniform records in one arena, the states they share, and one bin per screen
// tile listing the instances that touch it in submission order. Vectors keep their capacity
// from frame to frame, so the steady state allocates nothing per instance.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/compiler.h"
#include "raster/huge_page_allocator.h"
#include "raster/raster_state.h"
#include "raster/shading.h"

namespace pf {

struct Instance {
  const CompiledPrimitive* prim;
  uint32_t record_offset;  // into Scene::records
  uint16_t state;          // into Scene::states
  uint16_t layout;         // into Scene::layouts
  uint32_t shade_id;       // 1 + index into Scene::shades
  uint32_t shared_offset;  // into Scene::records: its shared interpolators' records (kNoShared: none)
  int x0, y0, x1, y1;      // pixels [x0, x1) x [y0, y1) that the instance may cover
  // depth_bound(): every depth its pixels test lies in [z_min, z_max] (raster/coarse_depth.h);
  // without one, has_depth_bound is false.
  bool has_depth_bound;
  float z_min, z_max;
};

constexpr uint32_t kNoShared = 0xffffffffu;

struct TileBin {
  std::vector<uint32_t> instances;
};

// A rectangle of pixels [x0, x1) x [y0, y1) in window coordinates.
struct PixelRect {
  int x0 = INT32_MIN, y0 = INT32_MIN, x1 = INT32_MAX, y1 = INT32_MAX;  // (the default: everything)
  bool operator==(const PixelRect&) const = default;
};

struct PendingClear {
  bool color = false, depth = false;
  float rgba[4] = {0, 0, 0, 0};
  float z = 1.0f;
  uint8_t color_mask = 0xf;  // RGBA channels the colour clear writes
  PixelRect rect;            // the pixels cleared (the scissor box, under GL_SCISSOR_TEST)
  bool stencil = false;      // the stencil buffer: stencil_value into the bits of stencil_mask
  uint8_t stencil_value = 0, stencil_mask = 0xff;
};

struct Scene {
  std::vector<Instance, HugePageAllocator<Instance>> instances;
  std::vector<uint32_t, HugePageAllocator<uint32_t>> records;
  std::vector<RasterState> states;
  std::vector<ChannelLayout> layouts;
  std::vector<ShadeState> shades;
  uint32_t current_shade = 0;  // of the instances being submitted (a back variant may follow it)
  std::vector<LightingState> lightings;  // per-pixel lighting states (ShadeState::lighting)
  std::vector<LightingEquation> lighting_equations;  // each one's equation, for the shading pass
  std::vector<TileBin> bins;
  int tiles_x = 0, tiles_y = 0;
  int gbuffer_slots = 0;
  uint8_t color_mask = 0xf;  // of every instance in the scene (a change of mask flushes)
  PendingClear clear;

  bool empty() const { return instances.empty() && !clear.color && !clear.depth && !clear.stencil; }
  bool clearing() const { return clear.color || clear.depth || clear.stencil; }
  void reset() {
    instances.clear();
    records.clear();
    states.clear();
    layouts.clear();
    shades.clear();
    lightings.clear();
    lighting_equations.clear();
    for (TileBin& b : bins) b.instances.clear();
    gbuffer_slots = 0;
    clear = PendingClear{};
  }
};

}  // namespace pf
