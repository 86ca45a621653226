// GL lighting of a glBegin's vertices, a batch at a time (vertex_lighting.h).
#include "api/src/vertex_lighting.h"

namespace pf {

void VertexLightingBatch::add(size_t row, const glm::vec3& eye, const glm::vec3& n, const Material& front,
                              const Material* back) {
  const int i = count_++;
  row_[i] = row;
  two_faced_ = back != nullptr;  // the same for every vertex of a glBegin
  for (int k = 0; k < 3; ++k) {
    eye_[k][i] = eye[k];
    normal_[k][i] = n[k];
    back_normal_[k][i] = -n[k];  // shade(m, eye, -n): glm's negation, component by component
  }
  for (int f = 0; f < (back ? 2 : 1); ++f) {
    const Material& m = f == 0 ? front : *back;
    FaceMaterials& out = face_[f];
    for (int k = 0; k < 4; ++k) {
      out.ambient[k][i] = m.ambient[k];
      out.diffuse[k][i] = m.diffuse[k];
      out.specular[k][i] = m.specular[k];
      out.emission[k][i] = m.emission[k];
    }
    out.shininess[i] = m.shininess;
  }
}

void VertexLightingBatch::lightFace(const LightingEquation& equation, const FaceMaterials& m,
                                    const float* const normal[3], const VertexColorTarget& target, int channel) {
  LitPoints in;
  in.n = count_;
  for (int k = 0; k < 3; ++k) {
    in.eye[k] = eye_[k];
    in.normal[k] = normal[k];
  }
  for (int k = 0; k < 4; ++k) {
    in.ambient[k] = m.ambient[k];
    in.diffuse[k] = m.diffuse[k];
    in.specular[k] = m.specular[k];
    in.emission[k] = m.emission[k];
  }
  in.shininess = m.shininess;
  alignas(64) float color[4][kMax];
  float* const out[4] = {color[0], color[1], color[2], color[3]};
  equation.shadeRun(in, out);
  for (int i = 0; i < count_; ++i) {
    float* dst = target.rows + row_[i] * target.stride + static_cast<size_t>(channel);
    for (int k = 0; k < 4; ++k) dst[k] = color[k][i];
  }
}

void VertexLightingBatch::flush(const LightingEquation& equation, const VertexColorTarget& target) {
  if (count_ == 0) return;
  const float* const front[3] = {normal_[0], normal_[1], normal_[2]};
  lightFace(equation, face_[0], front, target, target.front_channel);
  if (two_faced_ && target.back_channel >= 0) {
    const float* const back[3] = {back_normal_[0], back_normal_[1], back_normal_[2]};
    lightFace(equation, face_[1], back, target, target.back_channel);
  }
  count_ = 0;
}

}  // namespace pf
