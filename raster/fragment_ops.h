// The per-fragment operations GL applies between a pixel's colour and the framebuffer (GL 1.5
// section 4.1): the scissor test, the alpha test, the stencil test (raster/stencil.h), blending
// and the logic op, as a draw's
// snapshot (FragmentOps, part of its RasterState) and the code that writes shaded fragments
// through them (writeFragments).
//
// The scissor test only narrows the pixels an instance may touch (the renderer cuts its bound,
// and a clear's rectangle). The others need the fragment's colour, which deferred shading
// knows only after every instance of the tile has run, or change the stencil buffer fragment
// by fragment: a draw using any of them is *ordered*
// (FragmentOps::ordered) -- its pixels are shaded as soon as it has run, in submission order
// within the tile, and written through writeFragments (docs/architecture.md, "Ordered
// fragments").
//
// The framebuffer is RGBA8, and the alpha test, blending and the logic op work on its 8-bit
// values as llvmpipe does: the fragment's colour rounded to 8 bits first (as the deferred pass
// writes it: toUnorm8, a tie up), each product of a value and a factor as llvmpipe's 8-bit
// multiply computes it (a * b / 255 within one step: the same bytes as llvmpipe for every pair
// of factors and every equation), sums and differences saturated. The constants -- the blend
// colour, the alpha test's reference -- and the alpha the test compares are rounded as llvmpipe
// rounds them, a tie to even (toUnorm8Even), so that a test on them decides as llvmpipe does.
#pragma once

#include <cmath>
#include <cstdint>

#include <GL/gl.h>

#include "raster/limits.h"
#include "raster/stencil.h"

namespace pf {

struct FragmentOps {
  // The scissor test: pixels [scissor_x0, scissor_x1) x [scissor_y0, scissor_y1) only.
  bool scissor = false;
  int scissor_x0 = 0, scissor_y0 = 0, scissor_x1 = 0, scissor_y1 = 0;
  // The alpha test: the fragment's alpha against alpha_ref, both as 8-bit values (toUnorm8Even).
  bool alpha_test = false;
  CompareFunc alpha_func = CompareFunc::Always;
  uint8_t alpha_ref = 0;
  // Blending: GL's factor and equation enums, RGB and alpha apart (glBlendFuncSeparate); the
  // constant colour (glBlendColor) as 8-bit values (toUnorm8Even).
  bool blend = false;
  GLenum src_rgb = GL_ONE, dst_rgb = GL_ZERO, src_alpha = GL_ONE, dst_alpha = GL_ZERO;
  GLenum equation_rgb = GL_FUNC_ADD, equation_alpha = GL_FUNC_ADD;
  uint8_t blend_color[4] = {0, 0, 0, 0};
  // The logic op (GL_COLOR_LOGIC_OP): GL_CLEAR ... GL_SET; it replaces blending when on.
  bool logic_op = false;
  GLenum logic_mode = GL_COPY;
  StencilOps stencil;

  // Whether a draw's pixels must be shaded and written in submission order (not deferred).
  bool ordered() const { return alpha_test || blend || logic_op || stencil.test; }
  bool operator==(const FragmentOps&) const = default;
};

// Float colour component -> 8 bits: clamped to [0, 1] (NaN to 0), scaled, rounded to nearest
// with a tie to even (as llvmpipe converts to 8 bits).
inline uint8_t toUnorm8Even(float c) {
  if (!(c > 0.0f)) return 0;
  if (c >= 1.0f) return 255;
  return static_cast<uint8_t>(std::nearbyint(c * 255.0f));
}

// Writes `n` fragments of a row through `ops`: fragment i has colour c[k][skip + i] (floats,
// any range) and goes to the RGBA8 pixel px + 4 * i, if covered[i] != 0; only the channels
// in `color_mask` (bit k: channel k) change. A fragment the alpha test discards is not
// written and gets discarded[i] = 1 (others 0).
void writeFragments(const FragmentOps& ops, uint8_t color_mask, const float (*c)[kTileSize], int skip, int n,
                    const uint32_t* covered, uint8_t* px, uint8_t* discarded);

}  // namespace pf
