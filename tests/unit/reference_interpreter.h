// The scalar reference interpreter: runs a primitive's optimized IR for one pixel, directly --
// no setup / pixel split, no masks, no SIMD. The test helpers run it beside the real executors
// on every lane and require identical results, so every language test checks the split, the
// masking and the SIMD execution against it (the two execution modes of the compiler issue).
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/ir.h"
#include "raster/raster_state.h"

namespace pf::test {

struct ReferencePixel {
  bool drawn = false;         // survived to the end of the primitive
  bool depth_written = false;
  float depth = 0.0f;
  std::vector<float> channels;  // the shading channels interpolator_return left (0 if none)
  bool iteration_cap_hit = false;
};

ReferencePixel runReference(const IrFunction& f, const std::vector<uint32_t>& params,
                            const std::vector<float>& vertex_channels, const ChannelLayout& layout,
                            const RasterState& state, float x, float y, float depth_in);

}  // namespace pf::test
