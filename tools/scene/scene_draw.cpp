// Drawing a Scene through the public API (see scene.h): exactly the calls an application
// would make -- pfglCompilePrimitivesEXT for the scene's sources, the camera as the projection
// and viewing matrices, GL lights and materials (GL_COLOR_MATERIAL carries each material's
// colour), pfglMaterialInterpEXT for interpolator bindings, and one glBegin/glEnd per object
// whose sequence points carry the parameters.
#include <primflow/gl.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "model/model_file.h"
#include "scene/scene.h"

namespace pf::scene {

namespace {

[[noreturn]] void fail(const Scene& s, const Origin& o, const std::string& message) {
  throw SceneError(s.path + ":" + std::to_string(lineOf(s, o)) + ": error: " + message);
}

void setVec4(void (*f)(GLenum, GLenum, const GLfloat*), GLenum a, GLenum b, const glm::dvec4& v) {
  const GLfloat f4[4] = {static_cast<GLfloat>(v.x), static_cast<GLfloat>(v.y), static_cast<GLfloat>(v.z),
                         static_cast<GLfloat>(v.w)};
  f(a, b, f4);
}

void setCamera(const Camera& c, int width, int height) {
  pfglViewport(0, 0, width, height);
  pfglMatrixMode(GL_PROJECTION);
  pfglLoadIdentity();
  const double aspect = static_cast<double>(width) / height;
  if (c.ortho) {
    const double h = c.height / 2;
    pfglOrtho(-h * aspect, h * aspect, -h, h, c.near, c.far);
  } else {
    const double h = c.near * std::tan(glm::radians(c.fov_degrees) / 2);
    pfglFrustum(-h * aspect, h * aspect, -h, h, c.near, c.far);
  }
  pfglMatrixMode(GL_MODELVIEW);
  const glm::dmat4 view = glm::lookAt(c.eye, c.target, c.up);
  pfglLoadMatrixd(glm::value_ptr(view));
}

// Lights are given in world coordinates: set while the modelview is the viewing matrix, as GL
// transforms light positions by the modelview current at glLight.
void setLights(const Scene& s) {
  if (!s.lighting) {
    pfglDisable(GL_LIGHTING);
    return;
  }
  pfglEnable(GL_LIGHTING);
  pfglEnable(GL_NORMALIZE);
  if (s.per_pixel) pfglEnable(GL_PER_PIXEL_LIGHTING_EXT);
  else pfglDisable(GL_PER_PIXEL_LIGHTING_EXT);
  pfglEnable(GL_COLOR_MATERIAL);
  pfglColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  setVec4([](GLenum, GLenum p, const GLfloat* v) { pfglLightModelfv(p, v); }, 0, GL_LIGHT_MODEL_AMBIENT,
          s.global_ambient);
  pfglLightModeli(GL_LIGHT_MODEL_TWO_SIDE, s.two_side ? 1 : 0);
  pfglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, s.local_viewer ? 1 : 0);
  for (size_t i = 0; i < s.lights.size(); ++i) {
    const Light& l = s.lights[i];
    const GLenum id = GL_LIGHT0 + static_cast<GLenum>(i);
    pfglEnable(id);
    const double w = l.kind == Light::Kind::Directional ? 0.0 : 1.0;
    setVec4(pfglLightfv, id, GL_POSITION, glm::dvec4(l.position, w));
    setVec4(pfglLightfv, id, GL_AMBIENT, l.ambient);
    setVec4(pfglLightfv, id, GL_DIFFUSE, l.diffuse);
    setVec4(pfglLightfv, id, GL_SPECULAR, l.specular);
    pfglLightf(id, GL_CONSTANT_ATTENUATION, static_cast<GLfloat>(l.attenuation.x));
    pfglLightf(id, GL_LINEAR_ATTENUATION, static_cast<GLfloat>(l.attenuation.y));
    pfglLightf(id, GL_QUADRATIC_ATTENUATION, static_cast<GLfloat>(l.attenuation.z));
    const GLfloat dir[3] = {static_cast<GLfloat>(l.spot_direction.x), static_cast<GLfloat>(l.spot_direction.y),
                            static_cast<GLfloat>(l.spot_direction.z)};
    pfglLightfv(id, GL_SPOT_DIRECTION, dir);
    pfglLightf(id, GL_SPOT_CUTOFF, static_cast<GLfloat>(l.kind == Light::Kind::Spot ? l.spot_cutoff : 180.0));
    pfglLightf(id, GL_SPOT_EXPONENT, static_cast<GLfloat>(l.spot_exponent));
  }
}

// Parameter name ids by name, looked up once per scene (a scene of 100k spheres sets 200k
// values).
class ParamIds {
 public:
  GLuint operator()(const std::string& name) {
    auto it = ids_.find(name);
    if (it == ids_.end()) it = ids_.emplace(name, pfglGetParamNameEXT(name.c_str())).first;
    return it->second;
  }

 private:
  std::unordered_map<std::string, GLuint> ids_;
};

void setParams(const std::vector<ParamValue>& params, ParamIds& ids) {
  GLfloat v[16];
  for (const ParamValue& p : params) {
    if (!p.field.empty()) {  // a field's name: its id (compileSceneSources compiled it)
      pfglRastParamfEXT(ids(p.name), static_cast<GLfloat>(pfglGetFieldEXT(p.field.c_str())));
      continue;
    }
    const size_t n = std::min<size_t>(p.values.size(), 16);  // loading keeps 1..16 values
    std::copy_n(p.values.begin(), n, v);
    pfglRastParamfvEXT(ids(p.name), static_cast<GLsizei>(n), v);
  }
}

// The interpolator id for a binding's name.
GLenum interpolatorId(const Scene& s, const Material& m, const std::string& name) {
  if (name == "perspective_linear") return GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT;
  if (name == "linear") return GL_LINEAR_INTERPOLATOR_EXT;
  const GLenum id = pfglGetInterpolatorEXT(name.c_str());
  if (id == 0) {
    pfglGetError();
    fail(s, m.origin, "no shared interpolator named '" + name + "' (built-in ones: docs/primitives.md)");
  }
  return id;
}

void drawObjectWith(const Scene& s, const Object& o, ParamIds& ids) {
  const GLenum mode = pfglGetPrimitiveEXT(o.primitive.c_str());
  if (mode == 0) {
    pfglGetError();
    fail(s, o.origin, "no primitive named '" + o.primitive + "'");
  }
  static const Material kDefault;
  const Material& m = o.material.empty() ? kDefault : s.materials.at(o.material);
  for (const auto& [param, interp] : m.interpolators)
    pfglMaterialInterpEXT(ids(param), mode, interpolatorId(s, m, interp));
  setVec4(pfglMaterialfv, GL_FRONT_AND_BACK, GL_SPECULAR, m.specular);
  setVec4(pfglMaterialfv, GL_FRONT_AND_BACK, GL_EMISSION, m.emission);
  pfglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, static_cast<GLfloat>(m.shininess));
  pfglColor4f(static_cast<GLfloat>(m.color.r), static_cast<GLfloat>(m.color.g), static_cast<GLfloat>(m.color.b),
              static_cast<GLfloat>(m.color.a));
  setParams(m.params, ids);
  setParams(o.params, ids);
  if (pfglGetError() != GL_NO_ERROR) fail(s, o.origin, "a material or parameter value was refused");

  pfglPushMatrix();
  pfglMultMatrixd(glm::value_ptr(o.transform));
  pfglBegin(mode);
  if (!o.vertices.empty()) {
    for (size_t i = 0; i < o.vertices.size(); ++i) {
      if (!o.colors.empty())
        pfglColor4f(static_cast<GLfloat>(o.colors[i].r), static_cast<GLfloat>(o.colors[i].g),
                    static_cast<GLfloat>(o.colors[i].b), static_cast<GLfloat>(o.colors[i].a));
      if (!o.normals.empty())
        pfglNormal3f(static_cast<GLfloat>(o.normals[i].x), static_cast<GLfloat>(o.normals[i].y),
                     static_cast<GLfloat>(o.normals[i].z));
      pfglVertex3d(o.vertices[i].x, o.vertices[i].y, o.vertices[i].z);
    }
  } else {
    for (const auto& point : o.points) {
      setParams(point, ids);
      pfglSequencePointEXT();
    }
  }
  pfglEnd();
  pfglPopMatrix();
  // The bindings belong to this object's material: the next object of the mode starts afresh.
  for (const auto& [param, interp] : m.interpolators)
    pfglMaterialInterpEXT(ids(param), mode, GL_PERSPECTIVE_LINEAR_INTERPOLATOR_EXT);
  if (pfglGetError() != GL_NO_ERROR)
    fail(s, o.origin,
         "'" + o.primitive + "' refused the object's sequence points (a parameter it needs is missing or has the "
         "wrong number of values; the line above says which)");
}

}  // namespace

void compileSceneSources(const Scene& s) {
  for (const auto& [file, text] : s.sources) {
    if (pfglCompilePrimitivesEXT(text.c_str()) != 0) continue;
    std::vector<char> log(1 << 16);
    pfglGetCompileLogEXT(0, static_cast<GLsizei>(log.size()), nullptr, log.data());
    // The compiler names its input "moduleN.pfl": put the file's own name in.
    std::string text_log(log.data());
    const size_t colon = text_log.find(".pfl:");
    if (colon != std::string::npos) text_log = file + text_log.substr(colon + 4);
    throw SceneError(text_log.empty() ? file + ": error: does not compile" : text_log);
  }
  // (Checked when the scene was read: a failure here is the context's, e.g. inside glBegin.)
  for (const FieldSource& f : s.fields)
    if (model::uploadField(f.format, f.name, f.text, f.time, f.params, nullptr) == 0)
      fail(s, f.origin, "the field '" + f.name + "' does not compile");
}

void beginScene(const Scene& s, int width, int height, bool compile_sources) {
  pfglGetError();
  if (compile_sources) compileSceneSources(s);
  pfglClearColor(static_cast<GLfloat>(s.background.r), static_cast<GLfloat>(s.background.g),
                 static_cast<GLfloat>(s.background.b), static_cast<GLfloat>(s.background.a));
  pfglClearDepth(1.0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  setCamera(s.camera, width, height);
  setLights(s);
}

void drawObject(const Scene& s, const Object& o) {
  ParamIds ids;
  drawObjectWith(s, o, ids);
}

void drawScene(const Scene& s, int width, int height, bool compile_sources) {
  beginScene(s, width, height, compile_sources);
  ParamIds ids;
  for (const Object& o : s.objects) drawObjectWith(s, o, ids);
  pfglFinish();
}

}  // namespace pf::scene
