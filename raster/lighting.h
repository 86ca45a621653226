// GL's fixed-function lighting state and its equation (GL 1.5 section 2.14). Vertex primitives
// (those with a `vertex` parameter) are lit per sequence point by the API, as GL lights per
// vertex; primitives that set their surface normal N are lit per pixel by the shading pass.
#pragma once

#include <glm/glm.hpp>

#include <GL/gl.h>

#include "raster/simd_clones.h"

namespace pf {

constexpr int kMaxLights = 8;

struct Light {
  bool enabled = false;
  glm::vec4 ambient{0, 0, 0, 1};
  glm::vec4 diffuse{0, 0, 0, 1};   // light 0: (1, 1, 1, 1)
  glm::vec4 specular{0, 0, 0, 1};  // light 0: (1, 1, 1, 1)
  glm::vec4 position{0, 0, 1, 0};  // eye coordinates (transformed by the modelview when set)
  glm::vec3 spot_direction{0, 0, -1};  // eye coordinates
  float spot_exponent = 0, spot_cutoff = 180;
  float constant_attenuation = 1, linear_attenuation = 0, quadratic_attenuation = 0;
  bool operator==(const Light&) const = default;
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1};
  glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1};
  glm::vec4 specular{0, 0, 0, 1};
  glm::vec4 emission{0, 0, 0, 1};
  float shininess = 0;
  bool operator==(const Material&) const = default;
};

struct LightingState {
  bool enabled = false;            // GL_LIGHTING
  Light lights[kMaxLights];
  Material material[2];            // front, back
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1};
  bool local_viewer = false, two_side = false;
  bool color_material = false;     // GL_COLOR_MATERIAL
  GLenum color_material_face = GL_FRONT_AND_BACK;
  GLenum color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  bool normalize = false, rescale_normal = false;
  // GL_PER_PIXEL_LIGHTING_EXT: vertex primitives lit per pixel (the API plans the channels).
  bool per_pixel_vertices = false;

  LightingState() {
    lights[0].diffuse = glm::vec4(1);
    lights[0].specular = glm::vec4(1);
  }
  // glColor under GL_COLOR_MATERIAL: the tracked material properties take the colour.
  void trackColor(const glm::vec4& color);
  bool operator==(const LightingState&) const = default;
};

// Whether lighting with `s` depends on the eye-space point lit, not only on its normal: a
// positional light, a local viewer, or two-sided lighting (which faces the normal to the eye).
bool lightReadsEye(const LightingState& s);

// GL's lighting equation for one state, with what does not depend on the point lit worked out
// once: the enabled lights, a positional light's position, a directional light's direction,
// spot factor and (for a viewer at infinity) half vector. The shading pass evaluates it per
// pixel; litColor() below is the same object used once, so the two agree to the bit.
// n points lit at once (LightingEquation::shadeRun), each quantity one array per component.
struct LitPoints {
  static constexpr int kMax = 64;  // points per run (a tile's row)
  int n = 0;
  const float* eye[3];     // eye-space points
  const float* normal[3];  // as shade() takes them: unit or zero, reversed for a back face
  const float* ambient[4];
  const float* diffuse[4];
  const float* specular[4];
  const float* emission[4];
  const float* shininess;
};

class LightingEquation {
 public:
  explicit LightingEquation(const LightingState& s);
  // The colour at eye-space point `eye` with material `m` and normal `n` (already reversed for
  // a back face), clamped to [0, 1].
  glm::vec4 shade(const Material& m, const glm::vec3& eye, const glm::vec3& n) const;
  // shade() at every point of `in`, into out[component][point]: the same operations in the same
  // order, point by point -- the same bits -- in loops over the points that the compiler
  // vectorizes (the shading pass lights a row of a tile at a time). `out` may be the arrays of
  // in's material (GL_COLOR_MATERIAL's colour): every input is read before its point is written.
  void shadeRun(const LitPoints& in, float* const out[4]) const;

 private:
  struct Prepared {
    glm::vec3 ambient, diffuse, specular;
    bool positional;
    glm::vec3 position;     // positional: the light's position (divided by w)
    float constant, linear, quadratic;  // positional: attenuation
    glm::vec3 direction;    // directional: the unit vector to the light (VP)
    bool spot;              // a spot light (cutoff not 180)
    glm::vec3 spot_direction;  // unit
    float spot_cos_cutoff, spot_exponent;
    float directional_spot;    // directional: the spot factor (VP is fixed)
    bool has_half;             // directional, viewer at infinity: the half vector is fixed
    glm::vec3 half;            // its unit vector
    bool half_zero;            // ... which is zero (VP = -z)
  };
  Prepared lights_[kMaxLights];
  int count_ = 0;
  glm::vec3 model_ambient_;
  bool local_viewer_;
};

// The colour of a vertex at eye-space position `eye` with eye-space normal `normal` (already
// normalised or rescaled as the state asks), lit with material `face` (0 front, 1 back; the
// back face is lit with the normal reversed), clamped to [0, 1].
glm::vec4 litColor(const LightingState& s, const glm::vec3& eye, const glm::vec3& normal, int face);
// The same with material `m` and the normal as it is (already reversed for a back face).
glm::vec4 litColor(const LightingState& s, const Material& m, const glm::vec3& eye, const glm::vec3& n);
// Face `face`'s material with GL_COLOR_MATERIAL's tracked properties set to `color`.
Material trackedMaterial(const LightingState& s, int face, const glm::vec4& color);

}  // namespace pf
