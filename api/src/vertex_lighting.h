// GL lighting of a glBegin's vertices, a batch at a time. GL 1.x lights each vertex and
// interpolates the colour; called once per glVertex, the scalar LightingEquation::shade() was
// most of what lighting added to a lit mesh's API time. The vertices are gathered here,
// LitPoints::kMax at a time, and lit together by LightingEquation::shadeRun -- the same
// equation over arrays, operation for operation, which the compiler vectorizes and which gives
// shade()'s bits (tests/unit/shading_pass_test.cpp, tests/unit/vertex_lighting_test.cpp) -- so
// the colours are exactly those of a call per vertex.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

#include "raster/lighting.h"

namespace pf {

// Where the lit colours of a batch go: row r's front colour to rows[r * stride + front_channel
// + 0..3], its back colour (-1: none) likewise.
struct VertexColorTarget {
  float* rows = nullptr;
  size_t stride = 0;
  int front_channel = -1;
  int back_channel = -1;
};

class VertexLightingBatch {
 public:
  static constexpr int kMax = LitPoints::kMax;

  // Gathers sequence point `row`, lit at eye-space point `eye` with normal `n` (as shade()
  // takes it: unit, or as GL leaves it) and material `front`; with `back` (two-sided
  // lighting), also its back face, lit with the material `back` and the normal reversed.
  void add(size_t row, const glm::vec3& eye, const glm::vec3& n, const Material& front, const Material* back);
  bool full() const { return count_ == kMax; }
  bool empty() const { return count_ == 0; }
  // Lights the gathered points with `equation`, writes their colours to `target` and empties
  // the batch.
  void flush(const LightingEquation& equation, const VertexColorTarget& target);
  void clear() { count_ = 0; }

 private:
  // One face's materials, one array per component.
  struct FaceMaterials {
    alignas(64) float ambient[4][kMax];
    alignas(64) float diffuse[4][kMax];
    alignas(64) float specular[4][kMax];
    alignas(64) float emission[4][kMax];
    alignas(64) float shininess[kMax];
  };
  void lightFace(const LightingEquation& equation, const FaceMaterials& m, const float* const normal[3],
                 const VertexColorTarget& target, int channel);

  int count_ = 0;
  bool two_faced_ = false;
  size_t row_[kMax];
  alignas(64) float eye_[3][kMax];
  alignas(64) float normal_[3][kMax];
  alignas(64) float back_normal_[3][kMax];
  FaceMaterials face_[2];
};

}  // namespace pf
