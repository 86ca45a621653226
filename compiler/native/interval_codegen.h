// Block rejection as native code: raster/block_rejection.cpp's interval walk over a pixel
// program's leading part, compiled for one program. The interpreter of that walk decodes every
// instruction and operand for each 32x32 region it is asked about (a fifth of a frame of large
// triangles); here the walk is straight-line code over the ranges of the region's X and Y and
// the instance's uniforms, the constants folded in. It computes exactly the interpreter's
// ranges -- the same double operations, widenings and NaN tracking, in the same order -- so the
// verdicts are the same (tests/unit/native_rejection_test.cpp compares them).
#pragma once

#include <cstdint>
#include <string>

#include "compiler/isa.h"

namespace llvm {
class Function;
class Module;
}  // namespace llvm

namespace pf {

// The verdict of `program` for the instance's `record` over the pixel centres
// region = {x_lo, x_hi, y_lo, y_hi}: 0 unknown, 1 rejected, 2 accepted (RegionVerdict's values).
// `state_values`: compiler/isa.h's StateValue order, read where the program loads the state.
using NativeVerdictFunction = uint32_t (*)(const uint32_t* record, const float* state_values, const double* region);

// The same walk over `lanes` regions at once, one per lane of a vector (the rasterizer asks it
// about the kNativeRegionLanes 32x32 regions of a tile, and about the kNativeVerdictLanes 8x8
// blocks of a region whose own walk was undecided): regions[k * lanes + i] is bound k (x_lo,
// x_hi, y_lo, y_hi) of region i, verdicts[i] its verdict. A region's verdict is the single
// walk's, except that it is 0 where the regions part ways at a jump of the program (a region
// that does not take the jump the others certainly take ends there, undecided) -- never
// decisive where the single walk is not.
constexpr int kNativeVerdictLanes = 16;
constexpr int kNativeRegionLanes = 4;
using NativeBlockVerdictsFunction = void (*)(const uint32_t* record, const float* state_values, const double* regions,
                                             uint8_t* verdicts);

// Whether native code can walk `program` (forward jumps only in its leading part); if not, why.
bool nativeVerdictSupports(const PixelProgram& program, std::string* why = nullptr);

// Adds to `module` the function `name` (a NativeVerdictFunction) for `program`; null with `error`
// set when it cannot.
llvm::Function* buildVerdictFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                     std::string& error);
// The same for the NativeBlockVerdictsFunction of `program` over `lanes` regions.
llvm::Function* buildBlockVerdictsFunction(llvm::Module& module, const std::string& name, const PixelProgram& program,
                                           int lanes, std::string& error);

}  // namespace pf
