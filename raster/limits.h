// Every size and limit of the rasterizer in one place (as llvmpipe's lp_limits.h).
#pragma once

namespace pf {

constexpr int kTileSize = 64;          // screen tiles: the unit of binning and of threading
constexpr int kBlockSize = 8;          // pixel blocks: the unit of SIMD execution
constexpr int kLanes = kBlockSize * kBlockSize;  // lanes of a wide register
constexpr int kMaxFramebufferSize = 8192;
constexpr int kMaxChannels = 64;       // per-vertex shading-parameter floats per instance
constexpr int kMaxMaskDepth = 64;      // nesting of ifs and loops in a program
constexpr unsigned kDefaultIterationCap = 65536;  // per pixel and loop; per context settable

}  // namespace pf
