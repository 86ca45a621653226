// Writing shaded fragments through the alpha test, blending, the logic op and the colour mask
// (fragment_ops.h), on the framebuffer's 8-bit values.
#include "raster/fragment_ops.h"

#include <algorithm>

#include "raster/shading.h"
#include "raster/simd_clones.h"

namespace pf {
namespace {

// a * b / 255 for 8-bit a and b, as llvmpipe's 8-bit normalized multiply computes it (one less
// than the rounded quotient for some pairs: 226 * 233 / 255 = 206.50 gives 206).
inline int mul8(int a, int b) {
  const int t = a * b;
  return (t + (t >> 8) + 128) >> 8;
}

// Factor `f` of channel k (0..3: R, G, B, A) as an 8-bit value, for each of n fragments with
// sources s[channel][i], destinations d[channel][i] and constant colour cc: the switch is
// outside the loops, so that each loop is plain integer arithmetic the compiler vectorizes.
void factors(GLenum f, int k, int n, const int (*s)[kTileSize], const int (*d)[kTileSize], const uint8_t cc[4],
             int* out) {
  auto fill = [&](int v) { std::fill_n(out, n, v); };
  switch (f) {
    case GL_ZERO: fill(0); return;
    case GL_ONE: fill(255); return;
    case GL_SRC_COLOR: std::copy_n(s[k], n, out); return;
    case GL_ONE_MINUS_SRC_COLOR: for (int i = 0; i < n; ++i) out[i] = 255 - s[k][i]; return;
    case GL_DST_COLOR: std::copy_n(d[k], n, out); return;
    case GL_ONE_MINUS_DST_COLOR: for (int i = 0; i < n; ++i) out[i] = 255 - d[k][i]; return;
    case GL_SRC_ALPHA: std::copy_n(s[3], n, out); return;
    case GL_ONE_MINUS_SRC_ALPHA: for (int i = 0; i < n; ++i) out[i] = 255 - s[3][i]; return;
    case GL_DST_ALPHA: std::copy_n(d[3], n, out); return;
    case GL_ONE_MINUS_DST_ALPHA: for (int i = 0; i < n; ++i) out[i] = 255 - d[3][i]; return;
    case GL_CONSTANT_COLOR: fill(cc[k]); return;
    case GL_ONE_MINUS_CONSTANT_COLOR: fill(255 - cc[k]); return;
    case GL_CONSTANT_ALPHA: fill(cc[3]); return;
    case GL_ONE_MINUS_CONSTANT_ALPHA: fill(255 - cc[3]); return;
    case GL_SRC_ALPHA_SATURATE:
      if (k == 3)
        fill(255);
      else
        for (int i = 0; i < n; ++i) out[i] = std::min(s[3][i], 255 - d[3][i]);
      return;
    default: fill(0); return;
  }
}

// The blend equation over n fragments' values of one channel: source and destination terms
// (already multiplied by their factors) or, for GL_MIN / GL_MAX, the unweighted values.
void combine(GLenum equation, int n, const int* s, const int* d, const int* s_term, const int* d_term, int* out) {
  switch (equation) {
    case GL_FUNC_SUBTRACT: for (int i = 0; i < n; ++i) out[i] = std::max(s_term[i] - d_term[i], 0); return;
    case GL_FUNC_REVERSE_SUBTRACT: for (int i = 0; i < n; ++i) out[i] = std::max(d_term[i] - s_term[i], 0); return;
    case GL_MIN: for (int i = 0; i < n; ++i) out[i] = std::min(s[i], d[i]); return;
    case GL_MAX: for (int i = 0; i < n; ++i) out[i] = std::max(s[i], d[i]); return;
    default: for (int i = 0; i < n; ++i) out[i] = std::min(s_term[i] + d_term[i], 255); return;  // GL_FUNC_ADD
  }
}

// GL's 16 logic ops (GL 1.5 table 4.2) on 8-bit source s and destination d.
int logic(GLenum mode, int s, int d) {
  int v;
  switch (mode) {
    case GL_CLEAR: v = 0; break;
    case GL_AND: v = s & d; break;
    case GL_AND_REVERSE: v = s & ~d; break;
    case GL_AND_INVERTED: v = ~s & d; break;
    case GL_NOOP: v = d; break;
    case GL_XOR: v = s ^ d; break;
    case GL_OR: v = s | d; break;
    case GL_NOR: v = ~(s | d); break;
    case GL_EQUIV: v = ~(s ^ d); break;
    case GL_INVERT: v = ~d; break;
    case GL_OR_REVERSE: v = s | ~d; break;
    case GL_COPY_INVERTED: v = ~s; break;
    case GL_OR_INVERTED: v = ~s | d; break;
    case GL_NAND: v = ~(s & d); break;
    case GL_SET: v = 0xff; break;
    default: v = s; break;  // GL_COPY
  }
  return v & 0xff;
}

}  // namespace

// A span at a time: each step a loop over the span's fragments (covered or not: the
// uncovered are computed and not written), so that the conversions and the blend's integer
// arithmetic vectorize (built for AVX-512, AVX2 and the baseline: simd_clones.h; the file
// without trapping math, as the shading pass); fragment by fragment it is the arithmetic GL
// and llvmpipe define.
PF_SIMD_CLONES void writeFragments(const FragmentOps& ops, uint8_t color_mask, const float (*c)[kTileSize], int skip, int n,
                    const uint32_t* covered, uint8_t* px, uint8_t* discarded) {
  n = std::min(n, kTileSize);
  uint8_t write[kTileSize];
  for (int i = 0; i < n; ++i) {
    discarded[i] = 0;
    write[i] = covered[i] != 0;
    if (write[i] && ops.alpha_test &&
        !compares(ops.alpha_func, static_cast<float>(toUnorm8Even(c[3][skip + i])), static_cast<float>(ops.alpha_ref))) {
      discarded[i] = 1;
      write[i] = 0;
    }
  }
  int s[4][kTileSize], d[4][kTileSize], out[4][kTileSize];
  for (int k = 0; k < 4; ++k) {
    const float* const ck = c[k] + skip;
    for (int i = 0; i < n; ++i) s[k][i] = toUnorm8Select(ck[i]);
    for (int i = 0; i < n; ++i) d[k][i] = px[4 * i + k];
  }
  if (ops.logic_op) {
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < n; ++i) out[k][i] = logic(ops.logic_mode, s[k][i], d[k][i]);
  } else if (ops.blend) {
    int fs[kTileSize], fd[kTileSize], s_term[kTileSize], d_term[kTileSize];
    for (int k = 0; k < 4; ++k) {
      factors(k < 3 ? ops.src_rgb : ops.src_alpha, k, n, s, d, ops.blend_color, fs);
      factors(k < 3 ? ops.dst_rgb : ops.dst_alpha, k, n, s, d, ops.blend_color, fd);
      for (int i = 0; i < n; ++i) {
        s_term[i] = mul8(s[k][i], fs[i]);
        d_term[i] = mul8(d[k][i], fd[i]);
      }
      combine(k < 3 ? ops.equation_rgb : ops.equation_alpha, n, s[k], d[k], s_term, d_term, out[k]);
    }
  } else {
    for (int k = 0; k < 4; ++k) std::copy_n(s[k], n, out[k]);
  }
  for (int i = 0; i < n; ++i) {
    if (!write[i]) continue;
    uint8_t* const p = px + 4 * i;
    for (int k = 0; k < 4; ++k)
      if (color_mask & (1u << k)) p[k] = static_cast<uint8_t>(out[k][i]);
  }
}

}  // namespace pf
