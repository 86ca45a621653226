// Drawing pixel rectangles (GL 1.5 sections 3.6.4, 3.7, 4.3.3): glBitmap, glDrawPixels and
// glCopyPixels hand their fragments to the renderer as instances of the built-in primitive
// pixel_rectangle (primitives/pixel_rectangle.pfl) -- one a run of equal fragments in a row --
// so that the depth test, stencil, alpha test, blending, fog and the rest apply as to any
// primitive's fragments, in the JIT and the interpreter alike.
#pragma once

#include <glm/glm.hpp>

#include <GL/gl.h>

#include "api/src/pixel_maps.h"

struct PFcontextRec;

namespace pf {

// What every fragment of a pixel rectangle carries besides its colour: the raster position's
// texture coordinates (as glRasterPos computed them) and fog coordinate (its distance). While a
// PixelRectangles draws, the context's pixel_fragment points at it and the shading channels of
// its sequence points come from here (shading_channels.cpp) instead of the current values.
struct PixelFragment {
  glm::vec4 color{1.0f};
  glm::vec4 texcoord{0.0f, 0.0f, 0.0f, 1.0f};
  float fog = 0.0f;
};

// One draw of pixel rectangles, as one glBegin / glEnd of pixel_rectangle: constructed, it
// begins (the rectangles are not confined to the viewport, nor clipped by the user clip planes,
// as GL's are not); add() gives one rectangle; destroyed, it ends the draw -- the rectangles go
// to the renderer in order -- and puts back what it changed.
class PixelRectangles {
 public:
  PixelRectangles(PFcontextRec& ctx, float z);
  ~PixelRectangles();
  PixelRectangles(const PixelRectangles&) = delete;
  PixelRectangles& operator=(const PixelRectangles&) = delete;

  // The fragments whose centres lie in [x0, x1) x [y0, y1), of colour `color` (clamped to
  // [0, 1] as GL clamps a fragment's colour).
  void add(float x0, float y0, float x1, float y1, const glm::vec4& color) { add(x0, y0, x1, y1, color, z_); }
  // The same at depth `z` (glDrawPixels' depth images).
  void add(float x0, float y0, float x1, float y1, const glm::vec4& color, float z);
  bool drawing() const { return drawing_; }

 private:
  PFcontextRec& ctx_;
  float z_;
  bool drawing_ = false;
  bool changed_ = false;  // the context's viewport, clip planes and shading model changed
  PixelFragment fragment_;
  int viewport_[4];
  bool clip_enabled_[8];
  GLenum shade_model_;
  GLuint rect_param_ = 0;
  double saved_rect_[16];
  int saved_rect_count_ = 0;
};

// GL_PIXEL_MODE_BIT's state: glPixelZoom's factors (GL 1.5 section 3.6.4) and glPixelTransfer's
// modes (section 3.6.5; the pixel maps are in no attribute group).
struct PixelModeState {
  float zoom_x = 1.0f, zoom_y = 1.0f;
  PixelTransferModes transfer;
};

}  // namespace pf
