// The current raster position (GL 1.5 section 2.13, glWindowPos from GL 1.4 section 2.13) as a
// context keeps it: where glBitmap and glDrawPixels put their rectangles and what their fragments
// take (colour, texture coordinates, depth, fog distance). Commands and queries:
// raster_position.cpp.
#pragma once

#include <glm/glm.hpp>

#include <GL/gl.h>

#include "api/src/query.h"

struct PFcontextRec;

namespace pf {

// GL 1.5 table 6.5's raster position state, OSMesa's initial values. `position` is the window
// x, y, depth and the clip w of the glRasterPos that set it (1 for glWindowPos), as Mesa keeps
// it; colour and texture coordinates as glRasterPos computed them.
struct RasterPosState {
  glm::vec4 position{0.0f, 0.0f, 0.0f, 1.0f};
  bool valid = true;
  glm::vec4 color{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 texcoord{0.0f, 0.0f, 0.0f, 1.0f};
  float distance = 0.0f;  // the eye-space distance glRasterPos measured (fog's coordinate)
};

// The glGet* values of the raster position (GL_CURRENT_RASTER_*) and of glPixelZoom (GL_ZOOM_X,
// GL_ZOOM_Y); false for another pname.
bool rasterPosQuery(const PFcontextRec& ctx, GLenum pname, Query& q);

}  // namespace pf
