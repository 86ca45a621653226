// pfview's accuracy figure for a model: after a full-size frame at rest, a sparse grid of the
// frame's pixels (16 x 12) is checked against the double-precision reference of issue #8 (dense
// marching plus bisection along the same ray, tests/field/field_reference.h) -- missed or extra
// pixels, and the largest depth error along the ray in world units. Cheap enough to run once per
// resting view (a fraction of a second even for the bear); models only (one implicit surface in
// its box, no transform).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compiler/field/field_tape.h"
#include "model/model_file.h"
#include "scene/scene.h"

namespace pf::view {

struct AccuracyFigure {
  int rays = 0;          // sample pixels whose ray meets the box
  int mismatches = 0;    // drawn where the reference finds no surface, or the reverse
  double max_depth_error = 0.0;  // along the ray, world units
  std::string text() const;
};

class AccuracyProbe {
 public:
  // The model's tape, compiled as pfview drew it (throws ModelError as loadModel does).
  AccuracyProbe(const model::Model& model, const model::ModelView& view);

  // The figure for a frame drawn through `camera` at width x height, whose depth buffer (window
  // depth, rows bottom to top) is `depth`.
  AccuracyFigure measure(const scene::Camera& camera, int width, int height, const float* depth) const;

 private:
  field::FieldTape tape_;
  glm::dvec3 box_min_, box_max_;
};

}  // namespace pf::view
