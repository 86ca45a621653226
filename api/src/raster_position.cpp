// The current raster position: glRasterPos (GL 1.5 section 2.13) and glWindowPos (GL 1.4
// section 2.13), their glGet values. glRasterPos takes its vertex through the modelview and
// projection as a vertex would be, culls it by the view volume and the enabled user clip planes
// (GL_CURRENT_RASTER_POSITION_VALID false, the rest kept, as Mesa), maps it to the window by the
// viewport and depth range, and takes the colour (lit when GL_LIGHTING is on), the texture
// coordinates (generated and transformed) and the eye distance a vertex there would have.
// glWindowPos sets the window position directly, with the current colour and texture
// coordinates. Both are recorded in display lists; neither is allowed inside glBegin / glEnd.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"
#include "api/src/raster_position.h"
#include "api/src/textures.h"
#include "raster/lighting.h"

namespace pf {
namespace {

glm::vec4 currentTexcoord(const PFcontextRec& ctx) {
  const ParamValue& t = ctx.param(ctx.texcoord_param);
  glm::vec4 c(0.0f, 0.0f, 0.0f, 1.0f);
  for (int k = 0; k < 4 && k < t.count; ++k) c[k] = static_cast<float>(t.v[k]);
  return c;
}

// The eye-space normal of the current normal: by the inverse transpose of the modelview's upper
// 3x3, rescaled and normalised as a vertex's (immediate_mode.cpp's startBegin).
glm::vec3 eyeNormal(const PFcontextRec& ctx) {
  const glm::mat3 inverse = glm::inverse(glm::mat3(ctx.modelview.top));
  glm::mat3 m = glm::transpose(inverse);
  if (ctx.lighting.rescale_normal && !ctx.lighting.normalize) {
    const float len = std::sqrt(inverse[0][2] * inverse[0][2] + inverse[1][2] * inverse[1][2] +
                                inverse[2][2] * inverse[2][2]);
    if (len > 0.0f) m /= len;
  }
  const ParamValue& nv = ctx.param(ctx.normal_param);
  glm::vec3 n = m * glm::vec3(static_cast<float>(nv.v[0]), static_cast<float>(nv.v[1]), static_cast<float>(nv.v[2]));
  if (ctx.lighting.normalize && glm::length(n) > 0.0f) n = glm::normalize(n);
  return n;
}

}  // namespace

namespace cmd {

void rasterPos(PFcontextRec& ctx, GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  if (!outsideBegin(ctx)) return;
  RasterPosState& r = ctx.raster;
  const glm::vec4 object(x, y, z, w);
  const glm::vec4 eye = ctx.modelview.top * object;
  const glm::vec4 clip = ctx.projection.top * eye;
  // The view volume (Mesa's viewclip_point: a point on its boundary is in), then the planes.
  if (clip.x > clip.w || clip.x < -clip.w || clip.y > clip.w || clip.y < -clip.w || clip.z > clip.w ||
      clip.z < -clip.w) {
    r.valid = false;
    return;
  }
  for (int p = 0; p < kMaxClipPlanes; ++p) {
    if (!ctx.clip.enabled[p]) continue;
    const float* e = ctx.clip.eye[p];
    if (e[0] * eye.x + e[1] * eye.y + e[2] * eye.z + e[3] * eye.w < 0.0f) {
      r.valid = false;
      return;
    }
  }
  const float d = clip.w == 0.0f ? 1.0f : 1.0f / clip.w;
  const glm::vec3 ndc(clip.x * d, clip.y * d, clip.z * d);
  const float sx = static_cast<float>(ctx.viewport[2]) / 2.0f, sy = static_cast<float>(ctx.viewport[3]) / 2.0f;
  const float sz = (ctx.depth_range[1] - ctx.depth_range[0]) / 2.0f;
  r.position = glm::vec4(ndc.x * sx + (static_cast<float>(ctx.viewport[0]) + sx),
                         ndc.y * sy + (static_cast<float>(ctx.viewport[1]) + sy), ndc.z * sz + (ctx.depth_range[0] + sz),
                         clip.w);
  r.distance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
  const glm::vec3 n = eyeNormal(ctx);
  if (ctx.lighting.enabled) {
    const glm::vec3 eye3 = eye.w != 0.0f ? glm::vec3(eye) / eye.w : glm::vec3(eye);
    r.color = LightingEquation(ctx.lighting).shade(ctx.lighting.material[0], eye3, n);
  } else {
    r.color = ctx.current_color;
  }
  r.texcoord = textureCoordinates(ctx.textures, ctx.texture.top, currentTexcoord(ctx), object, eye, n);
  r.valid = true;
}

void windowPos(PFcontextRec& ctx, GLfloat x, GLfloat y, GLfloat z) {
  if (!outsideBegin(ctx)) return;
  RasterPosState& r = ctx.raster;
  const float depth = std::clamp(z, 0.0f, 1.0f) * (ctx.depth_range[1] - ctx.depth_range[0]) + ctx.depth_range[0];
  r.position = glm::vec4(x, y, depth, 1.0f);
  r.valid = true;
  r.distance = 0.0f;
  for (int k = 0; k < 4; ++k) r.color[k] = std::clamp(ctx.current_color[k], 0.0f, 1.0f);
  r.texcoord = currentTexcoord(ctx);
}

}  // namespace cmd

bool rasterPosQuery(const PFcontextRec& ctx, GLenum pname, Query& q) {
  const RasterPosState& r = ctx.raster;
  switch (pname) {
    case GL_CURRENT_RASTER_POSITION: q.set({r.position.x, r.position.y, r.position.z, r.position.w}); return true;
    case GL_CURRENT_RASTER_POSITION_VALID: q.set({r.valid ? 1.0 : 0.0}); return true;
    case GL_CURRENT_RASTER_COLOR: q.set({r.color.r, r.color.g, r.color.b, r.color.a}, true); return true;
    case GL_CURRENT_RASTER_TEXTURE_COORDS: q.set({r.texcoord.x, r.texcoord.y, r.texcoord.z, r.texcoord.w}); return true;
    case GL_CURRENT_RASTER_DISTANCE: q.set({r.distance}); return true;
    case GL_ZOOM_X: q.set({ctx.pixel_mode.zoom_x}); return true;  // (glPixelZoom: draw_pixels.cpp)
    case GL_ZOOM_Y: q.set({ctx.pixel_mode.zoom_y}); return true;
    default: return false;
  }
}

}  // namespace pf

namespace {

using pf::dispatch;
using pf::GlOp;

template <class T>
void rasterPos(T x, T y, T z, T w) {
  dispatch<GlOp::RasterPos>(static_cast<GLfloat>(x), static_cast<GLfloat>(y), static_cast<GLfloat>(z),
                            static_cast<GLfloat>(w));
}

template <class T>
void windowPos(T x, T y, T z) {
  dispatch<GlOp::WindowPos>(static_cast<GLfloat>(x), static_cast<GLfloat>(y), static_cast<GLfloat>(z));
}

}  // namespace

// glRasterPos2, 3 and 4 and glWindowPos2 and 3 with their vector forms for a component type
// (z = 0, w = 1 where missing; a NULL vector is ignored).
#define PF_RASTER_FORMS(T, s)                                                                    \
  void pfglRasterPos2##s(T x, T y) { rasterPos<T>(x, y, 0, 1); }                                 \
  void pfglRasterPos3##s(T x, T y, T z) { rasterPos<T>(x, y, z, 1); }                            \
  void pfglRasterPos4##s(T x, T y, T z, T w) { rasterPos<T>(x, y, z, w); }                       \
  void pfglRasterPos2##s##v(const T* v) {                                                        \
    if (v) rasterPos<T>(v[0], v[1], 0, 1);                                                       \
  }                                                                                              \
  void pfglRasterPos3##s##v(const T* v) {                                                        \
    if (v) rasterPos<T>(v[0], v[1], v[2], 1);                                                    \
  }                                                                                              \
  void pfglRasterPos4##s##v(const T* v) {                                                        \
    if (v) rasterPos<T>(v[0], v[1], v[2], v[3]);                                                 \
  }                                                                                              \
  void pfglWindowPos2##s(T x, T y) { windowPos<T>(x, y, 0); }                                    \
  void pfglWindowPos3##s(T x, T y, T z) { windowPos<T>(x, y, z); }                               \
  void pfglWindowPos2##s##v(const T* v) {                                                        \
    if (v) windowPos<T>(v[0], v[1], 0);                                                          \
  }                                                                                              \
  void pfglWindowPos3##s##v(const T* v) {                                                        \
    if (v) windowPos<T>(v[0], v[1], v[2]);                                                       \
  }

PF_RASTER_FORMS(GLshort, s)
PF_RASTER_FORMS(GLint, i)
PF_RASTER_FORMS(GLfloat, f)
PF_RASTER_FORMS(GLdouble, d)
#undef PF_RASTER_FORMS
