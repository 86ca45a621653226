// Models (see model_file.h): reading, the model command line's camera, drawing, depth output.
#include "model/model_file.h"

#include "compiler/field/sampled_reader.h"
#include "text_file.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>


namespace pf::model {

bool isModelPath(const std::string& path) { return field::fieldFormatOfPath(path).has_value(); }

Model loadModel(const std::string& path, double time) {
  Model m;
  std::string why;
  if (!tools::readTextFile(path, m.text, why)) throw ModelError(path + ": error: cannot open the model file: " + why);
  m.path = path;
  // Checked here, before any drawing, so that a bad file is reported with its line.
  DiagnosticLog log;
  m.format = field::fieldFormatOfPath(path).value_or(field::FieldFormat::Fidget);
  if (m.format != field::FieldFormat::Fidget) {
    // HyperFun's polygonizer's default box; a language field's, a little past the unit cube.
    const double half = m.format == field::FieldFormat::HyperFun ? 10.0 : 2.0;
    m.default_box_min = glm::dvec3(-half);
    m.default_box_max = glm::dvec3(half);
  }
  std::vector<field::FieldTape> attributes;
  const std::optional<field::FieldTape> tape =
      field::compileFieldSource(m.format, path, m.text, {}, time, log, "", &attributes);
  if (!tape) throw ModelError(log.format());
  if (m.format == field::FieldFormat::Sampled && !tape->grids.empty()) {
    // A sampled field's box is its grid's.
    const field::SampledGrid& g = *tape->grids[0];
    m.default_box_min = glm::dvec3(g.boxMin(0), g.boxMin(1), g.boxMin(2));
    m.default_box_max = glm::dvec3(g.boxMax(0), g.boxMax(1), g.boxMax(2));
  }
  m.two_dimensional = !tape->usesZ();
  m.coloured = !attributes.empty();
  return m;
}

GLuint uploadField(field::FieldFormat format, const std::string& name, const std::string& text, double time,
                   const std::vector<double>& params, std::string* error) {
  GLuint id = 0;
  if (format == field::FieldFormat::Sampled) {
    DiagnosticLog log;
    const std::shared_ptr<const field::SampledGrid> grid = field::readSampledField(name, text, log);
    if (!grid) {
      if (error) *error = log.format();
      return 0;
    }
    const GLdouble box[6] = {grid->boxMin(0), grid->boxMin(1), grid->boxMin(2),
                             grid->boxMax(0), grid->boxMax(1), grid->boxMax(2)};
    id = pfglSampledFieldEXT(name.c_str(), grid->size(0), grid->size(1), grid->size(2), box,
                             grid->interpolation() == field::SampleInterpolation::Trilinear ? GL_FIELD_TRILINEAR_EXT
                                                                                          : GL_FIELD_TRICUBIC_EXT,
                             grid->samples());
  } else {
    const GLenum gl_format = format == field::FieldFormat::HyperFun   ? GL_FIELD_HYPERFUN_EXT
                             : format == field::FieldFormat::Language ? GL_FIELD_LANGUAGE_EXT
                                                                      : GL_FIELD_FIDGET_EXT;
    id = pfglCompileFieldParamsEXT(gl_format, name.c_str(), text.c_str(), 0.0f, time,
                                   static_cast<GLsizei>(params.size()), params.data());
  }
  if (id == 0 && error) {
    std::vector<char> log(1 << 16);
    pfglGetFieldLogEXT(0, static_cast<GLsizei>(log.size()), nullptr, log.data());
    *error = log.data();
  }
  return id;
}

namespace {

// The matrices of the model view: projection and modelview (the model's space is the world).
struct ViewMatrices {
  glm::dmat4 projection, modelview;
};

ViewMatrices matricesOf(const ModelView& v, bool two_dimensional) {
  const glm::dvec3 lo = v.box_min, hi = v.box_max;
  const double depth = hi.z - lo.z, margin = 0.01 * depth + 1e-6;
  ViewMatrices m;
  if (v.ortho || two_dimensional) {
    // Looking down -z from just above the box; the image spans the box's x and y exactly.
    m.projection = glm::ortho(lo.x, hi.x, lo.y, hi.y, margin, depth + 2 * margin);
    m.modelview = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -(hi.z + margin)));
    return m;
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  const double fov = glm::radians(40.0);
  const double distance = radius / std::sin(0.5 * fov) * 1.05;
  const glm::dvec3 eye = centre + distance * glm::normalize(glm::dvec3(0.3, 0.35, 1.0));
  const double aspect = static_cast<double>(v.width) / v.height;
  m.projection = glm::perspective(fov, aspect, std::max(distance - radius * 1.01, 1e-3 * distance),
                                  distance + radius * 1.01);
  m.modelview = glm::lookAt(eye, centre, glm::dvec3(0, 1, 0));
  return m;
}

void loadMatrix(GLenum mode, const glm::dmat4& m) {
  pfglMatrixMode(mode);
  pfglLoadIdentity();
  double a[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) a[c * 4 + r] = m[c][r];
  pfglMultMatrixd(a);
}

}  // namespace

void drawModel(const Model& model, const ModelView& view) {
  std::string error;
  const GLuint field = uploadField(model.format, model.path, model.text,
                                   model.format == field::FieldFormat::HyperFun ? view.time : 0.0, {}, &error);
  if (field == 0) throw ModelError(error);
  const ViewMatrices m = matricesOf(view, model.two_dimensional);
  pfglViewport(0, 0, view.width, view.height);
  pfglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  pfglClearDepth(1.0);
  pfglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  pfglEnable(GL_DEPTH_TEST);
  loadMatrix(GL_PROJECTION, m.projection);
  loadMatrix(GL_MODELVIEW, glm::dmat4(1.0));
  if (model.two_dimensional) {
    pfglDisable(GL_LIGHTING);
    pfglColor3f(1.0f, 1.0f, 1.0f);
  } else {
    // One light from over the viewer's shoulder (eye space, set before the model's modelview).
    pfglEnable(GL_LIGHTING);
    pfglEnable(GL_LIGHT0);
    const GLfloat dir[4] = {0.4f, 0.6f, 1.0f, 0.0f}, white[4] = {1, 1, 1, 1}, ambient[4] = {0.12f, 0.12f, 0.14f, 1};
    pfglLightfv(GL_LIGHT0, GL_POSITION, dir);
    pfglLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    pfglLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    const GLfloat diffuse[4] = {0.85f, 0.78f, 0.62f, 1}, specular[4] = {0.25f, 0.25f, 0.25f, 1};
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, diffuse);
    pfglMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    pfglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);
  }
  if (model.coloured) {
    // The model's own colour per hit point: the implicit primitive's `field_attributes` branch,
    // tracked as the material's ambient and diffuse colour where the model is lit.
    pfglMaterialInterpEXT(pfglGetParamNameEXT("color"), pfglGetPrimitiveEXT("implicit"),
                          pfglGetInterpolatorEXT("field_attributes"));
    pfglEnable(GL_COLOR_MATERIAL);
  }
  loadMatrix(GL_MODELVIEW, m.modelview);
  const GLuint p_field = pfglGetParamNameEXT("field"), p_lo = pfglGetParamNameEXT("box_min"),
               p_hi = pfglGetParamNameEXT("box_max"), p_method = pfglGetParamNameEXT("method"),
               p_steps = pfglGetParamNameEXT("steps");
  pfglBegin(pfglGetPrimitiveEXT("implicit"));
  pfglRastParamfEXT(p_field, static_cast<GLfloat>(field));
  pfglRastParam3fEXT(p_lo, static_cast<float>(view.box_min.x), static_cast<float>(view.box_min.y),
                     static_cast<float>(view.box_min.z));
  pfglRastParam3fEXT(p_hi, static_cast<float>(view.box_max.x), static_cast<float>(view.box_max.y),
                     static_cast<float>(view.box_max.z));
  pfglRastParamfEXT(p_method, static_cast<GLfloat>(view.method));
  pfglRastParamfEXT(p_steps, view.steps);
  pfglSequencePointEXT();
  pfglEnd();
  pfglFinish();
}

scene::Scene sceneOfModel(const Model& model, const ModelView& view) {
  scene::Scene s;
  s.path = model.path;
  s.width = view.width;
  s.height = view.height;
  s.background = {0.0, 0.0, 0.0, 1.0};
  const std::string name = std::filesystem::path(model.path).stem().string();
  s.fields.push_back({name, model.path, model.text, {}, model.format,
                      model.format == field::FieldFormat::HyperFun ? view.time : 0.0, {}});
  const glm::dvec3 lo = view.box_min, hi = view.box_max, centre = 0.5 * (lo + hi);
  const double radius = 0.5 * glm::length(hi - lo);
  scene::Camera& c = s.camera;
  if (model.two_dimensional) {
    c.ortho = true;
    c.eye = {centre.x, centre.y, hi.z + radius};
    c.target = centre;
    c.height = hi.y - lo.y;
  } else {
    const double fov = 40.0, distance = radius / std::sin(glm::radians(0.5 * fov)) * 1.05;
    c.eye = centre + distance * glm::normalize(glm::dvec3(0.3, 0.35, 1.0));
    c.target = centre;
    c.fov_degrees = fov;
    s.lighting = true;
    s.global_ambient = {0.12, 0.12, 0.14, 1.0};
    // drawModel's light, over the viewer's shoulder: its eye-space direction taken to the world
    // (scene lights are given in world coordinates) through the inverse of the view's rotation.
    scene::Light light;
    const glm::dmat4 view_matrix = glm::lookAt(c.eye, c.target, c.up);
    light.position = glm::transpose(glm::dmat3(view_matrix)) * glm::dvec3(0.4, 0.6, 1.0);
    s.lights.push_back(light);
  }
  c.near = std::max(radius * 0.01, glm::length(c.eye - centre) - radius * 1.01);
  c.far = glm::length(c.eye - centre) + radius * 1.01;
  scene::Material m;
  m.color = model.two_dimensional ? glm::dvec4(1.0) : glm::dvec4(0.85, 0.78, 0.62, 1.0);
  m.specular = {0.25, 0.25, 0.25, 1.0};
  m.shininess = 24;
  if (model.coloured) m.interpolators["color"] = "field_attributes";  // the model's own colour
  s.materials["model"] = m;
  scene::Object o;
  o.primitive = "implicit";
  o.material = "model";
  o.params = {{"field", {}, name},
              {"box_min", {lo.x, lo.y, lo.z}, {}},
              {"box_max", {hi.x, hi.y, hi.z}, {}},
              {"method", {static_cast<double>(view.method)}, {}},
              {"steps", {static_cast<double>(view.steps)}, {}}};
  o.points.emplace_back();
  s.objects.push_back(std::move(o));
  return s;
}

std::vector<float> worldDepth(const Model& model, const ModelView& view, const std::vector<float>& window_depth) {
  const ViewMatrices m = matricesOf(view, model.two_dimensional);
  const glm::dmat4 inv = glm::inverse(m.projection * m.modelview);
  std::vector<float> out(static_cast<size_t>(view.width) * view.height, std::numeric_limits<float>::quiet_NaN());
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const size_t i = static_cast<size_t>(y) * view.width + x;
      const double d = window_depth[i];
      if (!(d < 1.0)) continue;  // the clear value: nothing drawn here
      const glm::dvec4 ndc((x + 0.5) / view.width * 2 - 1, (y + 0.5) / view.height * 2 - 1, d * 2 - 1, 1.0);
      const glm::dvec4 p = inv * ndc;
      out[i] = static_cast<float>(p.z / p.w);
    }
  return out;
}

bool writePfm(const std::string& path, int width, int height, const std::vector<float>& values, std::string* error) {
  std::ofstream out(path, std::ios::binary);
  if (!out) {
    if (error) *error = path + ": cannot write";
    return false;
  }
  out << "Pf\n" << width << ' ' << height << "\n-1.0\n";  // negative scale: little-endian
  for (float v : values) {
    unsigned char b[4];
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int k = 0; k < 4; ++k) b[k] = static_cast<unsigned char>(bits >> (8 * k));
    out.write(reinterpret_cast<const char*>(b), 4);
  }
  if (!out) {
    if (error) *error = path + ": write failed";
    return false;
  }
  return true;
}

}  // namespace pf::model
