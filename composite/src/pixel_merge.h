// The per-pixel work of depth compositing, without MPI: merging one band of pixels into another
// by depth (PixelFlow's compositor, after Molnar et al. 1992 as cited in seed 003 section 1),
// and the run-length code of bands sent compressed. Pure functions, unit-tested on their own
// (tests/composite/pixel_merge_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace pf::composite {

// A band of pixels: RGBA colour as one 32-bit word per pixel, float window depth.
struct PixelSpan {
  uint32_t* color;
  float* depth;
  size_t count;
};

struct ConstPixelSpan {
  const uint32_t* color;
  const float* depth;
  size_t count;
};

// dst = the nearer of dst and src, per pixel. `src_wins_ties`: src's pixel also wins at equal
// depth (src came from lower ranks than dst). The comparisons are the depth test's (GL_LESS on
// the float values): a NaN never wins, and 0 equals -0.
void mergeByDepth(PixelSpan dst, ConstPixelSpan src, bool src_wins_ties);

// The run-length code: a sequence of records, each a 32-bit header and its pixels.
//   header with the top bit set: a run of (header & 0x7fffffff) identical pixels, then that
//     pixel's colour word and depth bits;
//   otherwise a literal of `header` pixels (header > 0), then their colours, then their depths.
// Pixels are identical when colour and depth bits are: a cleared region (clear colour, clear
// depth) is one run; decoding gives back every bit. The code is never longer than the raw
// band plus one header: where runs do not pay, everything is one literal.
size_t maxEncodedWords(size_t pixels);
// Writes the code of `src` to out[0, maxEncodedWords(src.count)); returns the words written.
size_t encodeRuns(ConstPixelSpan src, uint32_t* out);
// Merges a coded band into dst (as mergeByDepth would merge the decoded band). False, with dst
// possibly half merged, if the code is malformed: a record past the end, a zero count, or a
// pixel count other than dst.count.
bool mergeRuns(PixelSpan dst, const uint32_t* code, size_t words, bool src_wins_ties);
// Decodes a coded band into dst (a copy). False if malformed, as mergeRuns.
bool decodeRuns(PixelSpan dst, const uint32_t* code, size_t words);

}  // namespace pf::composite
