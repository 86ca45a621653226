// Hierarchical rejection and acceptance of pixel blocks, for any primitive (issue [raster]): before a pixel
// program runs over an 8x8 block, its leading part is evaluated once in interval arithmetic over
// the whole block -- X and Y as the ranges of the block's pixel centres, the instance's uniform
// values as points -- and if a `return` (Op::Retire) is certainly reached by every pixel, the
// block is skipped without running a lane. For a triangle the three edge tests are affine in X
// and Y, so the intervals are exact up to rounding and the test is llvmpipe's block-versus-edge
// test; a sphere's or a quadric's discriminant test rejects blocks off its silhouette. No
// primitive is special-cased: whatever the program computes before its first loop, depth test or
// field search is used. The same evaluation also accepts: where it proves that none of the
// Retires deciding coverage runs for any pixel, the blocks run PixelProgram::covered, the program
// without those tests (compiler/covered_program.h) -- llvmpipe's fully covered blocks, for any
// primitive.
//
// Sound by construction: every interval is widened after each operation by more than float
// rounding can move a lane's value (2^-22 relative, plus the smallest normal absolute), NaN is
// tracked (a comparison that may see NaN is never "certainly true"), and anything the evaluator
// does not model -- Z, P, N, loops, field searches, interpolator_data -- is "unknown", which
// never rejects. So a rejected block is one where the program would have retired every lane.
#pragma once

#include <cstdint>
#include <vector>

#include "compiler/isa.h"
#include "raster/limits.h"
#include "raster/raster_state.h"

namespace pf {

// The side of the square regions tested at once (a multiple of the block size, dividing the
// tile size): a region rejected skips all its blocks; one that is not runs them as usual.
constexpr int kRejectionRegion = 32;
static_assert(kTileSize % kRejectionRegion == 0 && kRejectionRegion % kBlockSize == 0);

// What the interval evaluation proves of a region: nothing; that the program retires every pixel
// (skip the region's blocks); or that none of its coverage Retires (those up to
// PixelProgram::last_coverage_retire) runs for any pixel (run PixelProgram::covered instead).
enum class RegionVerdict : uint8_t { Unknown, Rejected, Accepted };

class BlockRejection {
 public:
  // The verdict for `program` (with the instance's uniform `record`) over the pixels whose
  // centre is (x + 0.5, y + 0.5) for x0 <= x < x1, y0 <= y < y1. Only worth asking of programs
  // with PixelProgram::last_early_retire >= 0.
  RegionVerdict verdict(const PixelProgram& program, const uint32_t* record, const RasterState& state, int x0, int y0,
                        int x1, int y1);
  bool rejects(const PixelProgram& program, const uint32_t* record, const RasterState& state, int x0, int y0,
               int x1, int y1) {
    return verdict(program, record, state, x0, y0, x1, y1) == RegionVerdict::Rejected;
  }

  // A value's range over the block's lanes. Bools are [0, 0], [1, 1] or [0, 1].
  struct Range {
    double lo, hi;
    bool maybe_nan;
  };

 private:
  std::vector<Range> regs_;
};

}  // namespace pf
