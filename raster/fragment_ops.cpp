// Writing shaded fragments through the alpha test, blending, the logic op and the colour mask
// (fragment_ops.h), on the framebuffer's 8-bit values.
#include "raster/fragment_ops.h"

#include <algorithm>

#include "raster/shading.h"

namespace pf {
namespace {

// a * b / 255 for 8-bit a and b, as llvmpipe's 8-bit normalized multiply computes it (one less
// than the rounded quotient for some pairs: 226 * 233 / 255 = 206.50 gives 206).
inline int mul8(int a, int b) {
  const int t = a * b;
  return (t + (t >> 8) + 128) >> 8;
}

// Factor `f` of channel k (0..3: R, G, B, A) as an 8-bit value, for source s, destination d and
// constant colour cc.
int factor(GLenum f, int k, const int s[4], const int d[4], const uint8_t cc[4]) {
  switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[k];
    case GL_ONE_MINUS_SRC_COLOR: return 255 - s[k];
    case GL_DST_COLOR: return d[k];
    case GL_ONE_MINUS_DST_COLOR: return 255 - d[k];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255 - d[3];
    case GL_CONSTANT_COLOR: return cc[k];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 255 - cc[k];
    case GL_CONSTANT_ALPHA: return cc[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 255 - cc[3];
    case GL_SRC_ALPHA_SATURATE: return k == 3 ? 255 : std::min(s[3], 255 - d[3]);
    default: return 0;
  }
}

// The blend equation over one channel's source and destination terms (already multiplied by
// their factors) or, for GL_MIN / GL_MAX, the unweighted values.
int combine(GLenum equation, int s, int d, int s_term, int d_term) {
  switch (equation) {
    case GL_FUNC_SUBTRACT: return std::max(s_term - d_term, 0);
    case GL_FUNC_REVERSE_SUBTRACT: return std::max(d_term - s_term, 0);
    case GL_MIN: return std::min(s, d);
    case GL_MAX: return std::max(s, d);
    default: return std::min(s_term + d_term, 255);  // GL_FUNC_ADD
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

void writeFragments(const FragmentOps& ops, uint8_t color_mask, const float (*c)[kTileSize], int skip, int n,
                    const uint32_t* covered, uint8_t* px, uint8_t* discarded) {
  for (int i = 0; i < n; ++i) {
    discarded[i] = 0;
    if (covered[i] == 0) continue;
    if (ops.alpha_test &&
        !compares(ops.alpha_func, static_cast<float>(toUnorm8Even(c[3][skip + i])), static_cast<float>(ops.alpha_ref))) {
      discarded[i] = 1;
      continue;
    }
    int s[4], d[4], out[4];
    uint8_t* const p = px + 4 * i;
    for (int k = 0; k < 4; ++k) {
      s[k] = toUnorm8(c[k][skip + i]);
      d[k] = p[k];
    }
    if (ops.logic_op) {
      for (int k = 0; k < 4; ++k) out[k] = logic(ops.logic_mode, s[k], d[k]);
    } else if (ops.blend) {
      for (int k = 0; k < 4; ++k) {
        const GLenum sf = k < 3 ? ops.src_rgb : ops.src_alpha, df = k < 3 ? ops.dst_rgb : ops.dst_alpha;
        const int s_term = mul8(s[k], factor(sf, k, s, d, ops.blend_color));
        const int d_term = mul8(d[k], factor(df, k, s, d, ops.blend_color));
        out[k] = combine(k < 3 ? ops.equation_rgb : ops.equation_alpha, s[k], d[k], s_term, d_term);
      }
    } else {
      for (int k = 0; k < 4; ++k) out[k] = s[k];
    }
    for (int k = 0; k < 4; ++k)
      if (color_mask & (1u << k)) p[k] = static_cast<uint8_t>(out[k]);
  }
}

}  // namespace pf
