// Texture objects and the texturing state around them (GL 1.5 sections 3.8.4-3.8.13, 2.11.4):
// glGen/Bind/Delete/IsTexture, priorities and residency, glTexParameter, glTexEnv, glTexGen and
// their queries, the snapshot a draw samples (TextureState::current) and the texture coordinates
// of a vertex (textureCoordinates). Images: texture_images.cpp.
#include <algorithm>
#include <cmath>
#include <new>
#include <type_traits>

#include <glm/gtc/matrix_inverse.hpp>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace pf {

TextureObject& TextureState::bound(GLenum target) {
  const bool two = target == GL_TEXTURE_2D;
  const GLuint name = two ? a.binding_2d : a.binding_1d;
  if (name != 0) {
    auto it = objects.find(name);
    if (it != objects.end()) return it->second;
  }
  return two ? default_2d : default_1d;
}

TextureObject* TextureState::object(GLuint name) {
  auto it = objects.find(name);
  return it == objects.end() ? nullptr : &it->second;
}

namespace {

bool mipmapFilter(GLenum f) { return f != GL_NEAREST && f != GL_LINEAR; }

// The snapshot of `t` for a draw, or null when it is not complete (GL 1.5 section 3.8.10:
// texturing is then off for the draw).
std::shared_ptr<const TextureUnit> snapshot(const TextureObject& t, int dims, const TextureAttribs& a) {
  const int base = t.base_level;
  if (base < 0 || base >= kMaxTextureLevels) return nullptr;
  const TextureImage& b = t.images[base];
  if (!b.level || b.width <= 0 || b.height <= 0) return nullptr;
  auto unit = std::make_shared<TextureUnit>();
  unit->dims = dims;
  unit->base = b.base;
  unit->levels.push_back(b.level);
  if (mipmapFilter(t.min_filter)) {
    // Every level from the base to the 1 x 1 one (or GL_TEXTURE_MAX_LEVEL), each half the one
    // before, of the base's internal format.
    int w = b.width, h = b.height;
    for (int level = base + 1; level <= std::min(t.max_level, kMaxTextureLevels - 1) && (w > 1 || h > 1); ++level) {
      w = std::max(1, w / 2);
      h = std::max(1, h / 2);
      const TextureImage& m = t.images[level];
      if (!m.level || m.width != w || m.height != h || m.internal_format != b.internal_format) return nullptr;
      unit->levels.push_back(m.level);
    }
    if ((w > 1 || h > 1) && t.max_level >= kMaxTextureLevels - 1) return nullptr;
  }
  unit->min_filter = t.min_filter;
  unit->mag_filter = t.mag_filter;
  unit->wrap_s = t.wrap_s;
  unit->wrap_t = t.wrap_t;
  std::copy(t.border, t.border + 4, unit->border);
  unit->min_lod = t.min_lod;
  unit->max_lod = t.max_lod;
  unit->env_mode = a.env_mode;
  std::copy(a.env_color, a.env_color + 4, unit->env_color);
  return unit;
}

bool isTextureTarget(GLenum target) { return target == GL_TEXTURE_1D || target == GL_TEXTURE_2D; }

float clamp01(float v) { return v > 0.0f ? std::min(v, 1.0f) : 0.0f; }

// glTexParameter's pnames that take one value, and those that take four.
bool scalarTexParameter(GLenum pname) {
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: case GL_TEXTURE_MAG_FILTER: case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_PRIORITY: case GL_TEXTURE_MIN_LOD: case GL_TEXTURE_MAX_LOD: case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL:
      return true;
    default: return false;
  }
}

GLint texGenIndex(GLenum coord) {
  switch (coord) {
    case GL_S: return 0;
    case GL_T: return 1;
    case GL_R: return 2;
    case GL_Q: return 3;
    default: return -1;
  }
}

// A query's values into float or integer results (colours as normalised integers).
template <class T>
void put(T* out, const float* v, int n, bool color) {
  if (!out) return;
  for (int i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<T, GLint>) {
      const double d = color ? std::trunc(static_cast<double>(v[i]) * 2147483647.0) : std::nearbyint(v[i]);
      out[i] = static_cast<GLint>(std::clamp(d, -2147483648.0, 2147483647.0));
    } else {
      out[i] = v[i];
    }
  }
}

template <class T>
void getTexParameter(GLenum target, GLenum pname, T* params) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (!isTextureTarget(target)) return ctx->setError(GL_INVALID_ENUM);
  const TextureObject& t = ctx->textures.bound(target);
  float v[4] = {0, 0, 0, 0};
  int n = 1;
  bool color = false;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER: v[0] = static_cast<float>(t.min_filter); break;
    case GL_TEXTURE_MAG_FILTER: v[0] = static_cast<float>(t.mag_filter); break;
    case GL_TEXTURE_WRAP_S: v[0] = static_cast<float>(t.wrap_s); break;
    case GL_TEXTURE_WRAP_T: v[0] = static_cast<float>(t.wrap_t); break;
    case GL_TEXTURE_BORDER_COLOR: std::copy(t.border, t.border + 4, v), n = 4, color = true; break;
    case GL_TEXTURE_PRIORITY: v[0] = t.priority; break;
    case GL_TEXTURE_RESIDENT: v[0] = 1.0f; break;
    case GL_TEXTURE_MIN_LOD: v[0] = t.min_lod; break;
    case GL_TEXTURE_MAX_LOD: v[0] = t.max_lod; break;
    case GL_TEXTURE_BASE_LEVEL: v[0] = static_cast<float>(t.base_level); break;
    case GL_TEXTURE_MAX_LEVEL: v[0] = static_cast<float>(t.max_level); break;
    default: return ctx->setError(GL_INVALID_ENUM);
  }
  put(params, v, n, color);
}

template <class T>
void getTexEnv(GLenum target, GLenum pname, T* params) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (target != GL_TEXTURE_ENV) return ctx->setError(GL_INVALID_ENUM);
  const TextureAttribs& a = ctx->textures.a;
  if (pname == GL_TEXTURE_ENV_MODE) {
    const float mode = static_cast<float>(a.env_mode);
    return put(params, &mode, 1, false);
  }
  if (pname == GL_TEXTURE_ENV_COLOR) return put(params, a.env_color, 4, true);
  ctx->setError(GL_INVALID_ENUM);
}

template <class T>
void getTexGen(GLenum coord, GLenum pname, T* params) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  const GLint i = texGenIndex(coord);
  if (i < 0) return ctx->setError(GL_INVALID_ENUM);
  const TexGen& g = ctx->textures.a.gen[i];
  if (pname == GL_TEXTURE_GEN_MODE) {
    const float mode = static_cast<float>(g.mode);
    return put(params, &mode, 1, false);
  }
  if (pname == GL_OBJECT_PLANE) return put(params, g.object_plane, 4, false);
  if (pname == GL_EYE_PLANE) return put(params, g.eye_plane, 4, false);
  ctx->setError(GL_INVALID_ENUM);
}

// glGenTextures' names: the lowest free ones above every name in use, as Mesa hands them out.
GLuint freeNames(const TextureState& t, GLsizei n) {
  GLuint first = t.objects.empty() ? 1 : t.objects.rbegin()->first + 1;
  if (first == 0 || 0xffffffffu - first < static_cast<GLuint>(n)) return 0;
  return first;
}

}  // namespace

const std::shared_ptr<const TextureUnit>& TextureState::current() {
  if (dirty) {
    unit.reset();
    if (a.enabled_2d) unit = snapshot(bound(GL_TEXTURE_2D), 2, a);
    else if (a.enabled_1d) unit = snapshot(bound(GL_TEXTURE_1D), 1, a);
    dirty = false;
  }
  return unit;
}

glm::vec4 textureCoordinates(const TextureState& t, const glm::mat4& texture_matrix, const glm::vec4& current,
                             const glm::vec4& object_vertex, const glm::vec4& eye_vertex, const glm::vec3& eye_normal) {
  glm::vec4 c = current;
  bool sphere = false;
  for (int k = 0; k < 4; ++k) sphere = sphere || (t.a.gen[k].enabled && t.a.gen[k].mode == GL_SPHERE_MAP);
  glm::vec2 sphere_st(0.0f);
  if (sphere) {
    // GL 1.5 equations 2.40-2.41: the reflection of the unit eye-to-vertex vector about the normal.
    glm::vec3 u = glm::vec3(eye_vertex);
    const float len = glm::length(u);
    if (len > 0.0f) u /= len;
    const glm::vec3 r = u - 2.0f * eye_normal * glm::dot(eye_normal, u);
    const float m = 2.0f * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.0f) * (r.z + 1.0f));
    if (m > 0.0f) sphere_st = glm::vec2(r.x / m + 0.5f, r.y / m + 0.5f);
    else sphere_st = glm::vec2(0.5f);
  }
  for (int k = 0; k < 4; ++k) {
    const TexGen& g = t.a.gen[k];
    if (!g.enabled) continue;
    switch (g.mode) {
      case GL_OBJECT_LINEAR:
        c[k] = g.object_plane[0] * object_vertex.x + g.object_plane[1] * object_vertex.y +
               g.object_plane[2] * object_vertex.z + g.object_plane[3] * object_vertex.w;
        break;
      case GL_EYE_LINEAR:
        c[k] = g.eye_plane[0] * eye_vertex.x + g.eye_plane[1] * eye_vertex.y + g.eye_plane[2] * eye_vertex.z +
               g.eye_plane[3] * eye_vertex.w;
        break;
      default: c[k] = sphere_st[k & 1]; break;  // GL_SPHERE_MAP (s and t only)
    }
  }
  return texture_matrix * c;
}

namespace cmd {

void bindTexture(PFcontextRec& ctx, GLenum target, GLuint name) {
  if (!outsideBegin(ctx)) return;
  if (!isTextureTarget(target)) return ctx.setError(GL_INVALID_ENUM);
  TextureState& t = ctx.textures;
  if (name != 0) {
    TextureObject* o = t.object(name);
    if (o && o->target != 0 && o->target != target) return ctx.setError(GL_INVALID_OPERATION);
    if (!o) {
      try {
        o = &t.objects[name];
      } catch (const std::bad_alloc&) {
        return ctx.outOfMemory("glBindTexture");
      }
    }
    o->target = target;
  }
  (target == GL_TEXTURE_2D ? t.a.binding_2d : t.a.binding_1d) = name;
  t.dirty = true;
}

void texParameter(PFcontextRec& ctx, GLenum target, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  if (!isTextureTarget(target)) return ctx.setError(GL_INVALID_ENUM);
  if (values.count == 0) return;  // a NULL vector: nothing to set
  TextureObject& t = ctx.textures.bound(target);
  const float v = values.v[0];
  const GLenum e = v >= 0.0f && v < 4294967296.0f ? static_cast<GLenum>(v) : 0u;
  switch (pname) {
    case GL_TEXTURE_MIN_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR && e != GL_NEAREST_MIPMAP_NEAREST && e != GL_LINEAR_MIPMAP_NEAREST &&
          e != GL_NEAREST_MIPMAP_LINEAR && e != GL_LINEAR_MIPMAP_LINEAR)
        return ctx.setError(GL_INVALID_ENUM);
      t.min_filter = e;
      break;
    case GL_TEXTURE_MAG_FILTER:
      if (e != GL_NEAREST && e != GL_LINEAR) return ctx.setError(GL_INVALID_ENUM);
      t.mag_filter = e;
      break;
    case GL_TEXTURE_WRAP_S:
    case GL_TEXTURE_WRAP_T:
      if (e != GL_REPEAT && e != GL_CLAMP && e != GL_CLAMP_TO_EDGE && e != GL_CLAMP_TO_BORDER && e != GL_MIRRORED_REPEAT)
        return ctx.setError(GL_INVALID_ENUM);
      (pname == GL_TEXTURE_WRAP_S ? t.wrap_s : t.wrap_t) = e;
      break;
    case GL_TEXTURE_BORDER_COLOR:
      for (int k = 0; k < 4; ++k) t.border[k] = clamp01(values.v[k]);
      break;
    case GL_TEXTURE_PRIORITY: t.priority = clamp01(v); break;
    case GL_TEXTURE_MIN_LOD: t.min_lod = v; break;
    case GL_TEXTURE_MAX_LOD: t.max_lod = v; break;
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL:
      if (v < 0.0f) return ctx.setError(GL_INVALID_VALUE);
      (pname == GL_TEXTURE_BASE_LEVEL ? t.base_level : t.max_level) = static_cast<int>(std::min(v, 1e9f));
      break;
    default: return ctx.setError(GL_INVALID_ENUM);
  }
  ctx.textures.dirty = true;
}

void texEnv(PFcontextRec& ctx, GLenum target, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  if (target != GL_TEXTURE_ENV) return ctx.setError(GL_INVALID_ENUM);
  if (values.count == 0) return;
  TextureAttribs& a = ctx.textures.a;
  if (pname == GL_TEXTURE_ENV_MODE) {
    const float v = values.v[0];
    const GLenum m = v >= 0.0f && v < 4294967296.0f ? static_cast<GLenum>(v) : 0u;
    if (m != GL_MODULATE && m != GL_DECAL && m != GL_BLEND && m != GL_REPLACE && m != GL_ADD)
      return ctx.setError(GL_INVALID_ENUM);
    a.env_mode = m;
  } else if (pname == GL_TEXTURE_ENV_COLOR) {
    for (int k = 0; k < 4; ++k) a.env_color[k] = clamp01(values.v[k]);
  } else {
    return ctx.setError(GL_INVALID_ENUM);
  }
  ctx.textures.dirty = true;
}

void texGen(PFcontextRec& ctx, GLenum coord, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  const GLint i = texGenIndex(coord);
  if (i < 0) return ctx.setError(GL_INVALID_ENUM);
  if (values.count == 0) return;
  TexGen& g = ctx.textures.a.gen[i];
  switch (pname) {
    case GL_TEXTURE_GEN_MODE: {
      const float v = values.v[0];
      const GLenum m = v >= 0.0f && v < 4294967296.0f ? static_cast<GLenum>(v) : 0u;
      if (m != GL_OBJECT_LINEAR && m != GL_EYE_LINEAR && !(m == GL_SPHERE_MAP && i < 2))
        return ctx.setError(GL_INVALID_ENUM);
      g.mode = m;
      break;
    }
    case GL_OBJECT_PLANE: std::copy(values.v, values.v + 4, g.object_plane); break;
    case GL_EYE_PLANE: {
      // Stored as the plane times the inverse of the modelview when it is given (equation 2.39).
      const glm::vec4 p(values.v[0], values.v[1], values.v[2], values.v[3]);
      const glm::vec4 e = p * glm::inverse(ctx.modelview.top);
      for (int k = 0; k < 4; ++k) g.eye_plane[k] = e[k];
      break;
    }
    default: return ctx.setError(GL_INVALID_ENUM);
  }
}

}  // namespace cmd
}  // namespace pf

namespace {

pf::Values4f texValues(const GLfloat* v, int n) { return pf::valuesOf<GLfloat, 4>(v, n, v ? n : 0); }
pf::Values4f texIntValues(const GLint* v, int n, bool color) {
  pf::Values4f out{};
  if (!v) return out;
  for (int i = 0; i < n; ++i) out.v[i] = color ? static_cast<float>(v[i] / 2147483647.0) : static_cast<float>(v[i]);
  out.count = n;
  return out;
}
pf::Values4f texScalar(float v) { return pf::valuesOf<GLfloat, 4>(&v, 1, 1); }
int parameterValues(GLenum pname) { return pf::scalarTexParameter(pname) ? 1 : 4; }

}  // namespace

extern "C" {

void pfglGenTextures(GLsizei n, GLuint* textures) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (n < 0) return ctx->setError(GL_INVALID_VALUE);
  if (n == 0 || !textures) return;
  const GLuint first = pf::freeNames(ctx->textures, n);
  if (first == 0) return ctx->setError(GL_OUT_OF_MEMORY);
  try {
    for (GLsizei i = 0; i < n; ++i) ctx->textures.objects[first + static_cast<GLuint>(i)];
  } catch (const std::bad_alloc&) {
    for (GLsizei i = 0; i < n; ++i) ctx->textures.objects.erase(first + static_cast<GLuint>(i));
    return ctx->setError(GL_OUT_OF_MEMORY);
  }
  for (GLsizei i = 0; i < n; ++i) textures[i] = first + static_cast<GLuint>(i);
}

void pfglDeleteTextures(GLsizei n, const GLuint* textures) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (n < 0) return ctx->setError(GL_INVALID_VALUE);
  if (!textures) return;
  pf::TextureState& t = ctx->textures;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = textures[i];
    if (name == 0 || !t.objects.count(name)) continue;
    // A bound texture's binding reverts to the default texture (GL 1.5 section 3.8.12).
    if (t.a.binding_1d == name) t.a.binding_1d = 0;
    if (t.a.binding_2d == name) t.a.binding_2d = 0;
    t.objects.erase(name);  // (draws recorded before keep the levels they sample)
    t.dirty = true;
  }
}

GLboolean pfglIsTexture(GLuint texture) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx || texture == 0) return GL_FALSE;
  const pf::TextureObject* o = ctx->textures.object(texture);
  return o && o->target != 0 ? GL_TRUE : GL_FALSE;
}

void pfglBindTexture(GLenum target, GLuint texture) { pf::dispatch<pf::GlOp::BindTexture>(target, texture); }

// Priorities are kept (glGetTexParameter reads them back); every texture is resident.
void pfglPrioritizeTextures(GLsizei n, const GLuint* textures, const GLclampf* priorities) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return;
  if (n < 0) return ctx->setError(GL_INVALID_VALUE);
  if (!textures || !priorities) return;
  for (GLsizei i = 0; i < n; ++i)
    if (pf::TextureObject* o = textures[i] ? ctx->textures.object(textures[i]) : nullptr)
      o->priority = priorities[i] > 0.0f ? std::min(priorities[i], 1.0f) : 0.0f;
}

GLboolean pfglAreTexturesResident(GLsizei n, const GLuint* textures, GLboolean* residences) {
  PFcontextRec* ctx = pf::contextOutsideBegin();
  if (!ctx) return GL_FALSE;
  if (n < 0) {
    ctx->setError(GL_INVALID_VALUE);
    return GL_FALSE;
  }
  if (!textures) return GL_FALSE;
  for (GLsizei i = 0; i < n; ++i)
    if (textures[i] == 0 || !ctx->textures.object(textures[i])) {
      ctx->setError(GL_INVALID_VALUE);
      return GL_FALSE;
    }
  (void)residences;  // (all resident: GL leaves the array as it is)
  return GL_TRUE;
}

void pfglTexParameterf(GLenum target, GLenum pname, GLfloat param) {
  pf::dispatch<pf::GlOp::TexParameter>(target, pname, texScalar(param));
}
void pfglTexParameteri(GLenum target, GLenum pname, GLint param) {
  pf::dispatch<pf::GlOp::TexParameter>(target, pname, texScalar(static_cast<float>(param)));
}
void pfglTexParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  pf::dispatch<pf::GlOp::TexParameter>(target, pname, texValues(params, parameterValues(pname)));
}
void pfglTexParameteriv(GLenum target, GLenum pname, const GLint* params) {
  pf::dispatch<pf::GlOp::TexParameter>(target, pname,
                                       texIntValues(params, parameterValues(pname), pname == GL_TEXTURE_BORDER_COLOR));
}
void pfglGetTexParameterfv(GLenum target, GLenum pname, GLfloat* params) { pf::getTexParameter(target, pname, params); }
void pfglGetTexParameteriv(GLenum target, GLenum pname, GLint* params) { pf::getTexParameter(target, pname, params); }

void pfglTexEnvf(GLenum target, GLenum pname, GLfloat param) {
  pf::dispatch<pf::GlOp::TexEnv>(target, pname, texScalar(param));
}
void pfglTexEnvi(GLenum target, GLenum pname, GLint param) {
  pf::dispatch<pf::GlOp::TexEnv>(target, pname, texScalar(static_cast<float>(param)));
}
void pfglTexEnvfv(GLenum target, GLenum pname, const GLfloat* params) {
  pf::dispatch<pf::GlOp::TexEnv>(target, pname, texValues(params, pname == GL_TEXTURE_ENV_COLOR ? 4 : 1));
}
void pfglTexEnviv(GLenum target, GLenum pname, const GLint* params) {
  const bool color = pname == GL_TEXTURE_ENV_COLOR;
  pf::dispatch<pf::GlOp::TexEnv>(target, pname, texIntValues(params, color ? 4 : 1, color));
}
void pfglGetTexEnvfv(GLenum target, GLenum pname, GLfloat* params) { pf::getTexEnv(target, pname, params); }
void pfglGetTexEnviv(GLenum target, GLenum pname, GLint* params) { pf::getTexEnv(target, pname, params); }

void pfglTexGeni(GLenum coord, GLenum pname, GLint param) {
  pf::dispatch<pf::GlOp::TexGen>(coord, pname, texScalar(static_cast<float>(param)));
}
void pfglTexGenf(GLenum coord, GLenum pname, GLfloat param) { pf::dispatch<pf::GlOp::TexGen>(coord, pname, texScalar(param)); }
void pfglTexGend(GLenum coord, GLenum pname, GLdouble param) {
  pf::dispatch<pf::GlOp::TexGen>(coord, pname, texScalar(static_cast<float>(param)));
}
void pfglTexGenfv(GLenum coord, GLenum pname, const GLfloat* params) {
  pf::dispatch<pf::GlOp::TexGen>(coord, pname, texValues(params, pname == GL_TEXTURE_GEN_MODE ? 1 : 4));
}
void pfglTexGeniv(GLenum coord, GLenum pname, const GLint* params) {
  pf::dispatch<pf::GlOp::TexGen>(coord, pname, texIntValues(params, pname == GL_TEXTURE_GEN_MODE ? 1 : 4, false));
}
void pfglTexGendv(GLenum coord, GLenum pname, const GLdouble* params) {
  pf::dispatch<pf::GlOp::TexGen>(coord, pname,
                                 pf::valuesOf<GLfloat, 4>(params, pname == GL_TEXTURE_GEN_MODE ? 1 : 4,
                                                          params ? (pname == GL_TEXTURE_GEN_MODE ? 1 : 4) : 0));
}
void pfglGetTexGeniv(GLenum coord, GLenum pname, GLint* params) { pf::getTexGen(coord, pname, params); }
void pfglGetTexGenfv(GLenum coord, GLenum pname, GLfloat* params) { pf::getTexGen(coord, pname, params); }
void pfglGetTexGendv(GLenum coord, GLenum pname, GLdouble* params) { pf::getTexGen(coord, pname, params); }

}  // extern "C"
