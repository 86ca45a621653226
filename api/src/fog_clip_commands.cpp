// Fog (GL 1.5 section 3.10) and user clip planes (section 2.11): glFog*, glClipPlane and
// glGetClipPlane with OSMesa's errors and conversions, their glGet values, and what a draw takes
// of them (fog_clip.h). Their enables are in gl_commands.cpp, their attribute groups in
// attrib_stack.cpp; the fog coordinate is a shading channel (shading_channels.cpp).
#include <algorithm>
#include <climits>
#include <cmath>

#include <glm/glm.hpp>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/fog_clip.h"
#include "api/src/normalized.h"

namespace pf {
namespace {

// How many values glFogfv / glFogiv read for `pname`: 4 for the colour, else 1.
int fogValues(GLenum pname) { return pname == GL_FOG_COLOR ? 4 : 1; }

bool fogPname(GLenum pname) {
  switch (pname) {
    case GL_FOG_MODE: case GL_FOG_DENSITY: case GL_FOG_START: case GL_FOG_END: case GL_FOG_INDEX:
    case GL_FOG_COLOR: case GL_FOG_COORD_SRC:
      return true;
    default:
      return false;
  }
}

// A float given for an enum, as Mesa reads it: truncated to an integer (NaN or out of range: no
// enum, 0).
GLenum enumOf(float v) {
  if (!(v >= static_cast<float>(INT_MIN) && v < 2147483648.0f)) return 0;
  return static_cast<GLenum>(static_cast<GLint>(v));
}

Values4f scalarValue(float v) { return valuesOf<GLfloat, 4>(&v, 1, 1); }

// The plane index of GL_CLIP_PLANEi, or -1 (GL_INVALID_ENUM).
int planeIndex(GLenum plane) {
  return plane >= GL_CLIP_PLANE0 && plane < GL_CLIP_PLANE0 + static_cast<GLenum>(kMaxClipPlanes)
             ? static_cast<int>(plane - GL_CLIP_PLANE0) : -1;
}

}  // namespace

namespace cmd {

// `values.count`: 1 for glFogf / glFogi, 4 or 1 for the vector forms (0: a NULL pointer, ignored
// after the enum check). As Mesa, the scalar forms take any pname -- glFogf(GL_FOG_COLOR, r) sets
// the colour (r, 0, 0, 0).
void fog(PFcontextRec& ctx, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  if (!fogPname(pname)) return ctx.setError(GL_INVALID_ENUM);
  const float* v = values.pointer();
  if (!v) return;
  FogState& f = ctx.fog;
  switch (pname) {
    case GL_FOG_MODE: {
      const GLenum mode = enumOf(v[0]);
      if (mode != GL_LINEAR && mode != GL_EXP && mode != GL_EXP2) return ctx.setError(GL_INVALID_ENUM);
      f.mode = mode;
      return;
    }
    case GL_FOG_DENSITY:
      if (v[0] < 0.0f) return ctx.setError(GL_INVALID_VALUE);  // (NaN is taken, as Mesa)
      f.density = v[0];
      return;
    case GL_FOG_START: f.start = v[0]; return;
    case GL_FOG_END: f.end = v[0]; return;
    case GL_FOG_INDEX: f.index = v[0]; return;
    case GL_FOG_COLOR:
      for (int k = 0; k < 4; ++k) f.color[k] = std::clamp(v[k], 0.0f, 1.0f);
      return;
    default:
      // GL_FOG_COORD_SRC: primflow has no fog coordinates of its own (glFogCoord, GL 1.4): the
      // fragment's depth, the one source it has, is taken; GL_FOG_COORD is not.
      if (enumOf(v[0]) != GL_FRAGMENT_DEPTH) ctx.setError(GL_INVALID_ENUM);
      return;
  }
}

void clipPlane(PFcontextRec& ctx, GLenum plane, Values4d equation) {
  if (!outsideBegin(ctx)) return;
  const int p = planeIndex(plane);
  if (p < 0) return ctx.setError(GL_INVALID_ENUM);
  const double* e = equation.pointer();
  if (!e) return;
  // Into eye coordinates: the equation (in float, as GL keeps it) as a row vector times the
  // inverse of the current modelview (computed in double, rounded once).
  const glm::dvec4 given(static_cast<float>(e[0]), static_cast<float>(e[1]), static_cast<float>(e[2]),
                         static_cast<float>(e[3]));
  const glm::dmat4 modelview(ctx.modelview.top);
  const glm::dmat4 inverse = glm::determinant(modelview) != 0.0 ? glm::inverse(modelview) : glm::dmat4(1.0);
  const glm::dvec4 eye = given * inverse;
  for (int k = 0; k < 4; ++k) ctx.clip.eye[p][k] = static_cast<float>(eye[k]);
}

}  // namespace cmd

bool fogClipQuery(const PFcontextRec& ctx, GLenum pname, Query& q) {
  const FogState& f = ctx.fog;
  switch (pname) {
    case GL_FOG: q.set({f.enabled ? 1.0 : 0.0}); return true;
    case GL_FOG_MODE: q.set({double(f.mode)}); return true;
    case GL_FOG_DENSITY: q.set({f.density}); return true;
    case GL_FOG_START: q.set({f.start}); return true;
    case GL_FOG_END: q.set({f.end}); return true;
    case GL_FOG_INDEX: q.set({f.index}); return true;
    case GL_FOG_COLOR: q.set({f.color[0], f.color[1], f.color[2], f.color[3]}, true); return true;
    case GL_MAX_CLIP_PLANES: q.set({double(kMaxClipPlanes)}); return true;
    default: {
      const int p = planeIndex(pname);
      if (p < 0) return false;
      q.set({ctx.clip.enabled[p] ? 1.0 : 0.0});
      return true;
    }
  }
}

FogParams fogParams(const FogState& fog) {
  FogParams p;
  p.on = fog.enabled;
  // Mesa's STATE_FOG_PARAMS_OPTIMIZED, in float as Mesa computes them.
  switch (fog.mode) {
    case GL_LINEAR:
      p.mode = FogMode::Linear;
      p.scale = fog.end == fog.start ? 1.0f : -1.0f / (fog.end - fog.start);
      p.offset = fog.end * -p.scale;
      break;
    case GL_EXP:
      p.mode = FogMode::Exp;
      p.scale = static_cast<float>(fog.density * 1.4426950408889634);  // 1 / ln 2
      break;
    default:
      p.mode = FogMode::Exp2;
      p.scale = static_cast<float>(fog.density * 1.2011224087864498);  // 1 / sqrt(ln 2)
      break;
  }
  for (int k = 0; k < 3; ++k) p.color[k] = fog.color[k];
  return p;
}

void windowClipPlanes(const ClipPlaneState& planes, const float projection[16], RasterState& s) {
  s.clip_plane_count = 0;
  glm::dmat4 proj;
  for (int k = 0; k < 16; ++k) proj[k / 4][k % 4] = projection[k];
  // (A singular projection draws nothing GL can clip; the identity keeps the planes finite.)
  const glm::dmat4 inverse = glm::determinant(proj) != 0.0 ? glm::inverse(proj) : glm::dmat4(1.0);
  for (int p = 0; p < kMaxClipPlanes; ++p) {
    if (!planes.enabled[p]) continue;
    // In clip coordinates (the eye plane times the inverse projection, as Mesa's
    // _ClipUserPlane), where dot(plane, clip) = w dot(plane, (ndc, 1)) and w > 0 at every
    // fragment drawn: the sign is that of the plane over normalised device coordinates, which
    // are affine in window x, y and depth.
    const glm::dvec4 eye(planes.eye[p][0], planes.eye[p][1], planes.eye[p][2], planes.eye[p][3]);
    const glm::dvec4 c = eye * inverse;
    const double scale[3] = {s.vp_scale_x, s.vp_scale_y, s.depth_scale};
    const double offset[3] = {s.vp_offset_x, s.vp_offset_y, s.depth_offset};
    double w[4] = {0, 0, 0, c[3]};
    for (int k = 0; k < 3; ++k) {
      if (scale[k] == 0.0) continue;  // (an empty viewport, or depth range n == f: ndc z taken as 0)
      w[k] = c[k] / scale[k];
      w[3] -= c[k] * offset[k] / scale[k];
    }
    double largest = 0.0;
    for (double v : w) largest = std::max(largest, std::fabs(v));
    float* out = s.clip_planes[s.clip_plane_count++];
    for (int k = 0; k < 4; ++k) out[k] = static_cast<float>(largest > 0.0 && std::isfinite(largest) ? w[k] / largest : w[k]);
  }
}

}  // namespace pf

extern "C" {

void pfglFogf(GLenum pname, GLfloat param) { pf::dispatch<pf::GlOp::Fog>(pname, pf::scalarValue(param)); }
void pfglFogi(GLenum pname, GLint param) {
  pf::dispatch<pf::GlOp::Fog>(pname, pf::scalarValue(static_cast<GLfloat>(param)));
}
void pfglFogfv(GLenum pname, const GLfloat* params) {
  pf::dispatch<pf::GlOp::Fog>(pname, pf::valuesOf<GLfloat, 4>(params, pf::fogValues(pname), 4));
}
// The colour's integers as GL maps them to [-1, 1] (GL 1.5 table 2.9); the others converted.
void pfglFogiv(GLenum pname, const GLint* params) {
  pf::Values4f v{};
  if (params) {
    for (int k = 0; k < pf::fogValues(pname); ++k)
      v.v[k] = pname == GL_FOG_COLOR ? static_cast<GLfloat>(pf::normalized(params[k])) : static_cast<GLfloat>(params[k]);
    v.count = 4;
  }
  pf::dispatch<pf::GlOp::Fog>(pname, v);
}

void pfglClipPlane(GLenum plane, const GLdouble* equation) {
  pf::dispatch<pf::GlOp::ClipPlane>(plane, pf::valuesOf<GLdouble, 4>(equation, 4, 4));
}

void pfglGetClipPlane(GLenum plane, GLdouble* equation) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  const int p = pf::planeIndex(plane);
  if (p < 0) return ctx->setError(GL_INVALID_ENUM);
  if (!equation) return;
  for (int k = 0; k < 4; ++k) equation[k] = ctx->clip.eye[p][k];
}

}  // extern "C"
