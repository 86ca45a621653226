// Fog (GL 1.5 section 3.10) and user clip planes (section 2.11) as a context keeps them, what
// glGet reads of them, and what a draw takes of them: fog as the shading pass's FogParams
// (raster/fog.h), the enabled clip planes as window-space planes its depth test applies
// (RasterState::clip_planes). Commands and queries: fog_clip_commands.cpp.
#pragma once

#include <GL/gl.h>

#include "api/src/query.h"
#include "raster/fog.h"
#include "raster/raster_state.h"

struct PFcontextRec;

namespace pf {

// GL_MAX_CLIP_PLANES: OSMesa's (llvmpipe's), so that a program using planes 6 and 7 there
// runs here too.
constexpr int kMaxClipPlanes = RasterState::kMaxClipPlanes;

// glFog's state (GL 1.5 table 6.9), OSMesa's initial values.
struct FogState {
  bool enabled = false;
  GLenum mode = GL_EXP;
  float density = 1.0f, start = 0.0f, end = 1.0f;
  float index = 0.0f;             // kept and read back (no colour-index buffers)
  float color[4] = {0, 0, 0, 0};  // clamped to [0, 1] when set, as Mesa keeps it for RGBA8
};

// glClipPlane's state (GL 1.5 table 6.7): each plane in eye coordinates (the equation given
// times the inverse of the modelview of its call) and whether it is enabled.
struct ClipPlaneState {
  bool enabled[kMaxClipPlanes] = {};
  float eye[kMaxClipPlanes][4] = {};
};

// The glGet* values of fog and the clip planes (GL_FOG, GL_FOG_*, GL_CLIP_PLANEi,
// GL_MAX_CLIP_PLANES); false for another pname.
bool fogClipQuery(const PFcontextRec& ctx, GLenum pname, Query& q);

// What the shading pass applies for fog (off when fog is disabled).
FogParams fogParams(const FogState& fog);

// Fills s.clip_planes / s.clip_plane_count with the enabled planes as window-space planes: the
// eye-space plane through the inverse projection to clip space, then through the viewport and
// depth range to window (x, y, depth). Needs s's viewport and depth-range fields set.
void windowClipPlanes(const ClipPlaneState& planes, const float projection[16], RasterState& s);

}  // namespace pf
