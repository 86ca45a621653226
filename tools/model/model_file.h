// Models as pfrender and pfview open them: a Fidget .vm, HyperFun .hf or language .pfl file (its
// one `field` unit, or the one named as the file), compiled into the
// current context as a field (pfglCompileFieldEXT) and drawn through the public API as an
// `implicit` instance, with the camera the model command line describes (issue #8's contract):
// HyperFun models are read as docs/hyperfun.md says, at the view's time (x[4]).
//   --ortho: looking down -z from above the box, the image covering the box's x and y extent
//   exactly (pixel centres at x0 + (i + 0.5)(x1 - x0)/W, row 0 at the bottom); otherwise a
//   perspective view of the box from the +z side, a little from above and the right.
// 2D models (no var-z) are coverage images over the box's x and y extent, as in the Prospero
// challenge: white where the model is inside, black elsewhere, whatever the camera option.
// A model with attributes (HyperFun's s array, seed 000's procedural colour) is drawn in the
// colour they give at each hit point: the colour bound to the `field_attributes` interpolator,
// lit through GL_COLOR_MATERIAL.
#pragma once

#include <primflow/gl.h>

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

#include "compiler/field/field_source.h"
#include "scene/scene.h"

namespace pf::model {

// A model that cannot be read or compiled: the message names the file (and line and column,
// with the source line and a caret, for compile errors).
struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Model {
  std::string path;
  field::FieldFormat format = field::FieldFormat::Fidget;
  std::string text;
  bool two_dimensional = false;  // reads no z: drawn as a coverage image
  bool coloured = false;         // defines attributes (HyperFun's s): drawn in the colour they give
  // [-1, 1]^3 (.vm), [-10, 10]^3 (.hf, HyperFun's polygonizer's), [-2, 2]^3 (.pfl)
  glm::dvec3 default_box_min{-1.0}, default_box_max{1.0};
};

// Whether pfrender treats `path` as a model (by its extension: .vm, .hf, .pfl).
bool isModelPath(const std::string& path);

// Compiles a field's source into the current context -- pfglCompileFieldParamsEXT for the text
// formats, pfglSampledFieldEXT for a sampled field's .pfgrid bytes -- and returns its id; 0 with
// the diagnostics (file:line:col, caret) in `error` when it does not compile.
GLuint uploadField(field::FieldFormat format, const std::string& name, const std::string& text, double time,
                   const std::vector<double>& params, std::string* error);

// Reads and checks a model file (throws ModelError), a HyperFun one at `time`.
Model loadModel(const std::string& path, double time = 0.0);

struct ModelView {
  int width = 512, height = 512;
  bool ortho = false;
  glm::dvec3 box_min{-1.0}, box_max{1.0};
  int method = GL_FIELD_METHOD_AUTO_EXT;
  float steps = 0.0f;  // the method's parameter (march: steps; sphere: Lipschitz bound)
  double time = 0.0;   // HyperFun's x[4] (Fidget models have no time)
};

// Compiles the model into the current context and draws it: clears, camera, light, the
// implicit instance. Throws ModelError if it does not compile.
void drawModel(const Model& model, const ModelView& view);

// The world z of the visible surface per pixel of the current context's last frame (rows
// bottom to top), NaN where nothing was drawn; from the depth buffer through the view's
// matrices, in double.
std::vector<float> worldDepth(const Model& model, const ModelView& view, const std::vector<float>& window_depth);

// The model as a scene (docs/scenes.md): its field, one implicit object over the view's box with
// the view's method, the perspective camera of drawModel (an orthographic view from above for 2D
// models, as their coverage images), and one light -- what pfview opens a model as.
scene::Scene sceneOfModel(const Model& model, const ModelView& view);

// Writes a greyscale PFM (little-endian, rows bottom to top). False with `error` on failure.
bool writePfm(const std::string& path, int width, int height, const std::vector<float>& values, std::string* error);

}  // namespace pf::model
