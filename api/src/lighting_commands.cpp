// The lighting commands: glLight, glLightModel, glMaterial, glColorMaterial, glGetLight,
// glGetMaterial (the state is raster/lighting.h's; the equation is evaluated there).
#include "raster/lighting.h"

#include <algorithm>
#include <cmath>

#include <primflow/gl.h>

#include "api/src/commands.h"
#include "api/src/context_state.h"

namespace {

using pf::contextOutsideBegin;

// glLight's and glMaterial's parameters: how many values each takes.
int lightValues(GLenum pname) {
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
  }
}

// How many values glLightModel's parameter takes.
int lightModelValues(GLenum pname) {
  return pname == GL_LIGHT_MODEL_AMBIENT ? 4 : pname == GL_LIGHT_MODEL_LOCAL_VIEWER || pname == GL_LIGHT_MODEL_TWO_SIDE ? 1 : 0;
}

// How many values glMaterial's parameter takes; a parameter name (below) takes 4.
int materialValues(PFcontextRec* ctx, GLenum pname) {
  if (pname == GL_SHININESS) return 1;
  if (pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR || pname == GL_EMISSION ||
      pname == GL_AMBIENT_AND_DIFFUSE || (ctx && ctx->isParam(pname)))
    return 4;
  return 0;
}

// The integer vector forms: `n` values, colours mapping 2^31 - 1 to 1.0 (GL 1.5 table 2.9),
// everything else taken as it is. Null stays null (the float form then ignores it).
pf::Values4f intValues(const GLint* v, int n, bool color) {
  pf::Values4f out{};
  if (!v) return out;
  for (int i = 0; i < n && i < 4; ++i) out.v[i] = color ? static_cast<float>(v[i] / 2147483647.0) : static_cast<float>(v[i]);
  out.count = 4;
  return out;
}

// A scalar form's one value.
pf::Values4f scalar(float v) { return pf::valuesOf<GLfloat, 4>(&v, 1, 1); }

bool isColor(GLenum pname) { return pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR; }

}  // namespace

namespace pf::cmd {

// `v.count`: 1 for glLightf / glLighti, else a vector form (0: its NULL pointer, ignored after
// the enum checks).
void light(PFcontextRec& ctx, GLenum which, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  const int need = lightValues(pname);
  const float* v = values.pointer();
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + kMaxLights || need == 0 || (values.count == 1 && need != 1)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  Light& l = ctx.lighting.lights[which - GL_LIGHT0];
  const glm::mat4& mv = ctx.modelview.top;
  switch (pname) {
    case GL_AMBIENT: l.ambient = glm::vec4(v[0], v[1], v[2], v[3]); break;
    case GL_DIFFUSE: l.diffuse = glm::vec4(v[0], v[1], v[2], v[3]); break;
    case GL_SPECULAR: l.specular = glm::vec4(v[0], v[1], v[2], v[3]); break;
    case GL_POSITION: l.position = mv * glm::vec4(v[0], v[1], v[2], v[3]); break;
    case GL_SPOT_DIRECTION: l.spot_direction = glm::mat3(mv) * glm::vec3(v[0], v[1], v[2]); break;
    case GL_SPOT_EXPONENT:
      if (v[0] < 0 || v[0] > 128) return ctx.setError(GL_INVALID_VALUE);
      l.spot_exponent = v[0];
      break;
    case GL_SPOT_CUTOFF:
      if ((v[0] < 0 || v[0] > 90) && v[0] != 180) return ctx.setError(GL_INVALID_VALUE);
      l.spot_cutoff = v[0];
      break;
    default: {  // attenuation
      if (v[0] < 0) return ctx.setError(GL_INVALID_VALUE);
      (pname == GL_CONSTANT_ATTENUATION ? l.constant_attenuation
       : pname == GL_LINEAR_ATTENUATION ? l.linear_attenuation : l.quadratic_attenuation) = v[0];
    }
  }
}

void lightModel(PFcontextRec& ctx, GLenum pname, Values4f values) {
  if (!outsideBegin(ctx)) return;
  const float* v = values.pointer();
  if (lightModelValues(pname) == 0 || (values.count == 1 && pname == GL_LIGHT_MODEL_AMBIENT)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  if (pname == GL_LIGHT_MODEL_AMBIENT) ctx.lighting.model_ambient = glm::vec4(v[0], v[1], v[2], v[3]);
  else if (pname == GL_LIGHT_MODEL_LOCAL_VIEWER) ctx.lighting.local_viewer = v[0] != 0;
  else ctx.lighting.two_side = v[0] != 0;
}

// glMaterial is allowed between glBegin and glEnd (it changes the material of later vertices).
// A parameter name (pfglGetParamNameEXT) instead of a GL material property sets that
// parameter's current value (paper section 3.1: glMaterial generalised): `given` values (the
// vector forms: 4).
void material(PFcontextRec& ctx, GLenum face, GLenum pname, Values4f values) {
  const float* v = values.pointer();
  const int given = values.count == 1 ? 1 : 4;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  if (ctx.isParam(pname)) {
    if (!v) return;
    double d[4];
    for (int i = 0; i < given; ++i) d[i] = v[i];
    ctx.setParamValue(pname, given, d);
    return;
  }
  const bool shininess = pname == GL_SHININESS;
  if (materialValues(nullptr, pname) == 0 || (given == 1 && !shininess)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  if (shininess && (v[0] < 0 || v[0] > 128)) {
    ctx.setError(GL_INVALID_VALUE);
    return;
  }
  for (int f = 0; f < 2; ++f) {
    if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT)) continue;
    Material& m = ctx.lighting.material[f];
    glm::vec4 c = shininess ? glm::vec4(0) : glm::vec4(v[0], v[1], v[2], v[3]);
    switch (pname) {
      case GL_AMBIENT: m.ambient = c; break;
      case GL_DIFFUSE: m.diffuse = c; break;
      case GL_SPECULAR: m.specular = c; break;
      case GL_EMISSION: m.emission = c; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = c; break;
      default: m.shininess = v[0]; break;
    }
  }
}

void colorMaterial(PFcontextRec& ctx, GLenum face, GLenum mode) {
  if (!outsideBegin(ctx)) return;
  if ((face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) ||
      (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
       mode != GL_AMBIENT_AND_DIFFUSE)) {
    ctx.setError(GL_INVALID_ENUM);
    return;
  }
  ctx.lighting.color_material_face = face;
  ctx.lighting.color_material_mode = mode;
  ctx.lighting.trackColor(ctx.current_color);
}

}  // namespace pf::cmd

extern "C" {

void pfglLightf(GLenum l, GLenum pname, GLfloat v) { pf::dispatch<pf::GlOp::Light>(l, pname, scalar(v)); }
void pfglLighti(GLenum l, GLenum pname, GLint v) { pf::dispatch<pf::GlOp::Light>(l, pname, scalar(static_cast<float>(v))); }
void pfglLightfv(GLenum l, GLenum pname, const GLfloat* v) {
  pf::dispatch<pf::GlOp::Light>(l, pname, pf::valuesOf<GLfloat, 4>(v, lightValues(pname), 4));
}
void pfglLightiv(GLenum l, GLenum pname, const GLint* v) {
  pf::dispatch<pf::GlOp::Light>(l, pname, intValues(v, lightValues(pname), isColor(pname)));
}

void pfglLightModelf(GLenum pname, GLfloat v) { pf::dispatch<pf::GlOp::LightModel>(pname, scalar(v)); }
void pfglLightModeli(GLenum pname, GLint v) { pf::dispatch<pf::GlOp::LightModel>(pname, scalar(static_cast<float>(v))); }
void pfglLightModelfv(GLenum pname, const GLfloat* v) {
  pf::dispatch<pf::GlOp::LightModel>(pname, pf::valuesOf<GLfloat, 4>(v, lightModelValues(pname), 4));
}
void pfglLightModeliv(GLenum pname, const GLint* v) {
  const bool ambient = pname == GL_LIGHT_MODEL_AMBIENT;
  pf::dispatch<pf::GlOp::LightModel>(pname, intValues(v, lightModelValues(pname), ambient));
}

// glMaterial is allowed between glBegin and glEnd.
void pfglMaterialf(GLenum face, GLenum pname, GLfloat v) { pf::dispatch<pf::GlOp::Material>(face, pname, scalar(v)); }
void pfglMateriali(GLenum face, GLenum pname, GLint v) {
  pf::dispatch<pf::GlOp::Material>(face, pname, scalar(static_cast<float>(v)));
}
void pfglMaterialfv(GLenum face, GLenum pname, const GLfloat* v) {
  pf::dispatch<pf::GlOp::Material>(face, pname, pf::valuesOf<GLfloat, 4>(v, materialValues(pf::currentContext(), pname), 4));
}
void pfglMaterialiv(GLenum face, GLenum pname, const GLint* v) {
  // Shininess and named parameters (as pfglRastParamivEXT) take the integers as they are.
  PFcontextRec* ctx = pf::currentContext();
  const bool raw = pname == GL_SHININESS || (ctx && ctx->isParam(pname));
  pf::dispatch<pf::GlOp::Material>(face, pname, intValues(v, materialValues(ctx, pname), !raw));
}

void pfglColorMaterial(GLenum face, GLenum mode) { pf::dispatch<pf::GlOp::ColorMaterial>(face, mode); }

void pfglGetLightfv(GLenum which, GLenum pname, GLfloat* v) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if (which < GL_LIGHT0 || which >= GL_LIGHT0 + pf::kMaxLights || lightValues(pname) == 0) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  const pf::Light& l = ctx->lighting.lights[which - GL_LIGHT0];
  auto put = [&](const float* src, int n) { std::copy(src, src + n, v); };
  switch (pname) {
    case GL_AMBIENT: put(&l.ambient[0], 4); break;
    case GL_DIFFUSE: put(&l.diffuse[0], 4); break;
    case GL_SPECULAR: put(&l.specular[0], 4); break;
    case GL_POSITION: put(&l.position[0], 4); break;
    case GL_SPOT_DIRECTION: put(&l.spot_direction[0], 3); break;
    case GL_SPOT_EXPONENT: v[0] = l.spot_exponent; break;
    case GL_SPOT_CUTOFF: v[0] = l.spot_cutoff; break;
    case GL_CONSTANT_ATTENUATION: v[0] = l.constant_attenuation; break;
    case GL_LINEAR_ATTENUATION: v[0] = l.linear_attenuation; break;
    default: v[0] = l.quadratic_attenuation; break;
  }
}

void pfglGetMaterialfv(GLenum face, GLenum pname, GLfloat* v) {
  PFcontextRec* ctx = contextOutsideBegin();
  if (!ctx) return;
  if ((face != GL_FRONT && face != GL_BACK) ||
      (pname != GL_AMBIENT && pname != GL_DIFFUSE && pname != GL_SPECULAR && pname != GL_EMISSION &&
       pname != GL_SHININESS)) {
    ctx->setError(GL_INVALID_ENUM);
    return;
  }
  if (!v) return;
  const pf::Material& m = ctx->lighting.material[face == GL_FRONT ? 0 : 1];
  const float* src = pname == GL_AMBIENT ? &m.ambient[0] : pname == GL_DIFFUSE ? &m.diffuse[0]
                     : pname == GL_SPECULAR ? &m.specular[0] : pname == GL_EMISSION ? &m.emission[0] : nullptr;
  if (src) std::copy(src, src + 4, v);
  else v[0] = m.shininess;
}

}  // extern "C"
