// Every size and limit of the rasterizer in one place (as llvmpipe's lp_limits.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "compiler/isa.h"

namespace pf {

constexpr int kTileSize = 64;          // screen tiles: the unit of binning and of threading
constexpr int kBlockSize = 8;          // pixel blocks: the unit of SIMD execution
constexpr int kLanes = kBlockSize * kBlockSize;  // lanes of a wide register
constexpr int kMaxFramebufferSize = 8192;
// Instances one submission may make by calling primitives: this many for each iteration the
// context's iteration cap allows (2^21 at the default cap), besides four a sequence point (a
// strip's or polygon's triangles); past it the calls are dropped and reported as a runaway
// (GL_TOO_MANY_ITERATIONS_EXT).
constexpr uint64_t kCallsPerIteration = 32;
// Uniform-record words a scene holds before a submission flushes it (offsets are 32-bit).
constexpr size_t kMaxRecordWords = size_t(1) << 30;
constexpr int kMaxChannels = 64;       // per-vertex shading-parameter floats per instance
constexpr int kMaxMaskDepth = kMaxProgramNesting;  // nesting of ifs and loops (compiler/isa.h)
constexpr unsigned kDefaultIterationCap = 65536;  // per pixel and loop; per context settable

}  // namespace pf
